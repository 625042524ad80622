#pragma once
// The static three-point bending test of the shock paper's Section 4.1: the
// notched plain-concrete beam of Koermeling and Reinhardt (1983) - E = 20 000
// N/mm2, nu = 0.2, f_t = 2.4 N/mm2, G_f = 113 N/m; span 450 mm, depth 100 mm,
// notch 50 mm, thickness 100 mm (the geometry as Rots 1988 and Wells and Sluys
// 2001 model it: lab-data/shock-concrete/three-point-bending.toml) - in plane
// stress under displacement control of the mid-span deflection.
//
// The model: the beam between its supports (length = span, simply supported at
// the bottom corners: u_y = 0 at both, u_x = 0 at the left), loaded through two
// points of the top face load_width_m apart, on either side of mid-span, both
// moved down by the deflection (the edges of a narrow loading plate: the crack
// may then reach the top face between them without cutting a load point off). The notch
// is a traction-free crack on the mid-span line (or at notch_x_m: an eccentric notch, the load
// still at mid-span); the crack grows from its tip
// in segments of one node spacing, vertical as the paper prescribes (the
// principal directions at mid-span are too sensitive to follow), whenever the
// St. Venant criterion holds just ahead of the tip, up to half a segment below
// the top face (a crack through the depth leaves the halves a zero-load
// mechanism that Newton finds: see the .cpp); after each extension the shape
// functions change and the step is solved again. The load is the sum of
// the two load points' reactions. Nodes: a regular grid whose mid-span line is
// a line of cell centres (an odd number of cells along the span), so no node
// lies on the crack.
//
// The complete curve (ligament_interface): the growing crack cannot cut
// through. When its last segment reaches the top face, the right half is
// held in x only by the cohesive tractions (its roller and load point fix
// u_y alone); the shape functions just cut give the new segment's points an
// opening of the order of a spacing times the strain, above w_initial (on the
// 10 mm grid 5 to 30 w_initial, the point next to the top face included), so
// they start on the softening branch, the x-translation of the half has a
// negative tangent (-4.6e5 N/m) and Newton goes to the other equilibrium at
// this deflection - every point past w_max, zero load (the dissipated energy
// jumps to 564 N mm while the work done is 353). Instead, as Rots
// (1988) places interface elements on the known path, the whole ligament is
// cohesive from the start: every point on the stiff initial secant
// f_t / w_initial (the traction reaching f_t starts the crack there, in place
// of St. Venant, the same for the uniaxial stress at the ligament), the
// closed-face penalty carrying the compression zone, no change of the shape
// functions during the run. The halves then turn about the quadrature point
// nearest the top face: it stays closed, so it never dissipates, and the load
// falls to zero once the point below it passes w_max. Work of fracture =
// G_f x ligament x thickness x (1 - that point's share of the ligament, its
// Gauss weight: 3.5 % with 4 points on 10 mm segments) x (1 - the initial
// secant's triangle, f_t w_initial / 2 of G_f); tests/efg/three_point_bending_test.cpp.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/efg/crack.hpp"
#include "mesowave/efg/crack_growth.hpp"
#include "mesowave/efg/geometry.hpp"
#include "mesowave/efg/mls.hpp"
#include "mesowave/efg/nonlinear_solver.hpp"
#include "mesowave/efg/vtk_output.hpp"

