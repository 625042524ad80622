#include "mesowave/io/text_table.hpp"

#include <algorithm>
#include <cstdlib>

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

}  // namespace mesowave::io
