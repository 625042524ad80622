#include "mesowave/io/text_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::io {
namespace {

bool looks_numeric(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// Display width in code points, so that "ν" or "µs" do not break alignment.
std::size_t width(const std::string& s) {
  return std::size_t(std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

}  // namespace

std::string format_text_table(const std::vector<std::string>& header,
                              const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> widths(header.size());
  for (std::size_t c = 0; c < header.size(); ++c) widths[c] = width(header[c]);
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size() && c < widths.size(); ++c) widths[c] = std::max(widths[c], width(row[c]));

  std::string out;
  auto emit = [&](const std::vector<std::string>& fields, bool is_header) {
    for (std::size_t c = 0; c < widths.size(); ++c) {
      const std::string f = c < fields.size() ? fields[c] : "";
      const std::string pad(widths[c] - width(f), ' ');
      const bool right = !is_header && looks_numeric(f);
      if (c) out += "  ";
      out += right ? pad + f : (c + 1 < widths.size() ? f + pad : f);
    }
    out += '\n';
  };
  emit(header, true);
  std::string rule;
  for (std::size_t c = 0; c < widths.size(); ++c) rule += (c ? "  " : "") + std::string(widths[c], '-');
  out += rule + '\n';
  for (const auto& row : rows) emit(row, false);
  return out;
}

std::pair<std::string, ColumnFormat> parse_column_format(const std::string& text, ColumnFormat::Style style) {
  const auto eq = text.rfind('=');
  const std::string name = eq == std::string::npos ? std::string() : text.substr(0, eq);
  const std::string digits = eq == std::string::npos ? std::string() : text.substr(eq + 1);
  const int lowest = style == ColumnFormat::Style::significant ? 1 : style == ColumnFormat::Style::rounded ? -17 : 0;
  char* end = nullptr;
  const long n = digits.empty() ? -1 : std::strtol(digits.c_str(), &end, 10);
  if (name.empty() || digits.empty() || end != digits.c_str() + digits.size() || n < lowest || n > 17)
    throw InputError("column format '" + text + "' must read NAME=DIGITS (" + std::to_string(lowest) + " to 17)");
  return {name, ColumnFormat{style, int(n)}};
}

std::string apply_column_format(const std::string& value, const ColumnFormat& format, const std::string& what) {
  char* end = nullptr;
  const double x = value.empty() ? NAN : std::strtod(value.c_str(), &end);
  if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(x))
    throw InputError(what + ": '" + value + "' is not a number to print with " + std::to_string(format.digits) +
                     " digits");
  switch (format.style) {
    case ColumnFormat::Style::fixed:
      return format_fixed(x, format.digits);
    case ColumnFormat::Style::significant:
      return format_significant(x, format.digits);
    case ColumnFormat::Style::rounded:
      break;
  }
  // Scaled as jq's `. * 100 | round / 100` or `. / 1e6 | round * 1e6` computes it, then
  // printed with its decimals, the trailing zeros dropped ("2453.0" -> "2453").
  const double scale = std::pow(10.0, std::abs(format.digits));
  const double rounded = format.digits >= 0 ? std::round(x * scale) / scale : std::round(x / scale) * scale;
  std::string text = format_fixed(rounded, std::max(format.digits, 0));
  if (text.find('.') != std::string::npos) {
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
  }
  return text;
}

std::string format_markdown_table(const std::vector<std::string>& header,
                                  const std::vector<std::vector<std::string>>& rows,
                                  const MarkdownTableOptions& options) {
  const auto index = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw InputError("the table has no column '" + name + "'");
    return std::size_t(it - header.begin());
  };
  std::vector<std::string> titles = header;
  for (const auto& [name, title] : options.headers) titles[index(name)] = title;
  std::map<std::size_t, ColumnFormat> formats;
  for (const auto& [name, format] : options.formats) formats[index(name)] = format;
  std::string out = "|", rule = "|";
  for (const auto& t : titles) {
    out += " " + t + " |";
    rule += "---|";
  }
  out += "\n" + rule + "\n";
  for (const auto& row : rows) {
    out += "|";
    for (std::size_t c = 0; c < row.size(); ++c) {
      const auto f = formats.find(c);
      const std::string field = row[c].empty()       ? options.empty
                                : f == formats.end() ? row[c]
                                                     : apply_column_format(row[c], f->second, "column " + header[c]);
      out += " " + field + " |";
    }
    out += "\n";
  }
  return out;
}

}  // namespace mesowave::io
