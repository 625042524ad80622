#pragma once
// Tables for people: aligned plain text for terminals (numbers right-aligned,
// text left), Markdown for summaries, and how a column's numbers are printed.
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mesowave::io {

std::string format_text_table(const std::vector<std::string>& header,
                              const std::vector<std::vector<std::string>>& rows);

/// How a column's numbers are printed: fixed decimals ("0.150", C's %.Nf);
/// rounded to that many decimals, half away from zero, and printed without
/// trailing zeros ("0.15", "2453"; -6 decimals: to millions, "3247000000"), as
/// jq's `. * 10 | round / 10` prints; or significant digits ("1.86", "0.0321",
/// C's %.Ng).
struct ColumnFormat {
  enum class Style { fixed, rounded, significant };
  Style style = Style::fixed;
  int digits = 0;  ///< decimals (fixed, rounded) or significant digits
};
/// "NAME=DIGITS": 0 to 17 decimals (rounded: -17 to 17), 1 to 17 significant
/// digits; InputError otherwise.
std::pair<std::string, ColumnFormat> parse_column_format(const std::string& text, ColumnFormat::Style style);
/// `value` (a number's text) printed as `format` says; InputError naming `what` if not a number.
std::string apply_column_format(const std::string& value, const ColumnFormat& format, const std::string& what);

/// A Markdown (GitHub) table: `| a | b |`, `|---|---|`, one line per row. A
/// column's header text may be renamed (`headers`) and its numbers printed as
/// `formats` say (by column name); an empty field prints as `empty`.
struct MarkdownTableOptions {
  std::map<std::string, std::string> headers;
  std::map<std::string, ColumnFormat> formats;
  std::string empty = "-";
};
/// InputError for a renamed or formatted column the table lacks.
std::string format_markdown_table(const std::vector<std::string>& header,
                                  const std::vector<std::vector<std::string>>& rows,
                                  const MarkdownTableOptions& options = {});

}  // namespace mesowave::io
