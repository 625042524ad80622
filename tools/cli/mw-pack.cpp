// mw-pack - flowchart step 5 (concrete paper, Section 4.2): the DEM model's
// packing of spheres, written as a packing HDF5 file (dem/packing/packing_file.hpp)
// with a flat JSON summary.
//
//   mw-pack box --cube-side-mm 50 --porosity-pct 7 --d-min-mm 1.6 --d-max-mm 2
//               --density-kg-m3 2129.56 --packing cube.h5
//   mw-pack cylinder --diameter-mm 50 --height-mm 100 --porosity-pct 7 --sieve-curve sand.csv --packing cyl.h5
//   mw-pack line --sphere-radius-mm 5.1 --spacing-R 1.03 --length-mm 1000 --density-kg-m3 7850.66 --packing rod.h5
//   mw-pack import yade-spheres.txt --lower-mm 0 0 0 --upper-mm 50 50 50 --packing same.h5
//
// The work (the container, the sizes, the mass, the summary) lives in
// dem/packing/packing_request.hpp; the packing method in dem/packing/packing_generator.hpp.
#include <chrono>
#include <optional>

#include "mesowave/app/progress.hpp"
#include "mesowave/app/tool.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/dem/packing/packing_file.hpp"
#include "mesowave/dem/packing/packing_import.hpp"
#include "mesowave/dem/packing/packing_request.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  app::Tool tool(
      "mw-pack",
      "Make (or import) the packing of spheres a DEM model starts from (concrete paper Section 4.2, rod paper "
      "Section 3) and write it as a packing HDF5 file with a JSON summary.\n"
      "Porosity p = 1 - sum(V_sphere)/V_container; p = 7 % is reached with overlaps. Diameters are drawn until "
      "their volume is (1 - p) V_container, centres placed at random at least their radius from every wall, then "
      "the overlap energy sum 1/2 xi^2 + Q/4 xi^4 (xi = overlap / smaller radius) is minimised (FIRE; for "
      "d_max > 1.5 d_min while the radii grow to full size), so overlaps spread evenly and no sphere is buried. Particle density "
      "rho_p = m_specimen / sum(V_sphere), so the model weighs what the specimen weighs. A line of spheres (rod "
      "model) has n = ceil(L/d) spheres at spacing d on the rod axis (z).\n\n"
      "  mw-pack box --cube-side-mm 50 --porosity-pct 7 --d-min-mm 1.6 --d-max-mm 2 --density-kg-m3 2129.56 "
      "--packing cube.h5\n"
      "  mw-pack box --from lab-data/concrete-cube/porosity.toml --from lab-data/concrete-cube/dem-packing.toml "
      "--packing cube.h5\n"
      "  mw-pack cylinder --diameter-mm 50 --height-mm 100 --porosity-pct 10 --sieve-curve sand.csv --d-min-mm 1 "
      "--packing cyl.h5\n"
      "  mw-pack line --sphere-radius-mm 5.1 --spacing-R 1.03 --length-mm 1000 --density-kg-m3 7850.66 "
      "--packing rod.h5\n"
      "  mw-pack line --experiment lab-data/steel-rod/experiment.toml --spacing-R 1.03 --packing rod.h5   (the same)\n"
      "  mw-pack import spheres.txt --lower-mm 0 0 0 --upper-mm 50 50 50 --packing same.h5   (Yade textExt, metres)\n"
      "  mw-pack import spheres.csv --packing same.h5   (columns x_mm,y_mm,z_mm,r_mm or x_m,...; container = "
      "bounding box)\n"
      "Threads: --threads N, else the cores the machine is not busy with, one below 4096 spheres (the packing is "
      "the same bits either way; the summary says how many and why).");
  dem::PackingRequest o;
  fs::path out, export_yade, export_csv;
  bool quiet = false;
  auto& cli = tool.cli();
  cli.add_option("container", o.container, "box | cylinder | line | import")
      ->required()
      ->check(CLI::IsMember({"box", "cylinder", "line", "import"}));
  cli.add_option("file", o.input, "import: the file to read (Yade textExt text or CSV)");
  cli.add_option("--packing", o.packing_file, "Packing HDF5 file to write")->required()->type_name("PATH");
  cli.add_option("--cube-side-mm", o.cube_side_mm, "box: a cube of this side [mm], corner at the origin");
  cli.add_option("--size-mm", o.size_mm, "box: sides X Y Z [mm], corner at the origin")->expected(3);
  cli.add_option("--diameter-mm", o.diameter_mm, "cylinder: diameter [mm] (axis along z)");
  cli.add_option("--height-mm", o.height_mm, "cylinder: height [mm]");
  cli.add_option("--porosity-pct", o.porosity_pct, "box/cylinder: target porosity 1 - sum(V_sphere)/V_container [%]");
  cli.add_option("--d-min-mm", o.d_min_mm, "Smallest diameter [mm] (uniform sizes; or where to cut a sieve curve)");
  cli.add_option("--d-max-mm", o.d_max_mm, "Largest diameter [mm] (uniform sizes; or where to cut a sieve curve)");
  cli.add_option("--sieve-curve", o.sieve_curve,
                 "CSV sieve curve: d_mm (or size_mm, d_m, ...) and passing_pct or passing_fraction, cumulative BY "
                 "MASS")
      ->type_name("FILE");
  cli.add_option("--seed", o.seed, "Random seed (same seed, same packing, bit for bit)")->capture_default_str();
  cli.add_option("--force-tolerance", o.force_tolerance,
                 "Relax until the largest net force on a sphere is below this fraction of the mean contact force")
      ->capture_default_str();
  cli.add_option("--overlap-stiffening", o.overlap_stiffening,
                 "Q of the relaxed overlap energy 1/2 xi^2 + Q/4 xi^4, xi = overlap / smaller radius (0: harmonic)")
      ->capture_default_str();
  cli.add_option("--sphere-radius-mm", o.sphere_radius_mm, "line: sphere radius R [mm] (rod paper: 5.1)");
  cli.add_option("--spacing-mm", o.spacing_mm, "line: centre spacing d [mm]");
  cli.add_option("--spacing-R", o.spacing_R, "line: centre spacing as a multiple of R (rod paper: 0.95, 1.03, 1.05, 1.15)");
  cli.add_option("--length-mm", o.length_mm, "line: rod length L [mm]; n = ceil(L/d)");
  cli.add_option("--rod-diameter-mm", o.rod_diameter_mm, "line: diameter of the rod the line stands for [mm] (default 2R)");
  cli.add_option("--experiment", o.experiment, "line: the rod of this experiment (lab-data/<study>/experiment.toml) gives "
                 "R = D/2, D, L and the density; the options beat its values")->type_name("FILE");
  cli.add_option("--import-format", o.import_format, "import: auto (.csv is CSV, else Yade) | csv | yade")
      ->check(CLI::IsMember({"auto", "csv", "yade"}))
      ->capture_default_str();
  cli.add_option("--lower-mm", o.lower_mm, "import: container box lower corner X Y Z [mm] (default: bounding box)")
      ->expected(3);
  cli.add_option("--upper-mm", o.upper_mm, "import: container box upper corner X Y Z [mm]")->expected(3);
  cli.add_option("--density-kg-m3", o.density_kg_m3,
                 "Specimen material density [kg/m3]: m_specimen = rho V_container (e.g. from mw-specimen)");
  cli.add_option("--specimen-mass-g", o.specimen_mass_g, "Specimen mass [g], instead of --density-kg-m3");
  cli.add_option("--detection-factor", o.detection_factor,
                 "C_f for the reported bond count and coordination: pairs with |x_i - x_j| <= C_f (r_i + r_j)")
      ->capture_default_str();
  cli.add_option("--export-yade", export_yade, "Also write the spheres as Yade textExt text (x y z r in m)")
      ->type_name("FILE");
  cli.add_option("--export-csv", export_csv, "Also write the spheres as CSV (id, x_m, y_m, z_m, r_m)")->type_name("FILE");
  cli.add_option("--threads", o.threads, "Threads for the relaxation (default: the cores the machine is not busy with)");
  cli.add_flag("--quiet", quiet, "No progress bar");
  app::add_out_option(cli, out, "the JSON summary");

  return tool.run(argc, argv, [&](app::Run& run) {
    const auto start = std::chrono::steady_clock::now();
    std::optional<app::Progress> progress;
    const auto on_progress = [&](double done) {
      if (!progress) progress.emplace("mw-pack " + o.container + " relaxing", 1000, "permille", !quiet);
      progress->update(std::int64_t(done * 999));
    };
    dem::PackedSpecimen made = dem::make_packing(o, on_progress);
    if (progress) progress->finish();
    for (const auto& file : made.inputs) run.input(file);
    const dem::Packing& packing = made.packing;
    dem::write_packing_file(run.output(o.packing_file), packing, made.origin);
    if (!export_yade.empty())
      run.write_text(export_yade, dem::yade_text(packing, "mesowave packing (mw-pack " + o.container + ")"));
    if (!export_csv.empty()) run.write_text(export_csv, dem::packing_csv(packing));
    made.summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    run.metric("spheres", double(made.stats.count), "");
    if (packing.container.shape != "line") run.metric("porosity", made.stats.porosity / units::percent, "%");
    run.metric("coordination", made.stats.coordination, "");
    run.metric("overlap_mean_ratio", made.stats.mean_overlap_ratio, "");
    if (made.specimen_mass_kg) run.metric("particle_density", packing.particle_density_kg_m3, "kg/m3");
    run.emit_json(made.summary, out);
  });
}
