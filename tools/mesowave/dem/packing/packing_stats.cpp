#include "mesowave/dem/packing/packing_stats.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesowave/core/check.hpp"
#include "mesowave/dem/engine/neighbour_search.hpp"
#include "mesowave/dem/packing/packing_generator.hpp"

namespace mesowave::dem {

double solid_volume(const Packing& p) {
  double sum = 0;
  for (double r : p.radii_m) sum += r * r * r;
  return 4.0 / 3.0 * std::numbers::pi * sum;
}

double porosity(const Packing& p) { return 1 - solid_volume(p) / container_volume(p.container); }

double particle_density_for_mass(double mass, const Packing& p) {
  require_positive("specimen mass", mass, "kg");
  const double v = solid_volume(p);
  if (!(v > 0)) throw InputError("the packing has no sphere volume to carry the specimen's mass");
  return mass / v;
}

double specimen_mass(double density, const Container& c) {
  require_positive("material density", density, "kg/m3");
  return density * container_volume(c);
}

bool sphere_inside(const Container& c, const std::array<double, 3>& x, double r, double tol) {
  if (x[2] - r < c.lower_m[2] - tol || x[2] + r > c.upper_m[2] + tol) return false;
  if (c.shape == "box") {
    for (int d = 0; d < 2; ++d)
      if (x[d] - r < c.lower_m[d] - tol || x[d] + r > c.upper_m[d] + tol) return false;
    return true;
  }
  const double cx = (c.lower_m[0] + c.upper_m[0]) / 2, cy = (c.lower_m[1] + c.upper_m[1]) / 2;
  return std::hypot(x[0] - cx, x[1] - cy) + r <= c.radius_m + tol;
}

Container bounding_box(const Packing& p) {
  if (p.size() == 0) throw InputError("an empty packing has no bounding box");
  Container c;
  c.shape = "box";
  c.lower_m = {INFINITY, INFINITY, INFINITY};
  c.upper_m = {-INFINITY, -INFINITY, -INFINITY};
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      c.lower_m[d] = std::min(c.lower_m[d], p.centres_m[i][d] - p.radii_m[i]);
      c.upper_m[d] = std::max(c.upper_m[d], p.centres_m[i][d] + p.radii_m[i]);
    }
  return c;
}

PackingStats packing_stats(const Packing& p, double detection_factor) {
  require_positive("detection factor C_f", detection_factor);
  PackingStats s;
  s.count = p.size();
  s.container_volume_m3 = container_volume(p.container);
  s.solid_volume_m3 = solid_volume(p);
  s.porosity = 1 - s.solid_volume_m3 / s.container_volume_m3;
  s.detection_factor = detection_factor;
  if (s.count == 0) return s;

  // Two passes: the mean, then deviations from it (no cancellation for equal sizes).
  double sum = 0;
  s.d_min_m = INFINITY;
  s.d_max_m = 0;
  for (double r : p.radii_m) {
    sum += 2 * r;
    s.d_min_m = std::min(s.d_min_m, 2 * r);
    s.d_max_m = std::max(s.d_max_m, 2 * r);
  }
  const double n = double(s.count);
  s.d_mean_m = sum / n;
  double squares = 0;
  for (double r : p.radii_m) squares += (2 * r - s.d_mean_m) * (2 * r - s.d_mean_m);
  s.d_std_m = s.count > 1 ? std::sqrt(squares / (n - 1)) : 0.0;

  const double scale = std::max({p.container.upper_m[0] - p.container.lower_m[0],
                                 p.container.upper_m[1] - p.container.lower_m[1],
                                 p.container.upper_m[2] - p.container.lower_m[2]});
  for (std::size_t i = 0; i < s.count; ++i)
    if (!sphere_inside(p.container, p.centres_m[i], p.radii_m[i], 1e-9 * scale)) ++s.spheres_outside;

  // Core porosity: the container shrunk by a margin of 2 d_max.
  if (p.container.shape == "box" || p.container.shape == "cylinder") {
    const double margin = 2 * s.d_max_m;
    Container core = p.container;
    bool fits = true;
    for (int d = 0; d < 3; ++d) {
      core.lower_m[d] += margin;
      core.upper_m[d] -= margin;
      fits = fits && core.upper_m[d] - core.lower_m[d] >= margin;  // a core worth counting
    }
    core.radius_m -= margin;
    if (fits && (core.shape == "box" || core.radius_m >= margin / 2)) {
      double v = 0;
      for (std::size_t i = 0; i < s.count; ++i)
        if (sphere_inside(core, p.centres_m[i], 0.0)) v += std::pow(p.radii_m[i], 3);
      s.core_porosity = 1 - 4.0 / 3.0 * std::numbers::pi * v / container_volume(core);
    }
  }

  const auto contacts = find_pairs_within(p.centres_m, p.radii_m, 1.0);
  s.contacts = contacts.size();
  s.coordination_contacts = coordination_number(s.contacts, s.count);
  double overlap_sum = 0;
  for (const auto& c : contacts) {
    const auto& a = p.centres_m[c.i];
    const auto& b = p.centres_m[c.j];
    const double dist = std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    const double ratio = (p.radii_m[c.i] + p.radii_m[c.j] - dist) / std::min(p.radii_m[c.i], p.radii_m[c.j]);
    overlap_sum += ratio;
    s.max_overlap_ratio = std::max(s.max_overlap_ratio, ratio);
  }
  s.mean_overlap_ratio = s.contacts ? overlap_sum / double(s.contacts) : 0.0;

  const auto bonds = find_pairs_within(p.centres_m, p.radii_m, detection_factor);
  s.bonds = bonds.size();
  s.coordination = coordination_number(s.bonds, s.count);
  Eigen::Matrix3d fabric = Eigen::Matrix3d::Zero();
  std::size_t counted = 0;
  for (const auto& b : bonds) {
    Eigen::Vector3d d(p.centres_m[b.j][0] - p.centres_m[b.i][0], p.centres_m[b.j][1] - p.centres_m[b.i][1],
                      p.centres_m[b.j][2] - p.centres_m[b.i][2]);
    const double len = d.norm();
    if (len == 0) continue;
    d /= len;
    fabric += d * d.transpose();
    ++counted;
  }
  if (counted) {
    fabric /= double(counted);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(fabric);
    s.fabric_min = eig.eigenvalues().minCoeff();
    s.fabric_max = eig.eigenvalues().maxCoeff();
  }
  return s;
}

}  // namespace mesowave::dem
