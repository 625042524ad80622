#pragma once
// Comma-separated tables as spreadsheets write them: one header row, fields
// optionally in double quotes, lines starting with '#' are comments.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mesowave::io {

struct CsvTable {
  std::string origin;  ///< file name (or label) used in error messages
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::size_t> row_lines;  ///< 1-based source line of each row

  std::optional<std::size_t> find_column(std::string_view name) const;
  /// Index of column `name`; InputError naming the file if absent.
  std::size_t column(std::string_view name) const;
  /// Field as a finite number; InputError naming file, line and column if not.
  double number(std::size_t row, std::size_t column) const;
  const std::string& text(std::size_t row, std::size_t column) const;
};

CsvTable parse_csv(std::string_view text, std::string origin);
CsvTable read_csv(const std::filesystem::path& path);

/// `s` without leading and trailing spaces, tabs and carriage returns (an
/// unquoted field as read, a header's name and unit).
std::string trim_blanks(std::string_view s);

/// Writes a table; fields with commas, quotes or newlines are quoted.
std::string to_csv(const std::vector<std::string>& header,
                   const std::vector<std::vector<std::string>>& rows);

}  // namespace mesowave::io
