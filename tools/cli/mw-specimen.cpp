// mw-specimen - flowchart step 1: the density of concrete specimens.
//
//   mw-specimen --shape cube --side-mm 150 --mass-g 7187.27
//   mw-specimen --csv specimens.csv --table densities.csv --out density.json
//
// One specimen from options, or a batch from a CSV (one row per specimen),
// reported as the mean and standard deviation. The resolution of the balance
// and the caliper is propagated to a standard uncertainty (GUM, rectangular).
#include <cmath>
#include <optional>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/lab/specimen_density.hpp"

using namespace mesowave;

namespace {

struct Options {
  std::string shape = "cube";
  std::optional<double> mass_g, side_mm, length_mm, width_mm, height_mm, diameter_mm;
  double mass_resolution_g = 0.1;
  double length_resolution_mm = 0.01;
  std::filesystem::path csv, table, out;
};

// The dimension options a shape needs, in the order they are reported.
std::vector<std::string> dimensions_of(lab::SpecimenShape shape) {
  switch (shape) {
    case lab::SpecimenShape::Cube: return {"side_mm"};
    case lab::SpecimenShape::Prism: return {"length_mm", "width_mm", "height_mm"};
    case lab::SpecimenShape::Cylinder: return {"diameter_mm", "height_mm"};
  }
  return {};
}

lab::SpecimenGeometry geometry_from(lab::SpecimenShape shape, const std::map<std::string, double>& mm) {
  lab::SpecimenGeometry g;
  g.shape = shape;
  auto get = [&](const std::string& key) { return mm.count(key) ? mm.at(key) * units::mm : 0.0; };
  g.side_m = get("side_mm");
  g.length_m = get("length_mm");
  g.width_m = get("width_mm");
  g.height_m = get("height_mm");
  g.diameter_m = get("diameter_mm");
  return g;
}

lab::MeasurementResolution resolution_from(double mass_g, double length_mm) {
  if (!std::isfinite(mass_g) || mass_g < 0) throw InputError("mass resolution (" + format_quantity(mass_g, "g") + ") must be >= 0");
  if (!std::isfinite(length_mm) || length_mm < 0)
    throw InputError("length resolution (" + format_quantity(length_mm, "mm") + ") must be >= 0");
  return {mass_g * units::g, length_mm * units::mm};
}

void one_specimen(app::Run& run, const Options& o) {
  const auto shape = lab::parse_specimen_shape(o.shape);
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
  const auto d = lab::specimen_density(*o.mass_g * units::g, geometry_from(shape, mm),
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
  run.metric("density", d.density_kg_m3, "kg/m3");
  run.emit_json(result, o.out);
}

void batch(app::Run& run, const Options& o) {
  run.input(o.csv);
  const auto table = io::read_csv(o.csv);
  static const std::set<std::string> known = {"specimen",  "shape",     "mass_g",      "side_mm",
                                              "length_mm", "width_mm",  "height_mm",   "diameter_mm",
                                              "note",      "mass_resolution_g", "length_resolution_mm"};
  for (const auto& column : table.header)
    if (!known.count(column))
      throw InputError(o.csv.string() + ": unknown column '" + column +
                       "' (known: specimen, shape, mass_g, side_mm, length_mm, width_mm, height_mm, diameter_mm, "
                       "mass_resolution_g, length_resolution_mm, note)");
  if (table.rows.empty()) throw InputError(o.csv.string() + ": no specimens");
  const std::size_t mass_col = table.column("mass_g");

  std::vector<lab::SpecimenDensity> densities;
  std::vector<std::vector<std::string>> rows;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const std::string where = o.csv.string() + ":" + std::to_string(table.row_lines[r]);
    auto number_or = [&](const std::string& column, double fallback) {
      auto c = table.find_column(column);
      return (c && !table.text(r, *c).empty()) ? table.number(r, *c) : fallback;
    };
    const std::string shape_name = table.find_column("shape") ? table.text(r, table.column("shape")) : o.shape;
    const auto shape = lab::parse_specimen_shape(shape_name);
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
    densities.push_back(lab::specimen_density(mass_g * units::g, geometry_from(shape, mm), resolution));
    const std::string id = table.find_column("specimen") ? table.text(r, table.column("specimen")) : std::to_string(r + 1);
    rows.push_back({id, shape_name, format_number(mass_g), format_number(densities.back().volume_m3),
                    format_fixed(densities.back().density_kg_m3, 2), format_fixed(densities.back().u_density_kg_m3, 2)});
  }
  const auto s = lab::summarize_densities(densities);
  if (!o.table.empty())
    run.write_text(o.table, io::to_csv({"specimen", "shape", "mass_g", "volume_m3", "density_kg_m3", "u_density_kg_m3"}, rows));

  nlohmann::ordered_json result;
  result["specimens"] = s.count;
  result["density_kg_m3"] = s.mean_kg_m3;
  result["density_std_kg_m3"] = s.std_kg_m3;
  result["density_sem_kg_m3"] = s.sem_kg_m3;
  result["u_density_resolution_kg_m3"] = s.u_resolution_kg_m3;
  result["u_density_kg_m3"] = s.u_mean_kg_m3;
  result["density_min_kg_m3"] = s.min_kg_m3;
  result["density_max_kg_m3"] = s.max_kg_m3;
  run.metric("density", s.mean_kg_m3, "kg/m3");
  run.metric("density_std", s.std_kg_m3, "kg/m3");
  run.emit_json(result, o.out);
}

}  // namespace