namespace mesowave::efg {

struct ThreePointBendingOptions {
  // geometry [m]
  double span_m = 0.450, depth_m = 0.100, notch_m = 0.050, thickness_m = 0.100;
  /// Where the notch opens on the bottom face, from the left support (unset: mid-span, under the load, as the
  /// beam was tested). The notch and the crack growing from it are vertical at this x; the load stays at mid-span.
  /// It must keep a quarter spacing off the node columns (a node on the crack line is hidden from both sides).
  std::optional<double> notch_x_m;
  // material (Section 4.1)
  double E_Pa = 20e9, nu = 0.20, f_t_Pa = 2.4e6, G_f_J_m2 = 113;
  /// Compressive strength (CohesiveParameters::f_c_Pa: the bilinear law's beta_t by Eq. (22); unset: below 30 MPa).
  std::optional<double> f_c_Pa;
  std::string law = "exponential";             ///< cohesive_law.hpp registry name
  std::map<std::string, double> law_keys;      ///< the law's own keys given (alpha; alpha_t), the rest its fallbacks
  // discretisation
  double spacing_m = 0.005;                    ///< target node spacing (the cells along the span: odd, so the nearest odd count)
  int gauss = 2;                               ///< per direction per cell (the paper's 2)
  double support_scale = 2.0;                  ///< support radius over the spacing (2: about 12 nodes in a support, the paper's 4 to 10 near faces and corners)
  CrackWeightMethod crack_method = CrackWeightMethod::visibility;
  int cohesive_gauss = 4;                      ///< Gauss points per cohesive segment
  /// Vertical, as the paper prescribes for this beam, or orthogonal to the largest principal strain.
  GrowthDirectionRule growth = GrowthDirectionRule::prescribed;
  // loading
  /// Distance between the two load points on the top face (a loading plate's edges): fixed, not tied to the
  /// spacing, so that grids of any spacing (and the FEM) solve the same problem - a point load's displacement
  /// in 2D grows without bound as the grid is refined (log singularity).
  double load_width_m = 0.010;
  double max_deflection_m = 1.0e-3;
  int steps = 100;                             ///< deflection steps
  /// Each step this times the one before (1: equal steps): small steps through the peak, long ones in the tail.
  double step_ratio = 1.0;
  NewtonOptions newton{};
  /// The whole ligament a cohesive interface from the start, instead of St. Venant growth (the header comment):
  /// the complete curve, to the separated beam, and its work of fracture.
  bool ligament_interface = false;
  /// Stop early when the crack tip has reached its highest point (half a segment below the top face, see the
  /// .cpp) and the load has fallen below this fraction of the peak.
  double stop_load_fraction = 0.005;
  /// Keep the nodes' displacement u^h and stress and the crack (opening, traction, damage) at every curve point
  /// (ParaView snapshots of the run).
  bool node_snapshots = false;
  /// InputError naming the value: sizes <= 0, a notch not inside the depth, a notch that leaves the body
  /// (require_crack_inside: only its mouth may touch the bottom face) or lies on a node column, nu outside
  /// (-1, 0.5), f_t or G_f <= 0, steps < 1, spacing above the ligament.
  void validate() const;
  /// The notch's x: notch_x_m, or mid-span.
  double notch_position_m() const { return notch_x_m.value_or(0.5 * span_m); }
  /// The notch as the user places it: from its mouth on the bottom face to its tip.
  std::vector<Vec2> notch_polyline() const { return {Vec2(notch_position_m(), 0), Vec2(notch_position_m(), notch_m)}; }
  /// Background cells along the span: round(span / spacing), made odd (mid-span a line of cell centres).
  int cells_along_span() const;
};

struct CurvePoint {
  double deflection_m = 0, load_N = 0;
  int iterations = 0;
  double crack_tip_y_m = 0;       ///< height of the crack tip above the bottom face
  double dissipated_J = 0;        ///< energy dissipated in the cohesive zone so far
};

struct ThreePointBendingResult {
  std::vector<CurvePoint> curve;          ///< from (0, 0)
  std::vector<Vec2> crack_path;           ///< the polyline: notch mouth, notch tip, grown points
  double peak_load_N = 0, deflection_at_peak_m = 0;
  double work_of_fracture_J = 0;          ///< area under the curve (trapezoids)
  double dissipated_J = 0;                ///< the cohesive zone's own account at the end
  double stored_J = 0;                    ///< elastic energy left at the end (continuum and faces)
  double final_load_N = 0, final_deflection_m = 0;
  double elastic_stiffness_N_per_m = 0;   ///< the notched beam before any crack growth (a linear solve)
  std::map<std::string, double> law_parameters;  ///< CohesiveLaw::parameters() of the law the run used
  double w_max_m = 0;                     ///< its critical opening, Eq. (20) / (23)
  bool completed = false;                 ///< every step converged
  std::string stop_reason;
  // cost
  std::size_t nodes = 0, gauss_points = 0, dofs = 0, cohesive_points = 0;
  int newton_iterations = 0, re_solves = 0, line_search_cuts = 0;
  double wall_s = 0;
  std::vector<StepReport> steps;          ///< per accepted step
  std::vector<NodeSnapshot> node_steps;   ///< per curve point, when options.node_snapshots
  /// Per curve point, when options.node_snapshots: the notch (one traction-free segment, its opening at half
  /// its depth, damage 1) and the cohesive crack as one polyline cut into a piece per cohesive Gauss point (the
  /// share of its segment the point's weight stands for), each piece with that point's opening, traction and damage.
  std::vector<CrackSnapshot> crack_steps;
};

ThreePointBendingResult run_three_point_bending(const ThreePointBendingOptions& options);

}  // namespace mesowave::efg
