#include "mesowave/efg/crack.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::efg {

CrackWeightMethod parse_crack_weight_method(std::string_view name) {
  if (name == "visibility") return CrackWeightMethod::visibility;
  if (name == "diffraction") return CrackWeightMethod::diffraction;
  if (name == "transparency") return CrackWeightMethod::transparency;
  throw InputError("crack weight method '" + std::string(name) +
                   "' unknown (visibility | diffraction | transparency)");
}

std::string_view to_string(CrackWeightMethod method) {
  switch (method) {
    case CrackWeightMethod::visibility: return "visibility";
    case CrackWeightMethod::diffraction: return "diffraction";
    case CrackWeightMethod::transparency: return "transparency";
  }
  return "?";
}

namespace {

std::string point_text(const Vec2& p) {
  return "(" + format_number(p.x()) + ", " + format_number(p.y()) + ") m";
}

void check_segment(const Vec2& a, const Vec2& b, std::size_t index) {
  if (!a.allFinite() || !b.allFinite())
    throw InputError("crack " + std::to_string(index) + ": point " + point_text(!a.allFinite() ? a : b) +
                     " is not finite");
  if (a == b) throw InputError("crack " + std::to_string(index) + ": zero-length segment at " + point_text(a));
}

double cross(const Vec2& v, const Vec2& w) { return v.x() * w.y() - v.y() * w.x(); }

// Length of the polyline from point i to point j (i <= j).
double polyline_length(const std::vector<Vec2>& p, std::size_t i, std::size_t j) {
  double l = 0;
  for (std::size_t k = i; k < j; ++k) l += (p[k + 1] - p[k]).norm();
  return l;
}

std::string_view face_name(BodyFace f) {
  switch (f) {
    case BodyFace::bottom: return "bottom";
    case BodyFace::right: return "right";
    case BodyFace::top: return "top";
    case BodyFace::left: return "left";
    case BodyFace::none: break;
  }
  return "none";
}

}  // namespace

void require_crack_inside(const std::vector<Vec2>& polyline, const Rect& body, BodyFace mouth, std::string_view what) {
  const std::string name(what);
  if (!(body.x1 > body.x0 && body.y1 > body.y0))
    throw InputError(name + ": the body [" + format_number(body.x0) + ", " + format_number(body.x1) + "] x [" +
                     format_number(body.y0) + ", " + format_number(body.y1) + "] m is empty");
  if (polyline.size() < 2)
    throw InputError(name + ": " + std::to_string(polyline.size()) + " points, a crack needs at least 2");
  const double tol = 1e-9 * std::max(body.x1 - body.x0, body.y1 - body.y0);
  const std::string box = "the body [" + format_number(body.x0) + ", " + format_number(body.x1) + "] x [" +
                          format_number(body.y0) + ", " + format_number(body.y1) + "] m";
  for (std::size_t k = 0; k < polyline.size(); ++k) {
    const Vec2& p = polyline[k];
    const std::string where = name + ": point " + std::to_string(k) + " " + point_text(p);
    if (!p.allFinite()) throw InputError(where + " is not finite");
    // signed distances inside each face (> 0: inside)
    const double d[4] = {p.y() - body.y0, body.x1 - p.x(), body.y1 - p.y(), p.x() - body.x0};  // bottom, right, top, left
    const double inner = *std::min_element(d, d + 4);
    if (inner < -tol) throw InputError(where + " lies outside " + box);
    if (inner > tol) continue;
    // on the boundary: only the mouth, on its own face (not at a corner, where it touches another face too)
    const int on = int(std::count_if(d, d + 4, [&](double x) { return std::abs(x) <= tol; }));
    const bool at_mouth = k == 0 && mouth != BodyFace::none && on == 1 && std::abs(d[int(mouth) - 1]) <= tol;
    if (!at_mouth)
      throw InputError(where + " lies on the boundary of " + box +
                       (mouth == BodyFace::none ? std::string(" (the crack must lie inside)")
                                                : " (only the first point may, on the " + std::string(face_name(mouth)) +
                                                      " face where the crack opens)"));
  }
}

std::size_t CrackSet::add(Crack crack) {
  const std::size_t index = cracks_.size();
  if (crack.points.size() < 2)
    throw InputError("crack " + std::to_string(index) + ": " + std::to_string(crack.points.size()) +
                     " points, a crack needs at least 2");
  for (std::size_t i = 0; i + 1 < crack.points.size(); ++i) check_segment(crack.points[i], crack.points[i + 1], index);
  cracks_.push_back(std::move(crack));
  boxes_.emplace_back();
  update_box(index);
  ++version_;
  return index;
}

