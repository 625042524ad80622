#pragma once
// The elastic part of a virtual compression test as one linear static problem
// (issue 17 item 2): mw-calibrate's elastic trials load the linearised bonded
// network (linear_bonded_network.hpp) with unbreakable bonds to sigma_max / 3
// and read the secant between two stress levels; on that network the response
// is linear, so equilibrium can be solved for instead of stepped to.
//
//   K u = f_w(u)                               u: (d, theta) of every sphere, 6 DOFs each
//
// K is assembled bond by bond from the dynamic law itself (linear_bond_response,
// the function the kernel runs): the law is linear in (d_i, theta_i, d_j,
// theta_j), so its response to the twelve unit displacements of a bond's two
// spheres are the twelve columns of the bond's 12 x 12 block (K u = minus the
// contact forces one dynamic step computes at u). K is unsymmetric (the lever
// arms r - u0/2 of the torques against the radii r in the shear strain, and
// a0 != 1), so the solver is Eigen's BiCGSTAB with a diagonal (Jacobi)
// preconditioner on a row-major matrix (its products run on the OpenMP threads,
// one row per thread: the same bits for any count). A direct SparseLU is out of
// reach on the 50 mm cube (225,480 DOFs, 14.8 million nonzeros in 3-D: the fill
// of its factors); an incomplete LU and hypre's algebraic multigrid
// (boomeramg.hpp, on the 50 mm cube 76 iterations for the two solves against
// Jacobi's 1,325) are options (StaticElasticOptions).
//
// Walls (rigid_wall.hpp) are the dynamic test's one-sided springs k_w = E_dem r
// along the wall normal, frictionless (no tangential term): a candidate sphere
// with penetration p = travel - gap0 - inward u_axis > 0 is pushed with k_w p.
// Which spheres touch is found by an active-set iteration: solve with a set,
// recompute p, repeat until the set is the one the solution says. Within one
// set u is affine in the wall travel delta (u = delta u1 + u0, two solves), so
// the travel that gives a stress level is found exactly, and the set is then
// checked at that travel.
//
// The three rigid-body motions the frictionless walls leave free (translations
// across the load axis, the rotation about it) are removed by fixing three
// DOFs: both transverse displacements of the sphere nearest the centre and one
// of a sphere half a width away; the walls push only along the axis, so these
// supports carry no force (their reaction is the residual, reported).
//
// The stress is the mean of the load sensors' walls' forces over the test's
// area, the strains are read by the scene's own extensometers (their code,
// sampling this static field), so E_glob and nu_glob are the dynamic test's
// definitions: the secant between the two levels of a linear response.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/SparseCore>

#include "mesowave/dem/calibration/boomeramg.hpp"
#include "mesowave/dem/calibration/uniaxial_analysis.hpp"
#include "mesowave/dem/packing/packing.hpp"
#include "mesowave/dem/scene/scene.hpp"

namespace mesowave::dem {

class SphereSystem;

/// K of the linearised network, 6 DOFs per sphere (d_x, d_y, d_z, theta_x,
/// theta_y, theta_z; model numbering): K u = minus the bonds' generalized forces at u.
Eigen::SparseMatrix<double, Eigen::RowMajor> linear_network_stiffness(const SphereSystem& system);

/// The names StaticElasticOptions::preconditioner takes (jacobi, ilut, amg): the tools' option checks.
std::vector<std::string> static_preconditioners();

struct StaticElasticOptions {
  double tolerance = 1e-10;        ///< BiCGSTAB's relative residual |r| / |b|
  int max_iterations = 100000;     ///< per solve
  int max_active_set_rounds = 30;  ///< per stress level
  /// jacobi (Eigen::DiagonalPreconditioner) | ilut (Eigen::IncompleteLUT on the system scaled to a
  /// unit diagonal): on the 50 mm cube ILUT(1e-2, 1) needs 143 iterations against Jacobi's 676 but its
  /// factorisation costs most of what that saves (docs/calibration.md, "Elastic trials as a static solve").
  /// amg: hypre's BoomerAMG (boomeramg.hpp), one V-cycle per application, on the scaled system as 6
  /// functions per sphere: 76 iterations there, half the Jacobi solve's time but twice the stepped trial's.
  std::string preconditioner = "jacobi";
  double ilut_droptol = 1e-2;
  int ilut_fill = 1;
  BoomerAmgSettings amg;
};

/// One stress level of the static test.
struct StaticLevel {
  double sigma_Pa = 0;        ///< the level (the mean wall force / area)
  double travel_m = 0;        ///< the moving walls' travel that gives it
  double axial_strain = 0;    ///< compression positive (as the dynamic analysis)
  double lateral_strain = 0;  ///< the lateral extensometers' mean (0 without them)
  std::size_t wall_contacts = 0;
  int active_set_rounds = 0;
};

struct StaticElasticResult {
  std::size_t spheres = 0, bonds = 0, dofs = 0, nonzeros = 0;
  std::string solver;  ///< "BiCGSTAB (Jacobi)", "BiCGSTAB (ILUT)" or "BiCGSTAB (BoomerAMG)"
  StaticLevel level_b, level_a;
  double E_glob_Pa = 0;
  std::optional<double> nu_glob;
  int solves = 0, iterations_max = 0, iterations_total = 0;
  double residual_max = 0;           ///< the largest relative residual of a solve
  double support_force_ratio = 0;    ///< the fixed DOFs' largest reaction / the wall force
  double setup_s = 0, assemble_s = 0, solve_s = 0, wall_s = 0;
  double preconditioner_s = 0;  ///< of solve_s: building the ILUT factors or the AMG hierarchy (all active sets)
  /// The two levels as a test result (time_s is the solve index 0, 1, 2 from the
  /// unloaded state), for the summary and curves a dynamic run writes.
  UniaxialTestResult test;
};

/// The scene's compression test solved statically on the linearised network
/// (the scene's [model] choice is overridden). InputError when the scene has no
/// compression [test], its modulus levels are not absolute stresses (a static
/// linear test has no peak to take fractions of: --modulus-levels-MPa), it has
/// no wall that moves, or a solve or the active set does not converge.
StaticElasticResult static_compression_test(const Scene& scene, const Packing& packing,
                                            const StaticElasticOptions& options = {});

}  // namespace mesowave::dem
