// mw-specimen - flowchart step 1: the density of concrete specimens.
//
//   mw-specimen --shape cube --side-mm 150 --mass-g 7187.27
//   mw-specimen --csv specimens.csv --table densities.csv --out density.json
//
// One specimen from options, or a batch from a CSV (one row per specimen),
// reported as the mean and standard deviation. The resolution of the balance
// and the caliper is propagated to a standard uncertainty (GUM, rectangular).
#include "mesowave/app/tool.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/lab/specimen_report.hpp"

using namespace mesowave;

int main(int argc, char** argv) {
  app::Tool tool("mw-specimen",
                 "Density of concrete specimens from mass and dimensions (flowchart step 1: rho = m / V), with the "
                 "balance and caliper resolution propagated to a standard uncertainty u = rho * sqrt((u_m/m)^2 + "
                 "sum (n u_L/L)^2), u = resolution/sqrt(12).\n\n"
                 "  mw-specimen --shape cube --side-mm 150 --mass-g 7187.27\n"
                 "  mw-specimen --csv specimens.csv --table densities.csv --out density.json\n\n"
                 "CSV columns: specimen, shape (cube|prism|cylinder), mass_g, side_mm | length_mm width_mm height_mm "
                 "| diameter_mm height_mm, and optionally mass_resolution_g, length_resolution_mm, note.");
  lab::SpecimenMeasurement o;
  std::filesystem::path csv, table, out;
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
  cli.add_option("--csv", csv, "A batch of specimens, one per row (see above)")->type_name("FILE");
  cli.add_option("--table", table, "With --csv: write each specimen's density to FILE (CSV)")->type_name("FILE");
  app::add_out_option(cli, out);

  return tool.run(argc, argv, [&](app::Run& run) {
    if (!table.empty() && csv.empty()) throw InputError("--table needs a batch (--csv)");
    if (csv.empty()) {
      auto summary = lab::specimen_density_summary(o);
      run.metric("density", summary["density_kg_m3"].get<double>(), "kg/m3");
      app::declare_products(summary, {"density_kg_m3"});  // what mw-upv, mw-estatic and mw-pack read
      run.emit_json(summary, out);
      return;
    }
    run.input(csv);
    const auto batch = lab::density_batch_report(io::read_csv(csv), o);
    if (!table.empty()) run.write_text(table, batch.table_csv);
    run.metric("density", batch.summary["density_kg_m3"].get<double>(), "kg/m3");
    run.metric("density_std", batch.summary["density_std_kg_m3"].get<double>(), "kg/m3");
    run.emit_json(batch.summary, out);
  });
}
