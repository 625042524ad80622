#include "mesowave/dem/packing/packing_request.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/dem/packing/packing_generator.hpp"
#include "mesowave/dem/packing/packing_import.hpp"
#include "mesowave/dem/packing/size_distribution.hpp"
#include "mesowave/experiment/experiment.hpp"

namespace mesowave::dem {
namespace {

double need(const std::optional<double>& value, const std::string& option, const std::string& why, const char* unit) {
  if (!value) throw InputError(why + " needs " + option);
  return require_positive(option, *value, unit);
}

std::array<double, 3> corner_mm(const std::vector<double>& v, const std::string& option) {
  if (v.size() != 3) throw InputError(option + " takes three values (x y z in mm)");
  for (double c : v) require_finite(option, c, "mm");
  return {v[0] * units::mm, v[1] * units::mm, v[2] * units::mm};
}

Container container_from(const PackingRequest& o) {
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
    return box_container({0, 0, 0}, size);
  }
  const double diameter = need(o.diameter_mm, "--diameter-mm", "a cylinder", "mm") * units::mm;
  const double height = need(o.height_mm, "--height-mm", "a cylinder", "mm") * units::mm;
  return cylinder_container(diameter / 2, 0, height, diameter / 2, diameter / 2);
}

SizeDistribution sizes_from(const PackingRequest& o, std::vector<std::filesystem::path>& inputs) {
  std::optional<double> lo, hi;
  if (o.d_min_mm) lo = require_positive("--d-min-mm", *o.d_min_mm, "mm") * units::mm;
  if (o.d_max_mm) hi = require_positive("--d-max-mm", *o.d_max_mm, "mm") * units::mm;
  if (lo && hi && *lo > *hi)
    throw InputError("--d-min-mm (" + format_quantity(*o.d_min_mm, "mm") + ") exceeds --d-max-mm (" +
                     format_quantity(*o.d_max_mm, "mm") + ")");
  if (!o.sieve_curve.empty()) {
    inputs.push_back(o.sieve_curve);
    return SizeDistribution::sieve(read_sieve_curve(o.sieve_curve), lo, hi);
  }
  if (!lo || !hi) throw InputError("give --d-min-mm and --d-max-mm (uniform diameters) or --sieve-curve FILE");
  return SizeDistribution::uniform(*lo, *hi);
}

Packing imported(const PackingRequest& o, std::vector<std::filesystem::path>& inputs) {
  if (o.input.empty()) throw InputError("import needs the file to read: mw-pack import FILE");
  inputs.push_back(o.input);
  std::string format = o.import_format;
  if (format == "auto") format = o.input.extension() == ".csv" ? "csv" : "yade";
  auto p = format == "csv" ? read_packing_csv(o.input) : read_yade_text(o.input);
  if (o.lower_mm.empty() != o.upper_mm.empty()) throw InputError("give both --lower-mm and --upper-mm, or neither");
  p.container = o.lower_mm.empty() ? bounding_box(p)
                                   : box_container(corner_mm(o.lower_mm, "--lower-mm"), corner_mm(o.upper_mm, "--upper-mm"));
  return p;
}

// The request with the experiment's rod where an option is not given.
PackingRequest with_experiment(const PackingRequest& request) {
  if (request.experiment.empty()) return request;
  if (request.container != "line")
    throw InputError("--experiment gives a line its rod; a " + request.container + " takes its sizes as options");
  const experiment::Rod rod = experiment::rod_of(experiment::read_experiment_file(request.experiment));
  PackingRequest o = request;
  if (!o.sphere_radius_mm) o.sphere_radius_mm = rod.radius_m / units::mm;
  if (!o.rod_diameter_mm) o.rod_diameter_mm = 2 * rod.radius_m / units::mm;
  if (!o.length_mm) o.length_mm = rod.length_m / units::mm;
  if (!o.density_kg_m3 && !o.specimen_mass_g) o.density_kg_m3 = rod.density_kg_m3;
  return o;
}

Packing rod_line(const PackingRequest& o) {
  RodLine line;
  line.sphere_radius_m = need(o.sphere_radius_mm, "--sphere-radius-mm", "a line", "mm") * units::mm;
  if (o.spacing_mm.has_value() == o.spacing_R.has_value())
    throw InputError("a line needs exactly one of --spacing-mm and --spacing-R");
  line.spacing_m = o.spacing_mm ? require_positive("--spacing-mm", *o.spacing_mm, "mm") * units::mm
                                : require_positive("--spacing-R", *o.spacing_R) * line.sphere_radius_m;
  line.length_m = need(o.length_mm, "--length-mm", "a line", "mm") * units::mm;
  line.rod_radius_m = o.rod_diameter_mm ? require_positive("--rod-diameter-mm", *o.rod_diameter_mm, "mm") * units::mm / 2
                                        : line.sphere_radius_m;
  return line_of_spheres(line);
}

// A random packing, relaxed on the threads of the rule in core/threads.hpp.
Packing generated(const PackingRequest& o, PackedSpecimen& out, const std::function<void(double)>& progress,
                  PackingRun& relax) {
  const auto container = container_from(o);
  PackingOptions options;
  if (!o.porosity_pct) throw InputError("a " + o.container + " needs --porosity-pct");
  options.porosity = require_finite("--porosity-pct", *o.porosity_pct, "%") * units::percent;
  if (options.porosity <= 0 || options.porosity >= 1)
    throw InputError("--porosity-pct (" + format_quantity(*o.porosity_pct, "%") + ") must lie strictly between 0 and 100");
  options.sizes = sizes_from(o, out.inputs);
  options.seed = o.seed;
  options.force_tolerance = require_positive("--force-tolerance", o.force_tolerance);
  options.overlap_stiffening = require_in_range("--overlap-stiffening", o.overlap_stiffening, 0, 1000);
  out.threads = use_threads(o.threads);
  // The progress callback runs inside generate_packing, after this block: what it keeps
  // between calls lives here, not in the block (ASan: stack-use-after-scope, make test-sanitize).
  std::optional<double> first;
  double shown = 0;
  if (progress) {
    options.progress = [&, tolerance = options.force_tolerance](std::size_t, double residual) {
      if (!first) first = std::max(residual, tolerance * 10);
      const double done = residual > 0 ? std::log(*first / residual) / std::log(*first / tolerance) : 1.0;
      shown = std::max(shown, std::clamp(done, 0.0, 1.0));
      progress(shown);
    };
  }
  Packing packing = generate_packing(container, options, &relax);
  if (packing.size() < options.parallel_from && out.threads.count > 1) {
    out.threads.count = 1;
    out.threads.reason += ", 1 for " + std::to_string(packing.size()) + " spheres (the relaxation runs on threads from " +
                          std::to_string(options.parallel_from) + " spheres on)";
  }
  out.origin.text = {{"method", "random centres, overlap-energy relaxation (FIRE), mw-pack"},
                     {"seed", std::to_string(o.seed)},
                     {"size_distribution", options.sizes.describe()}};
  if (!o.sieve_curve.empty()) out.origin.text.emplace_back("sieve_curve", o.sieve_curve.string());
  out.origin.numbers = {{"target_porosity", options.porosity},
                        {"force_tolerance", options.force_tolerance},
                        {"overlap_stiffening", options.overlap_stiffening},
                        {"relaxation_iterations", double(relax.iterations)},
                        {"relaxation_residual", relax.residual}};
  auto& s = out.summary;
  s["threads"] = out.threads.count;
  s["threads_reason"] = out.threads.reason;
  s["seed"] = o.seed;
  s["size_distribution"] = options.sizes.describe();
  s["porosity_target_pct"] = *o.porosity_pct;
  return packing;
}

std::vector<double> mm3(const std::array<double, 3>& m) { return {m[0] / units::mm, m[1] / units::mm, m[2] / units::mm}; }

}  // namespace

