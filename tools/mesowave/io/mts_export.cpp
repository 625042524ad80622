#include "mesowave/io/mts_export.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "mesowave/core/error.hpp"

namespace mesowave::io {

namespace {

std::vector<std::string> split_tabs(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const auto tab = line.find('\t', start);
    fields.emplace_back(line.substr(start, tab == std::string_view::npos ? std::string_view::npos : tab - start));
    if (tab == std::string_view::npos) break;
    start = tab + 1;
  }
  return fields;
}

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return std::string(s.substr(first, last - first + 1));
}

// A field with the export's decimal separator; empty -> NaN; anything else -> nullopt.
std::optional<double> parse_number(std::string_view field, char decimal) {
  std::string text = trim(field);
  if (text.empty()) return std::numeric_limits<double>::quiet_NaN();
  for (char& c : text)
    if (c == decimal) c = '.';
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// "Länge :" -> "Länge", "Höhe [mm]:" -> "Höhe".
std::string header_key(std::string_view raw) {
  std::string key = trim(raw);
  if (!key.empty() && key.back() == ':') key.pop_back();
  const auto bracket = key.find('[');
  if (bracket != std::string::npos) key = key.substr(0, bracket);
  return trim(key);
}

}  // namespace

std::optional<std::size_t> MtsBlock::find(std::string_view name) const {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return i;
  return std::nullopt;
}

std::optional<double> MtsExport::header_number(std::string_view key) const {
  const auto text = header_text(key);
  if (!text) return std::nullopt;
  const auto v = parse_number(*text, decimal_separator);
  if (!v || std::isnan(*v)) return std::nullopt;
  return v;
}

std::optional<std::string> MtsExport::header_text(std::string_view key) const {
  for (const auto& [k, v] : header)
    if (k.rfind(key, 0) == 0) return v;
  return std::nullopt;
}

std::string latin1_to_utf8(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (unsigned char c : text) {
    if (c < 0x80) {
      out += char(c);
    } else {
      out += char(0xC0 | (c >> 6));
      out += char(0x80 | (c & 0x3F));
    }
  }
  return out;
}

bool is_mts_export(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char head[7] = {0};
  in.read(head, 7);
  return in.gcount() == 7 && std::string_view(head, 7) == "MTS793|";
}

MtsExport parse_mts_export(std::string_view latin1_text, std::string origin) {
  const std::string text = latin1_to_utf8(latin1_text);
  MtsExport out;
  out.origin = std::move(origin);
  std::vector<std::string> lines;
  {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines.push_back(line);
    }
  }
  if (lines.empty() || lines.front().rfind("MTS793|", 0) != 0)
    throw InputError(out.origin + ": not an MTS 793 export (first line does not start with 'MTS793|')");
  {
    std::vector<std::string> sig;
    std::stringstream s(lines.front());
    std::string field;
    while (std::getline(s, field, '|')) sig.push_back(field);
    if (sig.size() > 5 && sig[5].size() == 1) out.decimal_separator = sig[5][0];
  }

  bool in_header = false;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (line.rfind("Bediener Information Ende", 0) == 0) {
      in_header = false;
      continue;
    }
    if (line.rfind("Bediener Information", 0) == 0) {
      in_header = true;
      // The opening line may carry a remark ("Würfeldruckfestigkeit (150mm)") before its time stamp.
      const auto fields = split_tabs(line);
      std::string remark;
      for (std::size_t f = 1; f < fields.size() && trim(fields[f]) != "Zeit:"; ++f)
        if (const std::string part = trim(fields[f]); !part.empty()) {
          if (!remark.empty()) remark += ' ';
          remark += part;
        }
      if (!remark.empty()) out.header.emplace_back("Bemerkung (Kopf)", remark);
      continue;
    }
    if (in_header) {
      const auto fields = split_tabs(line);
      if (fields.size() >= 2 && !trim(fields[0]).empty()) out.header.emplace_back(header_key(fields[0]), trim(fields[1]));
      continue;
    }
    if (line.rfind("Datenerfassung", 0) != 0) continue;
    if (i + 2 >= lines.size())
      throw InputError(out.origin + ":" + std::to_string(i + 1) + ": data block without column names and units");
    MtsBlock block;
    block.first_line = i + 2;
    for (const auto& n : split_tabs(lines[i + 1])) block.names.push_back(trim(n));
    for (const auto& u : split_tabs(lines[i + 2])) block.units.push_back(trim(u));
    if (block.units.size() != block.names.size())
      throw InputError(out.origin + ":" + std::to_string(i + 3) + ": " + std::to_string(block.units.size()) +
                       " units for " + std::to_string(block.names.size()) + " columns");
    block.columns.assign(block.names.size(), {});
    std::size_t r = i + 3;
    for (; r < lines.size(); ++r) {
      const std::string& row = lines[r];
      if (trim(row).empty() || row.rfind("Datenerfassung", 0) == 0) break;
      const auto fields = split_tabs(row);
      if (fields.size() > block.names.size())
        throw InputError(out.origin + ":" + std::to_string(r + 1) + ": " + std::to_string(fields.size()) +
                         " fields for " + std::to_string(block.names.size()) + " columns");
      for (std::size_t c = 0; c < block.names.size(); ++c) {
        const auto v = c < fields.size() ? parse_number(fields[c], out.decimal_separator)
                                         : std::optional<double>(std::numeric_limits<double>::quiet_NaN());
        if (!v)
          throw InputError(out.origin + ":" + std::to_string(r + 1) + ": column '" + block.names[c] + "': '" +
                           trim(fields[c]) + "' is not a number");
        block.columns[c].push_back(*v);
      }
    }
    out.blocks.push_back(std::move(block));
    i = r - 1;
  }
  if (out.blocks.empty()) throw InputError(out.origin + ": no data block ('Datenerfassung') found");
  return out;
}

MtsExport read_mts_export(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path.string());
  std::ostringstream s;
  s << in.rdbuf();
  return parse_mts_export(s.str(), path.string());
}

}  // namespace mesowave::io