int main(int argc, char** argv) {
  app::Tool tool("mw-specimen",
                 "Density of concrete specimens from mass and dimensions (flowchart step 1: rho = m / V), with the "
                 "balance and caliper resolution propagated to a standard uncertainty u = rho * sqrt((u_m/m)^2 + "
                 "sum (n u_L/L)^2), u = resolution/sqrt(12).\n\n"
                 "  mw-specimen --shape cube --side-mm 150 --mass-g 7187.27\n"
                 "  mw-specimen --csv specimens.csv --table densities.csv --out density.json\n\n"
                 "CSV columns: specimen, shape (cube|prism|cylinder), mass_g, side_mm | length_mm width_mm height_mm "
                 "| diameter_mm height_mm, and optionally mass_resolution_g, length_resolution_mm, note.");
  Options o;
  auto& cli = tool.cli();
  cli.add_option("--shape", o.shape, "cube | prism | cylinder")->capture_default_str();
  cli.add_option("--mass-g", o.mass_g, "Mass of the specimen [g]");
  cli.add_option("--side-mm", o.side_mm, "Cube: edge length [mm]");
  cli.add_option("--length-mm", o.length_mm, "Prism: length [mm]");
  cli.add_option("--width-mm", o.width_mm, "Prism: width [mm]");
  cli.add_option("--height-mm", o.height_mm, "Prism or cylinder: height [mm]");
  cli.add_option("--diameter-mm", o.diameter_mm, "Cylinder: diameter [mm]");
  cli.add_option("--mass-resolution-g", o.mass_resolution_g, "Resolution of the balance [g]")->capture_default_str();
  cli.add_option("--length-resolution-mm", o.length_resolution_mm, "Resolution of the caliper [mm]")
      ->capture_default_str();
  cli.add_option("--csv", o.csv, "A batch of specimens, one per row (see above)")->type_name("FILE");
  cli.add_option("--table", o.table, "With --csv: write each specimen's density to FILE (CSV)")->type_name("FILE");
  app::add_out_option(cli, o.out);

  return tool.run(argc, argv, [&](app::Run& run) {
    if (!o.table.empty() && o.csv.empty()) throw InputError("--table needs a batch (--csv)");
    if (o.csv.empty()) one_specimen(run, o);
    else batch(run, o);
  });
}
