#include "mesowave/dem/scene/model_choice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/dem/scene/plugins.hpp"
#include "mesowave/dem/loading/sphere_selection.hpp"
#include "mesowave/dem/parallel/domain.hpp"

namespace mesowave::dem {

std::optional<Vec3> line_axis(const SpherePart& part) {
  if (part.total() < 2) return std::nullopt;
  const Vec3 ca = part.centre_of(sphere_at_end(part, false)), cb = part.centre_of(sphere_at_end(part, true));
  const Vec3 d = cb - ca;
  const double length = norm(d);
  if (!(length > 0)) return std::nullopt;
  const Vec3 e = (1.0 / length) * d;
  const double tolerance = 1e-6 * part.radius_min();
  const SphereSet& s = part.spheres();
  double off = 0;  // 1 if an own sphere is off the line
  for (std::size_t k = 0; k < part.own_count() && off == 0; ++k) {
    const Vec3 r = s.centre_m[k] - ca;
    if (norm(r - dot(r, e) * e) > tolerance) off = 1;
  }
  if (part.domain()) off = part.domain()->max(off);
  if (off != 0) return std::nullopt;
  return e;
}

double estimated_force_ratio(const ResolvedLoad& load, const SpherePart& s, const BondNetwork& bonds,
                             const CohesiveFrictionalMaterial& m, double duration_s) {
  double weakest = std::numeric_limits<double>::infinity(), stiffest = 0;
  std::vector<std::size_t> loaded;  // this rank's own loaded spheres: another rank takes its own
  for (std::size_t k : load.spheres)
    if (bonds.lists_all_of(k)) loaded.push_back(k);
  std::sort(loaded.begin(), loaded.end());
  const auto is_loaded = [&](std::size_t k) { return std::binary_search(loaded.begin(), loaded.end(), k); };
  for (std::size_t b = 0; b < bonds.size() && !loaded.empty(); ++b) {
    if (is_loaded(bonds.first[b]) || is_loaded(bonds.second[b])) {
      const double ri = s.radius(bonds.first[b]), rj = s.radius(bonds.second[b]);
      const double kn = normal_stiffness(m, ri, rj);
      const double strength = m.breakable()
                                  ? std::min(tensile_bond_strength(m, ri, rj), shear_bond_strength(m, ri, rj))
                                  : kn * std::min(ri, rj);
      weakest = std::min(weakest, strength);
      stiffest = std::max(stiffest, kn);
    }
  }
  if (Domain* domain = s.domain()) weakest = -domain->max(-weakest), stiffest = domain->max(stiffest);  // exact in any order
  if (!std::isfinite(weakest)) return std::numeric_limits<double>::infinity();  // a loaded sphere without bonds
  const ActuatorKind& kind = actuator_kinds().get(load.spec->kind, "actuator " + load.spec->name);
  return kind.peak_sphere_force(*load.spec, load.spheres.size(), stiffest, duration_s) / weakest;
}

ModelChoice choose_model(const std::string& requested, const Scene& scene, const SpherePart& s,
                         const BondNetwork& bonds, const std::vector<ResolvedLoad>& loads) {
  ModelChoice c;
  for (const auto& load : loads)
    c.estimated_force_ratio = std::max(c.estimated_force_ratio, estimated_force_ratio(load, s, bonds, scene.material, scene.duration_s));
  const auto axis = line_axis(s);

  const ContactLaw& law = contact_laws().get(scene.contact_law, "[material].law");
  const auto offers = [&](const std::string& model) {
    return std::find(law.models.begin(), law.models.end(), model) != law.models.end();
  };
  // The law's own rule first (a shortcut it does not offer, or one its values rule out).
  const auto law_obstacle = [&](const std::string& model) {
    if (!offers(model)) return "the " + law.name + " law has no " + model + " model";
    return law.shortcut_obstacle(model, scene);
  };

  std::string chain_obstacle = law_obstacle("chain");
  if (chain_obstacle.empty() && !axis) chain_obstacle = "the sphere centres are not on one line";
  else if (chain_obstacle.empty()) {
    for (const auto& load : loads)
      if (std::abs(std::abs(dot(load.direction, *axis)) - 1.0) > 1e-9)
        chain_obstacle = "actuator " + load.spec->name + " does not load along the line";
    const bool along_coordinate_axis = std::max({std::abs(axis->x), std::abs(axis->y), std::abs(axis->z)}) > 1 - 1e-12;
    if (chain_obstacle.empty() && scene.material.damping != 0 && !along_coordinate_axis)
      chain_obstacle = "with damping the line must run along x, y or z (Yade damps per global component)";
  }

  if (requested != "auto") {
    if (requested == "chain" && !chain_obstacle.empty())
      throw InputError("--model chain is not possible: " + chain_obstacle);
    if (!offers(requested)) throw InputError("--model " + requested + " is not possible: " + law_obstacle(requested));
    c.model = requested;
    c.reason = "forced (model = " + requested + ")";
    return c;
  }
  if (chain_obstacle.empty()) {
    c.model = "chain";
    c.reason = "all " + std::to_string(s.total()) +
               " spheres lie on one line and every load acts along it: the full law keeps transverse motion, shear "
               "forces and rotations exactly zero and its normal force is linear, so only the axial degree of freedom "
               "is integrated (breakage is checked after the run)";
    return c;
  }
  const double bound = scene.linear_validity_bound;
  const std::string linear_obstacle = law_obstacle("linear");
  if (linear_obstacle.empty() && c.estimated_force_ratio < bound) {
    c.model = "linear";
    c.reason = "estimated peak bond force / strength " + format_number(c.estimated_force_ratio) +
               " is below the validity bound " + format_number(bound) +
               ": bonds stay far from breakage and friction, so the linearised bonded network is used (" +
               chain_obstacle + " for the chain; the measured peak ratio is checked after the run)";
    return c;
  }
  c.model = "full";
  c.reason = linear_obstacle.empty()
                 ? "estimated peak bond force / strength " + format_number(c.estimated_force_ratio) +
                       " reaches the linear validity bound " + format_number(bound) +
                       ": full cohesive-frictional law with contact detection"
                 : "full " + law.name + " law with contact detection (" + linear_obstacle + "; " + chain_obstacle +
                       " for the chain)";
  return c;
}

}  // namespace mesowave::dem
