#include "mesowave/lab/specimen_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"

namespace mesowave::lab {

namespace {

// The dimensions a shape needs, in the order they are reported.
std::vector<std::string> dimensions_of(SpecimenShape shape) {
  switch (shape) {
    case SpecimenShape::Cube: return {"side_mm"};
    case SpecimenShape::Prism: return {"length_mm", "width_mm", "height_mm"};
    case SpecimenShape::Cylinder: return {"diameter_mm", "height_mm"};
  }
  return {};
}

SpecimenGeometry geometry_from(SpecimenShape shape, const std::map<std::string, double>& mm) {
  SpecimenGeometry g;
  g.shape = shape;
  auto get = [&](const std::string& key) { return mm.count(key) ? mm.at(key) * units::mm : 0.0; };
  g.side_m = get("side_mm");
  g.length_m = get("length_mm");
  g.width_m = get("width_mm");
  g.height_m = get("height_mm");
  g.diameter_m = get("diameter_mm");
  return g;
}

MeasurementResolution resolution_from(double mass_g, double length_mm) {
  if (!std::isfinite(mass_g) || mass_g < 0) throw InputError("mass resolution (" + format_quantity(mass_g, "g") + ") must be >= 0");
  if (!std::isfinite(length_mm) || length_mm < 0)
    throw InputError("length resolution (" + format_quantity(length_mm, "mm") + ") must be >= 0");
  return {mass_g * units::g, length_mm * units::mm};
}

}  // namespace

nlohmann::ordered_json specimen_density_summary(const SpecimenMeasurement& o) {
  const auto shape = parse_specimen_shape(o.shape);
  if (!o.mass_g) throw InputError("--mass-g is required (or give a batch with --csv)");
  require_positive("--mass-g", *o.mass_g, "g");
  const std::map<std::string, std::optional<double>> given = {{"side_mm", o.side_mm},     {"length_mm", o.length_mm},
                                                             {"width_mm", o.width_mm},   {"height_mm", o.height_mm},
                                                             {"diameter_mm", o.diameter_mm}};
  std::map<std::string, double> mm;
  for (const auto& key : dimensions_of(shape)) {
    std::string option = "--" + key;
    std::replace(option.begin(), option.end(), '_', '-');
    if (!given.at(key)) throw InputError("a " + o.shape + " needs " + option);
    mm[key] = require_positive(option, *given.at(key), "mm");
  }
  const auto d = specimen_density(*o.mass_g * units::g, geometry_from(shape, mm),
                                  resolution_from(o.mass_resolution_g, o.length_resolution_mm));
  nlohmann::ordered_json result;
  result["shape"] = o.shape;
  result["mass_g"] = *o.mass_g;
  for (const auto& [key, value] : mm) result[key] = value;
  result["mass_resolution_g"] = o.mass_resolution_g;
  result["length_resolution_mm"] = o.length_resolution_mm;
  result["volume_m3"] = d.volume_m3;
  result["density_kg_m3"] = d.density_kg_m3;
  result["u_density_kg_m3"] = d.u_density_kg_m3;
  return result;
}

DensityBatchReport density_batch_report(const io::CsvTable& table, const SpecimenMeasurement& o) {
  static const std::set<std::string> known = {"specimen",  "shape",     "mass_g",      "side_mm",
                                              "length_mm", "width_mm",  "height_mm",   "diameter_mm",
                                              "note",      "mass_resolution_g", "length_resolution_mm"};
  for (const auto& column : table.header)
    if (!known.count(column))
      throw InputError(table.origin + ": unknown column '" + column +
                       "' (known: specimen, shape, mass_g, side_mm, length_mm, width_mm, height_mm, diameter_mm, "
                       "mass_resolution_g, length_resolution_mm, note)");
  if (table.rows.empty()) throw InputError(table.origin + ": no specimens");
  const std::size_t mass_col = table.column("mass_g");

  std::vector<SpecimenDensity> densities;
  std::vector<std::vector<std::string>> rows;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const std::string where = table.origin + ":" + std::to_string(table.row_lines[r]);
    auto number_or = [&](const std::string& column, double fallback) {
      auto c = table.find_column(column);
      return (c && !table.text(r, *c).empty()) ? table.number(r, *c) : fallback;
    };
    const std::string shape_name = table.find_column("shape") ? table.text(r, table.column("shape")) : o.shape;
    const auto shape = parse_specimen_shape(shape_name);
    std::map<std::string, double> mm;
    for (const auto& key : dimensions_of(shape)) {
      auto c = table.find_column(key);
      if (!c || table.text(r, *c).empty()) throw InputError(where + ": a " + shape_name + " needs " + key);
      mm[key] = table.number(r, *c);
      if (mm[key] <= 0) throw InputError(where + ": " + key + " (" + format_quantity(mm[key], "mm") + ") must be positive");
    }
    const double mass_g = table.number(r, mass_col);
    if (mass_g <= 0) throw InputError(where + ": mass_g (" + format_quantity(mass_g, "g") + ") must be positive");
    const auto resolution = resolution_from(number_or("mass_resolution_g", o.mass_resolution_g),
                                            number_or("length_resolution_mm", o.length_resolution_mm));
    densities.push_back(specimen_density(mass_g * units::g, geometry_from(shape, mm), resolution));
    const std::string id = table.find_column("specimen") ? table.text(r, table.column("specimen")) : std::to_string(r + 1);
    rows.push_back({id, shape_name, format_number(mass_g), format_number(densities.back().volume_m3),
                    format_fixed(densities.back().density_kg_m3, 2), format_fixed(densities.back().u_density_kg_m3, 2)});
  }
  const auto s = summarize_densities(densities);
  DensityBatchReport report;
  report.table_csv =
      io::to_csv({"specimen", "shape", "mass_g", "volume_m3", "density_kg_m3", "u_density_kg_m3"}, rows);
  auto& result = report.summary;
  result["specimens"] = s.count;
  result["density_kg_m3"] = s.mean_kg_m3;
  result["density_std_kg_m3"] = s.std_kg_m3;
  result["density_sem_kg_m3"] = s.sem_kg_m3;
  result["u_density_resolution_kg_m3"] = s.u_resolution_kg_m3;
  result["u_density_kg_m3"] = s.u_mean_kg_m3;
  result["density_min_kg_m3"] = s.min_kg_m3;
  result["density_max_kg_m3"] = s.max_kg_m3;
  return report;
}

}  // namespace mesowave::lab
