// mw-pack - flowchart step 5 (concrete paper, Section 4.2): the DEM model's
// packing of spheres, written as a packing HDF5 file (dem/packing_file.hpp)
// with a flat JSON summary.
//
//   mw-pack box --cube-side-mm 50 --porosity-pct 7 --d-min-mm 1.6 --d-max-mm 2
//               --density-kg-m3 2129.56 --packing cube.h5
//   mw-pack cylinder --diameter-mm 50 --height-mm 100 --porosity-pct 7 --sieve-curve sand.csv --packing cyl.h5
//   mw-pack line --sphere-radius-mm 5.1 --spacing-R 1.03 --length-mm 1000 --density-kg-m3 7850.66 --packing rod.h5
//   mw-pack import yade-spheres.txt --lower-mm 0 0 0 --upper-mm 50 50 50 --packing same.h5
//
// The packing method (random centres, overlap-energy relaxation) lives in
// dem/packing_generator.hpp; the statistics in dem/packing_stats.hpp.
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "mesowave/app/progress.hpp"
#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/dem/packing_file.hpp"
#include "mesowave/dem/packing_generator.hpp"
#include "mesowave/dem/packing_import.hpp"
#include "mesowave/dem/packing_stats.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

namespace {

struct Options {
  std::string container;
  fs::path input, packing, out, export_yade, export_csv, sieve_curve;
  std::string import_format = "auto";
  std::optional<double> cube_side_mm, diameter_mm, height_mm, porosity_pct, d_min_mm, d_max_mm;
  std::vector<double> size_mm, lower_mm, upper_mm;
  std::optional<double> sphere_radius_mm, spacing_mm, spacing_R, length_mm, rod_diameter_mm;
  std::optional<double> density_kg_m3, specimen_mass_g;
  double detection_factor = 1.1;
  double force_tolerance = 1e-3;
  double overlap_stiffening = 3;
  std::uint64_t seed = 1;
  bool quiet = false;
};

double need(const std::optional<double>& value, const std::string& option, const std::string& why, const char* unit) {
  if (!value) throw InputError(why + " needs " + option);
  return require_positive(option, *value, unit);
}

std::array<double, 3> corner_mm(const std::vector<double>& v, const std::string& option) {
  if (v.size() != 3) throw InputError(option + " takes three values (x y z in mm)");
  for (double c : v) require_finite(option, c, "mm");
  return {v[0] * units::mm, v[1] * units::mm, v[2] * units::mm};
}

dem::Container container_from(const Options& o) {
  if (o.container == "box") {
    std::array<double, 3> size{};
    if (o.cube_side_mm && !o.size_mm.empty()) throw InputError("give --cube-side-mm or --size-mm, not both");
    if (o.cube_side_mm) {
      const double side = require_positive("--cube-side-mm", *o.cube_side_mm, "mm") * units::mm;
      size = {side, side, side};
    } else if (o.size_mm.size() == 3) {
      for (int d = 0; d < 3; ++d) size[d] = require_positive("--size-mm", o.size_mm[std::size_t(d)], "mm") * units::mm;
    } else {
      throw InputError("a box needs --cube-side-mm S or --size-mm X Y Z");
    }
    return dem::box_container({0, 0, 0}, size);
  }
  const double diameter = need(o.diameter_mm, "--diameter-mm", "a cylinder", "mm") * units::mm;
  const double height = need(o.height_mm, "--height-mm", "a cylinder", "mm") * units::mm;
  return dem::cylinder_container(diameter / 2, 0, height, diameter / 2, diameter / 2);
}

dem::SizeDistribution sizes_from(app::Run& run, const Options& o) {
  std::optional<double> lo, hi;
  if (o.d_min_mm) lo = require_positive("--d-min-mm", *o.d_min_mm, "mm") * units::mm;
  if (o.d_max_mm) hi = require_positive("--d-max-mm", *o.d_max_mm, "mm") * units::mm;
  if (lo && hi && *lo > *hi)
    throw InputError("--d-min-mm (" + format_quantity(*o.d_min_mm, "mm") + ") exceeds --d-max-mm (" +
                     format_quantity(*o.d_max_mm, "mm") + ")");
  if (!o.sieve_curve.empty()) {
    run.input(o.sieve_curve);
    return dem::SizeDistribution::sieve(dem::read_sieve_curve(o.sieve_curve), lo, hi);
  }
  if (!lo || !hi) throw InputError("give --d-min-mm and --d-max-mm (uniform diameters) or --sieve-curve FILE");
  return dem::SizeDistribution::uniform(*lo, *hi);
}

// Generates, with a progress bar driven by the residual force (it falls from
// about 10 to the tolerance roughly geometrically).
dem::Packing generate(const dem::Container& container, dem::PackingOptions options, dem::PackingRun& run, bool quiet,
                      const std::string& label) {
  app::Progress progress(label + " relaxing", 1000, "permille", !quiet);
  std::int64_t shown = 0;
  std::optional<double> first;
  options.progress = [&](std::size_t, double residual) {
    if (!first) first = std::max(residual, options.force_tolerance * 10);
    const double span = std::log(*first / options.force_tolerance);
    const double done = residual > 0 ? std::log(*first / residual) / span : 1.0;
    shown = std::max(shown, std::int64_t(std::clamp(done, 0.0, 1.0) * 999));
    progress.update(shown);
  };
  auto packing = dem::generate_packing(container, options, &run);
  progress.finish();
  return packing;
}

// Threads for the relaxation. Each FIRE iteration ends at a barrier, so on a
// machine already busier than its cores a second thread mostly waits for the
// first to get a core back (measured: 2 threads 2-3x slower than 1 at load 8 on
// 2 cores). Unless OMP_NUM_THREADS says otherwise, run on one thread then.
// The packing is the same bits for any thread count.
int choose_threads() {
  if (std::getenv("OMP_NUM_THREADS")) return omp_get_max_threads();
  double load = 0;
  const int cores = omp_get_num_procs();
  if (getloadavg(&load, 1) == 1 && load > cores - 0.5) omp_set_num_threads(1);
  return omp_get_max_threads();
}

dem::Packing imported(app::Run& run, const Options& o) {
  if (o.input.empty()) throw InputError("import needs the file to read: mw-pack import FILE");
  run.input(o.input);
  std::string format = o.import_format;
  if (format == "auto") format = o.input.extension() == ".csv" ? "csv" : "yade";
  auto p = format == "csv" ? dem::read_packing_csv(o.input) : dem::read_yade_text(o.input);
  if (o.lower_mm.empty() != o.upper_mm.empty()) throw InputError("give both --lower-mm and --upper-mm, or neither");
  p.container = o.lower_mm.empty() ? dem::bounding_box(p)
                                   : dem::box_container(corner_mm(o.lower_mm, "--lower-mm"), corner_mm(o.upper_mm, "--upper-mm"));
  return p;
}

dem::Packing rod_line(const Options& o) {
  dem::RodLine line;
  line.sphere_radius_m = need(o.sphere_radius_mm, "--sphere-radius-mm", "a line", "mm") * units::mm;
  if (o.spacing_mm.has_value() == o.spacing_R.has_value())
    throw InputError("a line needs exactly one of --spacing-mm and --spacing-R");
  line.spacing_m = o.spacing_mm ? require_positive("--spacing-mm", *o.spacing_mm, "mm") * units::mm
                                : require_positive("--spacing-R", *o.spacing_R) * line.sphere_radius_m;
  line.length_m = need(o.length_mm, "--length-mm", "a line", "mm") * units::mm;
  line.rod_radius_m = o.rod_diameter_mm ? require_positive("--rod-diameter-mm", *o.rod_diameter_mm, "mm") * units::mm / 2
                                        : line.sphere_radius_m;
  return dem::line_of_spheres(line);
}

}  // namespace

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
      "  mw-pack import spheres.txt --lower-mm 0 0 0 --upper-mm 50 50 50 --packing same.h5   (Yade textExt, metres)\n"
      "  mw-pack import spheres.csv --packing same.h5   (columns x_mm,y_mm,z_mm,r_mm or x_m,...; container = "
      "bounding box)\n"
      "Threads: OMP_NUM_THREADS; if unset, all cores, or one when the load average exceeds the cores (the packing "
      "is the same bits either way).");
  Options o;
  auto& cli = tool.cli();
  cli.add_option("container", o.container, "box | cylinder | line | import")
      ->required()
      ->check(CLI::IsMember({"box", "cylinder", "line", "import"}));
  cli.add_option("file", o.input, "import: the file to read (Yade textExt text or CSV)");
  cli.add_option("--packing", o.packing, "Packing HDF5 file to write")->required()->type_name("PATH");
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
  cli.add_option("--export-yade", o.export_yade, "Also write the spheres as Yade textExt text (x y z r in m)")
      ->type_name("FILE");
  cli.add_option("--export-csv", o.export_csv, "Also write the spheres as CSV (id, x_m, y_m, z_m, r_m)")->type_name("FILE");
  cli.add_flag("--quiet", o.quiet, "No progress bar");
  app::add_out_option(cli, o.out, "the JSON summary");

  return tool.run(argc, argv, [&](app::Run& run) {
    const auto start = std::chrono::steady_clock::now();
    require_positive("--detection-factor", o.detection_factor);
    if (o.density_kg_m3 && o.specimen_mass_g) throw InputError("give --density-kg-m3 or --specimen-mass-g, not both");
    if (o.density_kg_m3) require_positive("--density-kg-m3", *o.density_kg_m3, "kg/m3");
    if (o.specimen_mass_g) require_positive("--specimen-mass-g", *o.specimen_mass_g, "g");
    if (!o.input.empty() && o.container != "import") throw InputError("a file argument is only for import");

    dem::Packing packing;
    dem::PackingRun relax;
    dem::PackingOrigin origin;
    nlohmann::ordered_json summary;
    summary["packing_file"] = o.packing.string();
    summary["container"] = o.container;
    if (o.container == "box" || o.container == "cylinder") {
      const auto container = container_from(o);
      dem::PackingOptions options;
      if (!o.porosity_pct) throw InputError("a " + o.container + " needs --porosity-pct");
      options.porosity = require_finite("--porosity-pct", *o.porosity_pct, "%") * units::percent;
      if (options.porosity <= 0 || options.porosity >= 1)
        throw InputError("--porosity-pct (" + format_quantity(*o.porosity_pct, "%") + ") must lie strictly between 0 and 100");
      options.sizes = sizes_from(run, o);
      options.seed = o.seed;
      options.force_tolerance = require_positive("--force-tolerance", o.force_tolerance);
      options.overlap_stiffening = require_in_range("--overlap-stiffening", o.overlap_stiffening, 0, 1000);
      summary["threads"] = choose_threads();
      packing = generate(container, options, relax, o.quiet, "mw-pack " + o.container);
      origin.text = {{"method", "random centres, overlap-energy relaxation (FIRE), mw-pack"},
                     {"seed", std::to_string(o.seed)},
                     {"size_distribution", options.sizes.describe()}};
      if (!o.sieve_curve.empty()) origin.text.emplace_back("sieve_curve", o.sieve_curve.string());
      origin.numbers = {{"target_porosity", options.porosity},
                        {"force_tolerance", options.force_tolerance},
                        {"overlap_stiffening", options.overlap_stiffening},
                        {"relaxation_iterations", double(relax.iterations)},
                        {"relaxation_residual", relax.residual}};
      summary["seed"] = o.seed;
      summary["size_distribution"] = options.sizes.describe();
      summary["porosity_target_pct"] = *o.porosity_pct;
    } else if (o.container == "line") {
      packing = rod_line(o);
      origin.text = {{"method", "line of spheres, n = ceil(L/d), mw-pack"}};
      summary["sphere_radius_mm"] = packing.radii_m.front() / units::mm;
      summary["spacing_mm"] = (packing.size() > 1 ? packing.centres_m[1][2] - packing.centres_m[0][2] : 0.0) / units::mm;
      summary["spacing_R"] = o.spacing_R ? *o.spacing_R : *o.spacing_mm / *o.sphere_radius_mm;
      summary["length_mm"] = *o.length_mm;
      summary["rod_diameter_mm"] = 2 * packing.container.radius_m / units::mm;
      summary["chain_length_mm"] =
          (packing.centres_m.back()[2] - packing.centres_m.front()[2] + 2 * packing.radii_m.front()) / units::mm;
    } else {
      packing = imported(run, o);
      origin.text = {{"method", "imported by mw-pack"}, {"source_file", o.input.string()}};
    }

    const double volume = dem::container_volume(packing.container);
    std::optional<double> mass;
    if (o.density_kg_m3) mass = dem::specimen_mass(*o.density_kg_m3, packing.container);
    if (o.specimen_mass_g) mass = *o.specimen_mass_g * units::g;
    if (mass) packing.particle_density_kg_m3 = dem::particle_density_for_mass(*mass, packing);

    const auto stats = dem::packing_stats(packing, o.detection_factor);
    dem::write_packing_file(run.output(o.packing), packing, origin);
    if (!o.export_yade.empty())
      run.write_text(o.export_yade, dem::yade_text(packing, "mesowave packing (mw-pack " + o.container + ")"));
    if (!o.export_csv.empty()) run.write_text(o.export_csv, dem::packing_csv(packing));

    summary["spheres"] = stats.count;
    summary["container_lower_mm"] = std::vector<double>{packing.container.lower_m[0] / units::mm,
                                                        packing.container.lower_m[1] / units::mm,
                                                        packing.container.lower_m[2] / units::mm};
    summary["container_upper_mm"] = std::vector<double>{packing.container.upper_m[0] / units::mm,
                                                        packing.container.upper_m[1] / units::mm,
                                                        packing.container.upper_m[2] / units::mm};
    if (packing.container.shape != "box") summary["container_radius_mm"] = packing.container.radius_m / units::mm;
    summary["container_volume_mm3"] = volume / 1e-9;
    summary["solid_volume_mm3"] = stats.solid_volume_m3 / 1e-9;
    if (packing.container.shape == "line") {
      summary["solid_to_rod_volume"] = stats.solid_volume_m3 / volume;  // > 1: spheres overlap and bulge out
    } else {
      summary["porosity_pct"] = stats.porosity / units::percent;
      if (stats.core_porosity) summary["core_porosity_pct"] = *stats.core_porosity / units::percent;
    }
    summary["d_mean_mm"] = stats.d_mean_m / units::mm;
    summary["d_std_mm"] = stats.d_std_m / units::mm;
    summary["d_min_mm"] = stats.d_min_m / units::mm;
    summary["d_max_mm"] = stats.d_max_m / units::mm;
    summary["contacts"] = stats.contacts;
    summary["coordination_contacts"] = stats.coordination_contacts;
    summary["overlap_mean_ratio"] = stats.mean_overlap_ratio;
    summary["overlap_max_ratio"] = stats.max_overlap_ratio;
    summary["detection_factor"] = o.detection_factor;
    summary["bonds"] = stats.bonds;
    summary["coordination"] = stats.coordination;
    summary["fabric_eigenvalue_min"] = stats.fabric_min;
    summary["fabric_eigenvalue_max"] = stats.fabric_max;
    summary["spheres_outside"] = stats.spheres_outside;
    if (packing.container.shape == "line")
      summary["note"] = "a line of n = ceil(L / d) spheres spans (n - 1) d + 2 R, more than the rod's length L, and "
                        "its balls overlap: spheres_outside (the end spheres) and solid_to_rod_volume > 1 are "
                        "expected; the model's mass is the rod's through the particle density";
    if (mass) {
      summary["specimen_mass_g"] = *mass / units::g;
      summary["particle_density_kg_m3"] = packing.particle_density_kg_m3;
    }
    if (o.container == "box" || o.container == "cylinder") {
      summary["relaxation_iterations"] = relax.iterations;
      summary["relaxation_residual"] = relax.residual;
      summary["relaxation_converged"] = relax.converged;
    }
    summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    run.metric("spheres", double(stats.count), "");
    if (packing.container.shape != "line") run.metric("porosity", stats.porosity / units::percent, "%");
    run.metric("coordination", stats.coordination, "");
    run.metric("overlap_mean_ratio", stats.mean_overlap_ratio, "");
    if (mass) run.metric("particle_density", packing.particle_density_kg_m3, "kg/m3");
    run.emit_json(summary, o.out);
  });
}
