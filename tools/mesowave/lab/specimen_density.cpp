#include "mesowave/lab/specimen_density.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesowave/core/check.hpp"

namespace mesowave::lab {
namespace {

double standard_uncertainty(double resolution) { return resolution / std::sqrt(12.0); }

}  // namespace

SpecimenShape parse_specimen_shape(const std::string& name) {
  if (name == "cube") return SpecimenShape::Cube;
  if (name == "prism") return SpecimenShape::Prism;
  if (name == "cylinder") return SpecimenShape::Cylinder;
  throw InputError("shape '" + name + "' is not one of cube, prism, cylinder");
}

std::string to_string(SpecimenShape shape) {
  switch (shape) {
    case SpecimenShape::Cube: return "cube";
    case SpecimenShape::Prism: return "prism";
    case SpecimenShape::Cylinder: return "cylinder";
  }
  return "?";
}

double specimen_volume(const SpecimenGeometry& g) {
  switch (g.shape) {
    case SpecimenShape::Cube:
      require_positive("side", g.side_m, "m");
      return g.side_m * g.side_m * g.side_m;
    case SpecimenShape::Prism:
      require_positive("length", g.length_m, "m");
      require_positive("width", g.width_m, "m");
      require_positive("height", g.height_m, "m");
      return g.length_m * g.width_m * g.height_m;
    case SpecimenShape::Cylinder:
      require_positive("diameter", g.diameter_m, "m");
      require_positive("height", g.height_m, "m");
      return std::numbers::pi / 4.0 * g.diameter_m * g.diameter_m * g.height_m;
  }
  return 0;
}

SpecimenDensity specimen_density(double mass_kg, const SpecimenGeometry& g, const MeasurementResolution& res) {
  require_positive("mass", mass_kg, "kg");
  if (!std::isfinite(res.mass_kg) || res.mass_kg < 0)
    throw InputError("mass resolution (" + format_quantity(res.mass_kg, "kg") + ") must be >= 0");
  if (!std::isfinite(res.length_m) || res.length_m < 0)
    throw InputError("length resolution (" + format_quantity(res.length_m, "m") + ") must be >= 0");

  SpecimenDensity d;
  d.volume_m3 = specimen_volume(g);
  d.density_kg_m3 = mass_kg / d.volume_m3;

  const double u_l = standard_uncertainty(res.length_m);
  auto term = [&](double power, double length) { return power * u_l / length; };
  double rel2 = std::pow(standard_uncertainty(res.mass_kg) / mass_kg, 2);
  switch (g.shape) {
    case SpecimenShape::Cube: rel2 += std::pow(term(3, g.side_m), 2); break;
    case SpecimenShape::Prism:
      rel2 += std::pow(term(1, g.length_m), 2) + std::pow(term(1, g.width_m), 2) + std::pow(term(1, g.height_m), 2);
      break;
    case SpecimenShape::Cylinder: rel2 += std::pow(term(2, g.diameter_m), 2) + std::pow(term(1, g.height_m), 2); break;
  }
  d.u_density_kg_m3 = d.density_kg_m3 * std::sqrt(rel2);
  return d;
}

DensitySummary summarize_densities(std::span<const SpecimenDensity> specimens) {
  if (specimens.empty()) throw InputError("no specimens to summarise");
  DensitySummary s;
  s.count = specimens.size();
  s.min_kg_m3 = s.max_kg_m3 = specimens.front().density_kg_m3;
  for (const auto& d : specimens) {
    s.mean_kg_m3 += d.density_kg_m3;
    s.u_resolution_kg_m3 += d.u_density_kg_m3;
    s.min_kg_m3 = std::min(s.min_kg_m3, d.density_kg_m3);
    s.max_kg_m3 = std::max(s.max_kg_m3, d.density_kg_m3);
  }
  const double n = double(s.count);
  s.mean_kg_m3 /= n;
  s.u_resolution_kg_m3 /= n;
  if (s.count > 1) {
    double ss = 0;
    for (const auto& d : specimens) ss += std::pow(d.density_kg_m3 - s.mean_kg_m3, 2);
    s.std_kg_m3 = std::sqrt(ss / (n - 1));
    s.sem_kg_m3 = s.std_kg_m3 / std::sqrt(n);
  }
  s.u_mean_kg_m3 = std::hypot(s.sem_kg_m3, s.u_resolution_kg_m3);
  return s;
}

}  // namespace mesowave::lab
