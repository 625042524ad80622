#pragma once
// The crater of a contact-detonated slab (shock paper Section 4.3: "The blasting results in a crater beneath
// the explosive. The concrete underneath the crater is highly compacted. Below this compacted range the
// concrete is damaged by cracks."), measured on the state the run leaves: the EFG run erodes nothing.
//
// Why no erosion. Removing Gauss points (element erosion's analogue) leaves the nodes under the crater with
// supports that hold too few integration points: their rows of the lumped mass and of K lose weight unevenly
// and the MLS moment matrix of the points beside the hole keeps nodes whose mass is gone; removing nodes as
// well changes the shape functions of every point within a support radius (2.5 h), i.e. the field itself.
// The crater is therefore what a blast engineer would find after the test - the material that is no longer
// part of the slab - read off the final state:
//
//  (a) CRUSHED material under the charge: Gauss points whose most compressive volumetric strain passed the
//      crushing strain, |min eps_v| >= eps_crush, joined to the loaded face through crushed points. Default
//      eps_crush: the minimum of the Y-function, Eqs. (25)-(26) (0.0475 for the paper's parameters,
//      hugoniot_Y_minimum): the paper reads its dip as the damage of the micropores ("the gradient of the
//      stress-strain relation becomes smaller") and the rise after it as compaction ("the stiffness is
//      getting higher", Section 3.2); past the minimum the pore structure has collapsed and the material is
//      crushed powder held only by confinement. The same three regimes are in the Holmquist-Johnson-Cook
//      concrete model's equation of state (Holmquist, Johnson and Cook, 14th Int. Symp. on Ballistics, 1993:
//      elastic up to mu_crush, pore compaction, fully dense at mu_lock = 0.1): eps_crush = 0.0475 lies inside
//      that compaction range. The compacted zone of efg/blast_slab (past e_v,th = 0.008) is the larger set:
//      "the concrete underneath the crater is highly compacted".
//  (b) FRAGMENTS cut loose by fully opened cracks: a crack segment is open when every one of its face points
//      has opened past its cohesive law's w_max (w_hist >= w_max: Eqs. (20), (23), the traction gone for good,
//      efg/cohesive_law's history rule; traction-free faces are open). Gauss points closer than the link
//      radius are joined unless an open segment lies between them (segments_cross); the joined sets are the
//      pieces, the one of the largest area the slab, the others loose. A loose piece that touches the loaded
//      face or holds a crushed crater point is in the crater; one that touches the far face (y = y0) is spall
//      (scabbing, the reflected tension), reported apart; one that touches neither is loose inside.
//
// "Touches a face": the point lies within half the link radius of it (with the 2 x 2 rule and a link radius
// of one spacing h, the first row of points at 0.21 h, the second at 0.79 h). The crater's depth is the
// loaded face's y less the lowest crater point's y (like the compacted depth, it moves in steps of the point
// rows), its width the crater points' x range, its area the sum of their Gauss weights (m^2 per metre of
// charge length in plane strain).
#include <cstddef>
#include <vector>

#include "mesowave/efg/geometry.hpp"
#include "mesowave/efg/hugoniot.hpp"

namespace mesowave::efg {

/// What became of a Gauss point (CraterMeasure::label).
enum class CraterLabel : int { intact = 0, crushed = 1, crater_fragment = 2, spall = 3, loose_inside = 4 };

struct CraterInput {
  Rect body;                      ///< the slab; the loaded face is y = body.y1, the far face y = body.y0
  std::vector<Vec2> x;            ///< the Gauss points
  std::vector<double> area_m2;    ///< their weights (area)
  std::vector<double> min_eps_v;  ///< their most compressive volumetric strain (< 0 in compression)
  std::vector<Segment> open_segments;  ///< crack segments whose faces are all past w_max (header)
  double link_radius_m = 0;       ///< points closer than this are joined unless an open segment lies between
  double crushing_eps_v = 0;      ///< eps_crush, a magnitude > 0
  /// InputError naming the value: sizes that differ, link radius or crushing strain not > 0.
  void validate() const;
};

struct CraterMeasure {
  std::vector<CraterLabel> label;  ///< per point
  std::size_t pieces = 0;          ///< the slab and every loose piece
  std::size_t crushed_points = 0, crater_fragment_points = 0, crater_fragments = 0;
  std::size_t spall_points = 0, spall_fragments = 0, loose_inside_points = 0;
  double depth_m = 0, width_m = 0, x_min_m = 0, x_max_m = 0;  ///< 0 when there is no crater
  double area_m2 = 0, crushed_area_m2 = 0, fragment_area_m2 = 0;
  double spall_area_m2 = 0, spall_depth_m = 0;  ///< spall depth: the highest spall point above the far face
};

/// eps_crush by default: |eps_v| at the Y-function's minimum (header, (a)).
double default_crushing_eps_v(const HugoniotParameters& p);

/// The crater of the state (header). Deterministic: the same input gives the same labels in any order of
/// evaluation (union-find over links in ascending point order; the slab is the piece of the largest area,
/// ties to the piece of the lowest point index).
CraterMeasure measure_crater(const CraterInput& in);

}  // namespace mesowave::efg