PackedSpecimen make_packing(const PackingRequest& request, const std::function<void(double)>& relaxation_progress) {
  const PackingRequest o = with_experiment(request);
  require_positive("--detection-factor", o.detection_factor);
  if (o.density_kg_m3 && o.specimen_mass_g) throw InputError("give --density-kg-m3 or --specimen-mass-g, not both");
  if (o.density_kg_m3) require_positive("--density-kg-m3", *o.density_kg_m3, "kg/m3");
  if (o.specimen_mass_g) require_positive("--specimen-mass-g", *o.specimen_mass_g, "g");
  if (!o.input.empty() && o.container != "import") throw InputError("a file argument is only for import");

  PackedSpecimen out;
  if (!o.experiment.empty()) out.inputs.push_back(o.experiment);
  auto& s = out.summary;
  s["packing_file"] = o.packing_file.string();
  s["container"] = o.container;
  out.threads = {1, "no relaxation (a " + o.container + ")"};
  const bool relaxed = o.container == "box" || o.container == "cylinder";
  PackingRun relax;
  if (relaxed) {
    out.packing = generated(o, out, relaxation_progress, relax);
  } else if (o.container == "line") {
    out.packing = rod_line(o);
    const Packing& p = out.packing;
    out.origin.text = {{"method", "line of spheres, n = ceil(L/d), mw-pack"}};
    s["sphere_radius_mm"] = p.radii_m.front() / units::mm;
    s["spacing_mm"] = (p.size() > 1 ? p.centres_m[1][2] - p.centres_m[0][2] : 0.0) / units::mm;
    s["spacing_R"] = o.spacing_R ? *o.spacing_R : *o.spacing_mm / *o.sphere_radius_mm;
    s["length_mm"] = *o.length_mm;
    s["rod_diameter_mm"] = 2 * p.container.radius_m / units::mm;
    s["chain_length_mm"] = (p.centres_m.back()[2] - p.centres_m.front()[2] + 2 * p.radii_m.front()) / units::mm;
  } else if (o.container == "import") {
    out.packing = imported(o, out.inputs);
    out.origin.text = {{"method", "imported by mw-pack"}, {"source_file", o.input.string()}};
  } else {
    throw InputError("container '" + o.container + "' must be box, cylinder, line or import");
  }

  Packing& packing = out.packing;
  const double volume = container_volume(packing.container);
  std::optional<double>& mass = out.specimen_mass_kg;
  if (o.density_kg_m3) mass = specimen_mass(*o.density_kg_m3, packing.container);
  if (o.specimen_mass_g) mass = *o.specimen_mass_g * units::g;
  if (mass) packing.particle_density_kg_m3 = particle_density_for_mass(*mass, packing);

  out.stats = packing_stats(packing, o.detection_factor);
  const PackingStats& st = out.stats;
  s["spheres"] = st.count;
  s["container_lower_mm"] = mm3(packing.container.lower_m);
  s["container_upper_mm"] = mm3(packing.container.upper_m);
  if (packing.container.shape != "box") s["container_radius_mm"] = packing.container.radius_m / units::mm;
  s["container_volume_mm3"] = volume / 1e-9;
  s["solid_volume_mm3"] = st.solid_volume_m3 / 1e-9;
  if (packing.container.shape == "line") {
    s["solid_to_rod_volume"] = st.solid_volume_m3 / volume;  // > 1: spheres overlap and bulge out
  } else {
    s["porosity_pct"] = st.porosity / units::percent;
    if (st.core_porosity) s["core_porosity_pct"] = *st.core_porosity / units::percent;
  }
  s["d_mean_mm"] = st.d_mean_m / units::mm;
  s["d_std_mm"] = st.d_std_m / units::mm;
  s["d_min_mm"] = st.d_min_m / units::mm;
  s["d_max_mm"] = st.d_max_m / units::mm;
  s["contacts"] = st.contacts;
  s["coordination_contacts"] = st.coordination_contacts;
  s["overlap_mean_ratio"] = st.mean_overlap_ratio;
  s["overlap_max_ratio"] = st.max_overlap_ratio;
  s["detection_factor"] = o.detection_factor;
  s["bonds"] = st.bonds;
  s["coordination"] = st.coordination;
  s["fabric_eigenvalue_min"] = st.fabric_min;
  s["fabric_eigenvalue_max"] = st.fabric_max;
  s["spheres_outside"] = st.spheres_outside;
  if (packing.container.shape == "line")
    s["note"] = "a line of n = ceil(L / d) spheres spans (n - 1) d + 2 R, more than the rod's length L, and "
                "its balls overlap: spheres_outside (the end spheres) and solid_to_rod_volume > 1 are "
                "expected; the model's mass is the rod's through the particle density";
  if (mass) {
    s["specimen_mass_g"] = *mass / units::g;
    s["particle_density_kg_m3"] = packing.particle_density_kg_m3;
  }
  if (relaxed) {
    s["relaxation_iterations"] = relax.iterations;
    s["relaxation_residual"] = relax.residual;
    s["relaxation_converged"] = relax.converged;
  }
  return out;
}

}  // namespace mesowave::dem
