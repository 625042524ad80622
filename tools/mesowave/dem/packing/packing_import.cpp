#include "mesowave/dem/packing/packing_import.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/io/csv.hpp"

namespace mesowave::dem {
namespace {

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path.string());
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

struct UnitColumn {
  std::size_t index;
  double factor;
};

std::optional<UnitColumn> unit_column(const io::CsvTable& t, const std::string& stem) {
  for (auto [suffix, factor] : {std::pair{"m", 1.0}, {"mm", 1e-3}, {"um", 1e-6}})
    if (auto i = t.find_column(stem + "_" + suffix)) return UnitColumn{*i, factor};
  return std::nullopt;
}

UnitColumn required_column(const io::CsvTable& t, const std::string& stem) {
  if (auto c = unit_column(t, stem)) return *c;
  throw InputError(t.origin + ": no column " + stem + "_m, " + stem + "_mm or " + stem + "_um (units go in the name)");
}

void check_sphere(const std::string& where, double r) {
  if (!(r > 0) || !std::isfinite(r)) throw InputError(where + "radius " + format_number(r) + " m is not positive");
}

bool parse_double(std::string_view text, double& value) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && ptr == text.data() + text.size() && std::isfinite(value);
}

}  // namespace

Packing parse_packing_csv(const std::string& text, const std::string& origin) {
  const auto t = io::parse_csv(text, origin);
  const auto cx = required_column(t, "x"), cy = required_column(t, "y"), cz = required_column(t, "z");
  auto cr = unit_column(t, "r");
  double radius_factor = 1;
  if (!cr) {
    cr = unit_column(t, "d");
    radius_factor = 0.5;
  }
  if (!cr) throw InputError(origin + ": no radius column r_m, r_mm or r_um (or diameter d_m, d_mm, d_um)");
  const auto id_column = t.find_column("id");
  Packing p;
  std::set<std::int64_t> seen;
  for (std::size_t row = 0; row < t.rows.size(); ++row) {
    const std::string where = origin + ":" + std::to_string(t.row_lines[row]) + ": ";
    const double r = t.number(row, cr->index) * cr->factor * radius_factor;
    check_sphere(where, r);
    p.centres_m.push_back({t.number(row, cx.index) * cx.factor, t.number(row, cy.index) * cy.factor,
                           t.number(row, cz.index) * cz.factor});
    p.radii_m.push_back(r);
    std::int64_t id = std::int64_t(row);
    if (id_column) {
      const std::string& field = t.text(row, *id_column);
      const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), id);
      if (field.empty() || ec != std::errc() || ptr != field.data() + field.size())
        throw InputError(where + "id '" + field + "' is not an integer");
    }
    if (!seen.insert(id).second) throw InputError(where + "id " + std::to_string(id) + " appears twice");
    p.ids.push_back(id);
  }
  if (p.size() == 0) throw InputError(origin + ": no spheres");
  return p;
}

Packing read_packing_csv(const std::filesystem::path& path) { return parse_packing_csv(read_all(path), path.string()); }

Packing parse_yade_text(const std::string& text, const std::string& origin) {
  Packing p;
  std::string format = "x_y_z_r";
  std::istringstream in(text);
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const std::string where = origin + ":" + std::to_string(number) + ": ";
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.empty()) continue;
    if (w[0] == "#format") {
      if (w.size() < 2) throw InputError(where + "#format names no layout");
      format = w[1];
      if (format != "x_y_z_r" && format != "x_y_z_r_matId" && format != "id_x_y_z_r_matId")
        throw InputError(where + "format '" + format + "' is not x_y_z_r, x_y_z_r_matId or id_x_y_z_r_matId");
      continue;
    }
    if (w[0][0] == '#') continue;
    const std::size_t first = format == "id_x_y_z_r_matId" ? 1 : 0;
    const std::size_t needed = format == "x_y_z_r" ? 4 : (format == "x_y_z_r_matId" ? 5 : 6);
    if (w.size() < needed)
      throw InputError(where + std::to_string(w.size()) + " fields where " + format + " needs " + std::to_string(needed));
    double v[4];
    for (int k = 0; k < 4; ++k)
      if (!parse_double(w[first + std::size_t(k)], v[k]))
        throw InputError(where + "'" + w[first + std::size_t(k)] + "' is not a finite number");
    check_sphere(where, v[3]);
    p.centres_m.push_back({v[0], v[1], v[2]});
    p.radii_m.push_back(v[3]);
    p.ids.push_back(std::int64_t(p.ids.size()));
  }
  if (p.size() == 0) throw InputError(origin + ": no spheres");
  return p;
}

Packing read_yade_text(const std::filesystem::path& path) { return parse_yade_text(read_all(path), path.string()); }

std::string yade_text(const Packing& p, const std::string& comment) {
  std::string out = "#format x_y_z_r\n";
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out += "# " + line + "\n";
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& c = p.centres_m[i];
    out += format_exact(c[0]) + ' ' + format_exact(c[1]) + ' ' + format_exact(c[2]) + ' ' + format_exact(p.radii_m[i]) + '\n';
  }
  return out;
}

std::string packing_csv(const Packing& p) {
  std::vector<std::vector<std::string>> rows;
  rows.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& c = p.centres_m[i];
    rows.push_back({std::to_string(p.ids[i]), format_exact(c[0]), format_exact(c[1]), format_exact(c[2]),
                    format_exact(p.radii_m[i])});
  }
  return io::to_csv({"id", "x_m", "y_m", "z_m", "r_m"}, rows);
}

}  // namespace mesowave::dem
