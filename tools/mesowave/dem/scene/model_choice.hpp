#pragma once
// Model only what the scene needs (docs/models.md, "Three models"). The rules, in order:
//  1. `--model` (or the scene's [model] choice) forces a model;
//  2. chain: every centre on one line and every load along it (and, with
//     damping, the line along x, y or z, where Yade's per-component damping is
//     the axial one): the full law keeps transverse motion exactly zero;
//  3. linear: the estimated peak bond force / strength of the loading is below
//     the scene's validity bound (1e-3 by default): bonds stay far from
//     breakage and friction, the linearisation error is of the order of the
//     strain (~1e-6 for concrete at that bound);
//  4. full: everything else.
// After the run the simulation checks the measured peak ratio against the
// bound for the linear model (and against 1, no breakage, for the chain).
#include <optional>
#include <string>
#include <vector>

#include "mesowave/dem/contact/bond_network.hpp"
#include "mesowave/dem/scene/scene.hpp"
#include "mesowave/dem/engine/sphere_part.hpp"

namespace mesowave::dem {

struct ModelChoice {
  std::string model;   ///< full | linear | chain
  std::string reason;  ///< one sentence a user can check
  double estimated_force_ratio = 0;
};

/// Unit vector along a line of spheres (first to last sphere along the
/// longest extent) if every centre lies within 1e-6 of the smallest radius
/// from that line; nothing otherwise (or for fewer than two spheres).
std::optional<Vec3> line_axis(const SpherePart& spheres);

/// What an actuator loads, resolved to spheres.
struct ResolvedLoad {
  const ActuatorSpec* spec = nullptr;
  std::vector<std::size_t> spheres;
  Vec3 direction;
};

/// Estimated peak bond force / strength of one load: the per-sphere force
/// (force actuators: |amplitude| / spheres; displacement actuators: stiffest
/// K_n there times |amplitude|, or times |velocity| x duration for a moving
/// platen or wall) over the weakest bond at those spheres
/// (min(T, C) R^2; K_n R, a strain of one, when the bonds never break).
/// Of a rank's part of the spheres and the network (collective), each rank takes the loaded
/// spheres whose bonds it lists, and the weakest and stiffest come from every rank (exact).
double estimated_force_ratio(const ResolvedLoad& load, const SpherePart& spheres, const BondNetwork& bonds,
                             const CohesiveFrictionalMaterial& material, double duration_s);

/// `requested`: auto | full | linear | chain. InputError for chain on a
/// packing that is not a line. Of a part: as estimated_force_ratio.
ModelChoice choose_model(const std::string& requested, const Scene& scene, const SpherePart& spheres,
                         const BondNetwork& bonds, const std::vector<ResolvedLoad>& loads);

}  // namespace mesowave::dem
