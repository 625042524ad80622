#include "mesowave/io/csv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "mesowave/core/error.hpp"

namespace mesowave::io {
namespace {

// Splits one record starting at `pos`; advances `pos` past its line end and
// `line` by the number of newlines consumed (quoted fields may span lines).
std::vector<std::string> split_record(std::string_view text, std::size_t& pos, std::size_t& line,
                                      const std::string& origin) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false, was_quoted = false;
  const std::size_t start_line = line;
  for (; pos < text.size(); ++pos) {
    const char c = text[pos];
    if (quoted) {
      if (c == '"' && pos + 1 < text.size() && text[pos + 1] == '"') {
        field += '"';
        ++pos;
      } else if (c == '"') {
        quoted = false;
      } else {
        if (c == '\n') ++line;
        field += c;
      }
    } else if (c == '"') {
      quoted = was_quoted = true;
    } else if (c == ',') {
      fields.push_back(was_quoted ? field : trim_blanks(field));
      field.clear();
      was_quoted = false;
    } else if (c == '\n') {
      ++pos;
      ++line;
      break;
    } else {
      field += c;
    }
  }
  if (quoted) throw InputError(origin + ":" + std::to_string(start_line) + ": unterminated quoted field");
  fields.push_back(was_quoted ? field : trim_blanks(field));
  return fields;
}

bool blank_or_comment(std::string_view text, std::size_t pos) {
  while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t' || text[pos] == '\r')) ++pos;
  return pos >= text.size() || text[pos] == '\n' || text[pos] == '#';
}

}  // namespace

std::optional<std::size_t> CsvTable::find_column(std::string_view name) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  return std::nullopt;
}

std::size_t CsvTable::column(std::string_view name) const {
  if (auto index = find_column(name)) return *index;
  throw InputError(origin + ": missing column '" + std::string(name) + "'");
}

const std::string& CsvTable::text(std::size_t row, std::size_t column) const {
  return rows.at(row).at(column);
}

double CsvTable::number(std::size_t row, std::size_t column) const {
  const std::string& field = text(row, column);
  double value = 0;
  const char* begin = field.data();
  const char* end = begin + field.size();
  if (!field.empty() && *begin == '+') ++begin;
  auto [ptr, ec] = std::from_chars(begin, end, value);
  if (field.empty() || ec != std::errc() || ptr != end || !std::isfinite(value))
    throw InputError(origin + ":" + std::to_string(row_lines.at(row)) + ": column '" + header.at(column) +
                     "' holds '" + field + "', not a finite number");
  return value;
}

CsvTable parse_csv(std::string_view text, std::string origin) {
  CsvTable table;
  table.origin = std::move(origin);
  std::size_t pos = 0, line = 1;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") pos = 3;  // UTF-8 byte-order mark
  while (pos < text.size()) {
    if (blank_or_comment(text, pos)) {
      const auto eol = text.find('\n', pos);
      pos = (eol == std::string_view::npos) ? text.size() : eol + 1;
      ++line;
      continue;
    }
    const std::size_t record_line = line;
    auto fields = split_record(text, pos, line, table.origin);
    if (table.header.empty()) {
      table.header = std::move(fields);
      continue;
    }
    if (fields.size() != table.header.size())
      throw InputError(table.origin + ":" + std::to_string(record_line) + ": " + std::to_string(fields.size()) +
                       " fields where the header has " + std::to_string(table.header.size()));
    table.rows.push_back(std::move(fields));
    table.row_lines.push_back(record_line);
  }
  if (table.header.empty()) throw InputError(table.origin + ": no header row");
  return table;
}

CsvTable read_csv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path.string());
  std::ostringstream content;
  content << in.rdbuf();
  return parse_csv(content.str(), path.string());
}

std::string to_csv(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  auto field = [](const std::string& f) {
    if (f.find_first_of(",\"\n") == std::string::npos) return f;
    std::string quoted = "\"";
    for (char c : f) quoted += (c == '"') ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
  };
  std::string out;
  auto line = [&](const std::vector<std::string>& fields) {
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (i) out += ',';
      out += field(fields[i]);
    }
    out += '\n';
  };
  line(header);
  for (const auto& r : rows) line(r);
  return out;
}

std::string trim_blanks(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return std::string(s.substr(first, last - first + 1));
}

}  // namespace mesowave::io
