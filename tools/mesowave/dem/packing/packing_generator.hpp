#pragma once
// Packings for the DEM models: dense random packings of spheres in a box or a
// cylinder at a target porosity, and the line of spheres of the rod model.
//
// Porosity (concrete paper, Section 4.2): p = 1 - sum(V_sphere) / V_container,
// counted as if the spheres did not overlap. p = 7 % is far denser than a
// random close packing (p ~ 36 %), so it is reached with overlaps, which the
// bonds later keep force-free (Eq. 1, u_0).
//
// How a packing is made (mesowave's method; Yade's own generator differs):
//  1. diameters are drawn from the size distribution until their volumes add
//     up to (1 - p) V_container (the count follows from the volume);
//  2. centres are placed uniformly at random in the container, each at least
//     its radius from every wall (so every sphere lies wholly inside);
//  3. the overlap energy E = sum_pairs 1/2 xi^2 + Q/4 xi^4, with
//     xi = delta_ij / r_min,ij, delta_ij = r_i + r_j - |x_i - x_j| > 0 and
//     r_min,ij the smaller radius, is minimised over the centres (FIRE,
//     Bitzek et al. 2006, with the FIRE 2.0 refinements of Guenole et al.
//     2020), the walls being hard constraints, until every sphere is in
//     balance. For wide size ranges (d_max > 1.5 d_min) the radii first grow
//     together from a solid fraction of 0.5 to 1 - p in steps, so that small
//     spheres settle between large ones. The quartic term (Q = 3 by default)
//     makes deep overlaps dear, so the overlaps spread evenly and no sphere
//     ends up buried in another.
// On the concrete paper's cube (50 mm, p = 7 %, d = 1.6-2.0 mm) this gives
// about 37,600 spheres and 214,000-215,000 bonds at C_f = 1.1 (Yade: 37,605
// and 213,501). Random centres make the structure disordered, statistically
// homogeneous and isotropic; the layer next to the walls is less dense,
// because no sphere may cross a wall (PackingStats::core_porosity).
// Deterministic for a given seed: same bits for any number of threads.
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>

#include "mesowave/dem/packing/packing.hpp"
#include "mesowave/dem/packing/size_distribution.hpp"

namespace mesowave::dem {

/// A box from its lower and upper corners (m).
Container box_container(const std::array<double, 3>& lower_m, const std::array<double, 3>& upper_m);
/// A cylinder with its axis parallel to z through (axis_x, axis_y), from z0 to
/// z1; stored as its bounding box (lower/upper corners) and its radius.
Container cylinder_container(double radius_m, double z0_m, double z1_m, double axis_x_m = 0, double axis_y_m = 0);
/// The rod of the line model: a cylinder of `rod_radius_m` along z from z0 to z1, shape "line".
Container rod_container(double rod_radius_m, double z0_m, double z1_m);
/// Box: product of the sides; cylinder and line (rod): pi R^2 h.
double container_volume(const Container& container);
/// InputError unless the container is well formed (positive sizes, a
/// cylinder's bounding box square in x-y and 2R wide, a known shape).
void check_container(const Container& container);

struct PackingOptions {
  double porosity = 0.07;  ///< target, 1 - sum(V_sphere)/V_container, in (0, 1)
  SizeDistribution sizes = SizeDistribution::uniform(1.6e-3, 2.0e-3);
  std::uint64_t seed = 1;
  /// Stop when the largest net force on a sphere is below this fraction of
  /// the mean contact force (the overlaps are then balanced to about this
  /// relative accuracy).
  double force_tolerance = 1e-3;
  std::size_t max_iterations = 100000;
  /// Q of the overlap energy 1/2 xi^2 + Q/4 xi^4 (0: purely harmonic; larger
  /// values even out the overlaps at the cost of iterations).
  double overlap_stiffening = 3;
  /// Radius growth before the final relaxation: the solid fraction rises from
  /// min(0.5, 1 - p) to 1 - p in this many steps (0: relax at full size from
  /// the random start), each relaxed for at most this many iterations.
  /// -1 (default): 10 steps when d_max > 1.5 d_min, where small spheres would
  /// otherwise end up buried, else none.
  int growth_stages = -1;
  std::size_t growth_stage_iterations = 200;
  /// Loops run on OpenMP threads from this many spheres on (serial below:
  /// synchronisation would cost more than it saves). The result does not
  /// depend on it.
  std::size_t parallel_from = 4096;
  /// Called now and then with (iteration, relative residual force).
  std::function<void(std::size_t, double)> progress;
};

struct PackingRun {
  std::size_t iterations = 0;
  std::size_t neighbour_rebuilds = 0;
  double residual = 0;  ///< final max net force / mean contact force
  bool converged = false;
};

/// A random packing in a box or cylinder. InputError for a bad container,
/// porosity outside (0, 1), a container too small for the largest sphere,
/// a porosity leaving no sphere, or one that can only be reached by burying
/// spheres (an overlap above the smaller radius after relaxation).
Packing generate_packing(const Container& container, const PackingOptions& options, PackingRun* run = nullptr);

/// The rod paper's line of spheres (rod paper, Section 3): spheres of radius R
/// at centre spacing d on the axis of a rod of length L, n = ceil(L/d) of them
/// (which reproduces the paper's Table 1 counts), centred on the rod.
struct RodLine {
  double sphere_radius_m = 5.1e-3;
  double spacing_m = 1.03 * 5.1e-3;
  double length_m = 1.0;
  double rod_radius_m = 5.1e-3;  ///< the rod the line stands for (its volume gives the mass)
};
/// n = ceil(L/d), with L/d within 1e-9 of an integer counted as that integer.
std::size_t rod_sphere_count(double length_m, double spacing_m);
/// Spheres along z, centres at z_k = (L - (n-1) d)/2 + k d; container "line".
Packing line_of_spheres(const RodLine& line);

}  // namespace mesowave::dem
