#pragma once
// Cracks and notches as polylines that cut the MLS weight functions, Eq. (13) of Larcher and
// Stempniewski (seed 004, Section 2.2): the weight of node x_I is zero in the part B of its support
// that the crack hides from it. Three ways to decide what is hidden and how the weight behaves near a
// tip (Belytschko et al.; Organ, Fleming, Terry and Belytschko 1996, "Continuous meshless
// approximations for nonconvex bodies by diffraction and transparency", Comput. Mech. 18: 225-235):
//  - visibility: w = 0 where the segment x_I-x crosses the crack. Simple, but the shape functions
//    jump across the shadow line that runs from x_I through the tip (the paper's objection).
//  - diffraction: where x_I-x crosses the crack, the distance in the weight is bent around the
//    nearest tip x_c, d = ((s1 + s2(x)) / s0(x))^lambda s0(x) with s0 = |x - x_I|, s1 = |x_I - x_c|,
//    s2 = |x - x_c|. On the shadow line s1 + s2 = s0, so d and the shape functions are continuous.
//  - transparency: the crack is transparent at its tip and opaque beyond s_bar from it,
//    d = s0(x) + h_I (s_c(x) / s_bar)^kappa, s_c the distance from where x_I-x crosses the crack to
//    the tip (measured along the crack). Continuous too; needs the node's support radius h_I.
// A node or a point lying exactly ON a crack line is hidden from both sides (the crossing test counts
// touching): place nodes off crack lines, and evaluate on a crack face a small distance off the line.
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include "mesowave/efg/geometry.hpp"

namespace mesowave::efg {

enum class CrackWeightMethod { visibility, diffraction, transparency };

/// A face of a rectangular body, where a crack may open (the mouth of a notch).
enum class BodyFace { none, bottom, right, top, left };

/// A crack or notch as the user places it must lie in the body: InputError, one line naming the point
/// (its index and coordinates [m]) and the body, when a point lies outside `body` or on its boundary.
/// The one exception is the first point (the mouth), which may lie on the face `mouth` - an edge
/// notch opens there; with BodyFace::none it must be inside too. The body is convex, so a polyline
/// whose points are inside stays inside: no segment can leave it between them. Touching is judged
/// within 1e-9 of the body's larger side. `what` starts the message ("three-point bending: notch").
/// (Solvers may run a crack's line on beyond a face - the notch below the bottom face so that the
/// bottom edge's weights are cut too - but that is their construction, not the user's crack.)
void require_crack_inside(const std::vector<Vec2>& polyline, const Rect& body, BodyFace mouth, std::string_view what);
/// "visibility" | "diffraction" | "transparency"; InputError otherwise.
CrackWeightMethod parse_crack_weight_method(std::string_view name);
std::string_view to_string(CrackWeightMethod method);

struct Crack {
  std::vector<Vec2> points;   ///< polyline, >= 2 points
  bool tip_at_start = false;  ///< an end inside the body is a tip (diffraction bends around it)
  bool tip_at_end = true;
};

/// The weight distance of a node at a point and its gradient with respect to the point.
struct WeightDistance {
  double d = std::numeric_limits<double>::infinity();  ///< +inf: the node's weight is cut
  Vec2 gradient = Vec2::Zero();                         ///< dd/dx (zero where d is infinite or s0 = 0)
  bool cut() const { return !(d < std::numeric_limits<double>::infinity()); }
};

/// Options of the transparency method (Organ et al. 1996, Section 4).
struct TransparencyOptions {
  double opaque_distance_m = 0;  ///< s_bar: beyond it from the tip the crack is opaque (> 0)
  double kappa = 2.0;            ///< exponent, >= 2 so that the weight's derivative is continuous
};

class CrackSet {
public:
  /// Index of the crack. InputError: fewer than 2 points, a non-finite point, a zero-length segment.
  std::size_t add(Crack crack);
  /// Appends a point at the tip end (the end if tip_at_end, else the start); InputError when the
  /// crack has no tip or the new segment has zero length.
  void extend(std::size_t crack, const Vec2& new_tip);
  const std::vector<Crack>& cracks() const { return cracks_; }
  bool empty() const { return cracks_.empty(); }
  /// The end that extend() moves: the last point if tip_at_end, else the first (InputError: no tip).
  const Vec2& tip(std::size_t crack) const;
  /// A crack with two tips (one that started inside the body, efg/dynamic_cracks) grows at either end:
  /// appends `new_point` at the end (`at_end`) or the start; InputError when that end is not a tip or
  /// the new segment has zero length.
  void extend_end(std::size_t crack, bool at_end, const Vec2& new_point);
  /// That end is no longer a tip (it ran out through a face or into another crack): diffraction and
  /// transparency stop bending the weights around it.
  void close_tip(std::size_t crack, bool at_end);
  /// The cracks of `earlier` (a copy taken before a change that is undone) under a NEW version, so
  /// that caches keyed on version() (ElasticModel's shape functions) see the change back.
  void restore(const CrackSet& earlier);
  /// Shortest distance from p to any crack segment (+inf without cracks): keeps nodes and Gauss
  /// points off crack lines, where the crossing test cannot tell the sides apart.
  double distance(const Vec2& p) const;

  /// Eq. (13), visibility: true when a crack hides point x from node x_I (the segment x_I-x crosses
  /// or touches one of its segments).
  bool hides(const Vec2& node, const Vec2& x) const;

  /// Weight distance for the MLS weight of node x_I at x under `method` (Organ et al. 1996 for
  /// diffraction: d = ((s1 + s2(x)) / s0(x))^lambda s0(x), around the nearest tip); +infinity when
  /// the node's weight is cut (visibility, or a crack with no tip between them). Transparency needs
  /// the node's support radius: see weight_distance_gradient.
  double weight_distance(const Vec2& node, const Vec2& x, CrackWeightMethod method, double lambda = 2.0) const;

  /// The same with dd/dx, which the MLS derivatives need (chain rule through d). For transparency,
  /// `support_radius_m` is h_I and `transparency` its options (opaque distance defaults to h_I).
  WeightDistance weight_distance_gradient(const Vec2& node, const Vec2& x, CrackWeightMethod method,
                                          double lambda = 2.0, double support_radius_m = 0,
                                          TransparencyOptions transparency = {}) const;

  /// Version counter, bumped by add/extend (callers cache shape functions against it).
  std::uint64_t version() const { return version_; }

private:
  // True when the segment s crosses crack k (any of its segments); `tip` names an end point of the
  // crack that s may touch without crossing (the diffraction path passes through the tip).
  bool crosses(std::size_t k, const Segment& s, const Vec2* tip = nullptr) const;
  bool path_clear(const Segment& s, const Vec2& tip) const;

  /// crack k's bounding box (min x, min y, max x, max y), kept by every change: a segment whose box misses it
  /// cannot cross or touch the crack (segments_cross is true only at a common point), so crosses() skips it.
  /// The shape functions ask crosses() for every node-point pair and every crack after each change
  /// (docs/efg.md, "The slab's time step, its spacing and its cost"); the answer is the same, only sooner.
  void update_box(std::size_t k);

  std::vector<Crack> cracks_;
  std::vector<Eigen::Vector4d> boxes_;
  std::uint64_t version_ = 0;
};

}  // namespace mesowave::efg