void CrackSet::extend(std::size_t k, const Vec2& new_tip) {
  if (k >= cracks_.size())
    throw InputError("crack " + std::to_string(k) + " does not exist (" + std::to_string(cracks_.size()) + " cracks)");
  Crack& c = cracks_[k];
  if (!c.tip_at_end && !c.tip_at_start) throw InputError("crack " + std::to_string(k) + " has no tip to extend");
  auto& p = c.points;
  if (c.tip_at_end) {
    check_segment(p.back(), new_tip, k);
    p.push_back(new_tip);
  } else {
    check_segment(new_tip, p.front(), k);
    p.insert(p.begin(), new_tip);
  }
  update_box(k);
  ++version_;
}

void CrackSet::extend_end(std::size_t k, bool at_end, const Vec2& new_point) {
  if (k >= cracks_.size())
    throw InputError("crack " + std::to_string(k) + " does not exist (" + std::to_string(cracks_.size()) + " cracks)");
  Crack& c = cracks_[k];
  if (!(at_end ? c.tip_at_end : c.tip_at_start))
    throw InputError("crack " + std::to_string(k) + ": its " + (at_end ? "end" : "start") + " is not a tip");
  auto& p = c.points;
  if (at_end) {
    check_segment(p.back(), new_point, k);
    p.push_back(new_point);
  } else {
    check_segment(new_point, p.front(), k);
    p.insert(p.begin(), new_point);
  }
  update_box(k);
  ++version_;
}

void CrackSet::close_tip(std::size_t k, bool at_end) {
  if (k >= cracks_.size())
    throw InputError("crack " + std::to_string(k) + " does not exist (" + std::to_string(cracks_.size()) + " cracks)");
  (at_end ? cracks_[k].tip_at_end : cracks_[k].tip_at_start) = false;
  ++version_;
}

void CrackSet::restore(const CrackSet& earlier) {
  const std::uint64_t next = std::max(version_, earlier.version_) + 1;
  cracks_ = earlier.cracks_;
  boxes_ = earlier.boxes_;
  version_ = next;
}

void CrackSet::update_box(std::size_t k) {
  Eigen::Vector4d& b = boxes_[k];
  const auto& p = cracks_[k].points;
  b << p[0].x(), p[0].y(), p[0].x(), p[0].y();
  for (const Vec2& q : p) {
    b[0] = std::min(b[0], q.x()), b[1] = std::min(b[1], q.y());
    b[2] = std::max(b[2], q.x()), b[3] = std::max(b[3], q.y());
  }
}

const Vec2& CrackSet::tip(std::size_t k) const {
  if (k >= cracks_.size())
    throw InputError("crack " + std::to_string(k) + " does not exist (" + std::to_string(cracks_.size()) + " cracks)");
  const Crack& c = cracks_[k];
  if (!c.tip_at_end && !c.tip_at_start) throw InputError("crack " + std::to_string(k) + " has no tip");
  return c.tip_at_end ? c.points.back() : c.points.front();
}

double CrackSet::distance(const Vec2& p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& c : cracks_)
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
      const Vec2 a = c.points[i], ab = c.points[i + 1] - a;
      const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a + t * ab - p).norm());
    }
  return best;
}

bool CrackSet::crosses(std::size_t k, const Segment& s, const Vec2* tip) const {
  const Eigen::Vector4d& b = boxes_[k];
  if (std::max(s.a.x(), s.b.x()) < b[0] || std::min(s.a.x(), s.b.x()) > b[2] || std::max(s.a.y(), s.b.y()) < b[1] ||
      std::min(s.a.y(), s.b.y()) > b[3])
    return false;  // no common point with the crack's box: no crossing, no touching (update_box)
  const auto& p = cracks_[k].points;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    // A segment ending at the tip may be touched there (the bent path of diffraction).
    const bool at_tip = tip != nullptr && (p[i] == *tip || p[i + 1] == *tip);
    if (segments_cross(s, {p[i], p[i + 1]}, !at_tip)) return true;
  }
  return false;
}

bool CrackSet::path_clear(const Segment& s, const Vec2& tip) const {
  for (std::size_t k = 0; k < cracks_.size(); ++k)
    if (crosses(k, s, &tip)) return false;
  return true;
}

bool CrackSet::hides(const Vec2& node, const Vec2& x) const {
  for (std::size_t k = 0; k < cracks_.size(); ++k)
    if (crosses(k, {node, x})) return true;
  return false;
}

double CrackSet::weight_distance(const Vec2& node, const Vec2& x, CrackWeightMethod method, double lambda) const {
  return weight_distance_gradient(node, x, method, lambda).d;
}

WeightDistance CrackSet::weight_distance_gradient(const Vec2& node, const Vec2& x, CrackWeightMethod method,
                                                  double lambda, double support_radius_m,
                                                  TransparencyOptions transparency) const {
  const Vec2 r = x - node;
  const double s0 = r.norm();
  const Vec2 ds0 = s0 > 0 ? Vec2(r / s0) : Vec2::Zero();
  // The one crack the segment node-x crosses; two or more cut the weight under every method.
  std::size_t crossed = cracks_.size();
  for (std::size_t k = 0; k < cracks_.size(); ++k) {
    if (!crosses(k, {node, x})) continue;
    if (crossed != cracks_.size()) return {};
    crossed = k;
  }
  if (crossed == cracks_.size()) return {s0, ds0};
  if (method == CrackWeightMethod::visibility) return {};
  const Crack& c = cracks_[crossed];

  if (method == CrackWeightMethod::diffraction) {
    if (!(lambda >= 1)) throw InputError("diffraction exponent lambda (" + format_number(lambda) + ") must be >= 1");
    WeightDistance best;
    for (int end = 0; end < 2; ++end) {
      if (!(end == 0 ? c.tip_at_start : c.tip_at_end)) continue;
      const Vec2& tip = end == 0 ? c.points.front() : c.points.back();
      if (!path_clear({node, tip}, tip) || !path_clear({tip, x}, tip)) continue;
      const double s1 = (node - tip).norm(), s2 = (x - tip).norm();
      if (!(s2 > 0) || !(s0 > 0)) continue;
      const double ratio = (s1 + s2) / s0;
      const double d = std::pow(ratio, lambda) * s0;
      if (d >= best.d) continue;
      // d = (s1 + s2)^lambda s0^(1 - lambda): product rule, ds2/dx = (x - x_c)/s2, ds0/dx = (x - x_I)/s0.
      const Vec2 ds2 = (x - tip) / s2;
      best.d = d;
      best.gradient = lambda * std::pow(ratio, lambda - 1) * ds2 + (1 - lambda) * std::pow(ratio, lambda) * ds0;
    }
    return best;
  }

  // Transparency: where along the crack the segment node-x crosses it, and how far that is from a tip.
  if (!(support_radius_m > 0))
    throw InputError("transparency needs the node's support radius h_I > 0 (got " + format_number(support_radius_m) + " m)");
  if (!(transparency.kappa >= 2))
    throw InputError("transparency exponent kappa (" + format_number(transparency.kappa) + ") must be >= 2");
  const double s_bar = transparency.opaque_distance_m > 0 ? transparency.opaque_distance_m : support_radius_m;
  const auto& p = c.points;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    if (!segments_cross({node, x}, {p[i], p[i + 1]}, true)) continue;
    const double L = (p[i + 1] - p[i]).norm();
    const Vec2 e = (p[i + 1] - p[i]) / L, q = p[i] - node;
    // The crossing point p_i + u e lies on the line x_I + t r: cross(q + u e, r) = 0.
    const double f = cross(q, r), g = cross(e, r);
    if (g == 0) return {};  // along the crack face: opaque
    const double u = -f / g;
    const Vec2 du = -(Vec2(-q.y(), q.x()) * g - f * Vec2(-e.y(), e.x())) / (g * g);
    WeightDistance best;
    for (int end = 0; end < 2; ++end) {
      if (!(end == 0 ? c.tip_at_start : c.tip_at_end)) continue;
      const double sc = end == 0 ? polyline_length(p, 0, i) + u : (L - u) + polyline_length(p, i + 1, p.size() - 1);
      if (sc >= s_bar) continue;
      const Vec2 dsc = end == 0 ? du : Vec2(-du);
      const double d = s0 + support_radius_m * std::pow(sc / s_bar, transparency.kappa);
      if (d >= best.d) continue;
      best.d = d;
      best.gradient = ds0 + support_radius_m * transparency.kappa * std::pow(sc / s_bar, transparency.kappa - 1) / s_bar * dsc;
    }
    return best;
  }
  return {};
}

}  // namespace mesowave::efg
