#include "mesowave/efg/dynamic_cracks.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/efg/discretisation.hpp"
#include "mesowave/efg/field_projection.hpp"

namespace mesowave::efg {

namespace {

/// Largest principal stress and its unit direction (Voigt xx, yy, xy).
std::pair<double, Vec2> largest_principal(const Eigen::Vector3d& s) {
  const double mean = 0.5 * (s[0] + s[1]), radius = std::hypot(0.5 * (s[0] - s[1]), s[2]);
  const double theta = 0.5 * std::atan2(2 * s[2], s[0] - s[1]);
  return {mean + radius, Vec2(std::cos(theta), std::sin(theta))};
}

Vec2 perpendicular(const Vec2& d) { return Vec2(-d.y(), d.x()); }

Vec2 rotate(const Vec2& d, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Vec2(c * d.x() - s * d.y(), s * d.x() + c * d.y());
}

double distance_to_segment(const Vec2& p, const Segment& s) {
  const Vec2 ab = s.b - s.a;
  const double t = std::clamp((p - s.a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (s.a + t * ab - p).norm();
}

/// [u] = sum (phi+ - phi-) u_I through a visitor on (node, coefficient).
template <class F>
void for_jump(const CrackFacePoint& p, F f) {
  for (std::size_t i = 0; i < p.plus.nodes.size(); ++i) f(p.plus.nodes[i], p.plus.phi[i]);
  for (std::size_t i = 0; i < p.minus.nodes.size(); ++i) f(p.minus.nodes[i], -p.minus.phi[i]);
}

}  // namespace

FieldProjection parse_field_projection(std::string_view name) {
  if (name == "none") return FieldProjection::none;
  if (name == "u") return FieldProjection::displacement;
  if (name == "u-v") return FieldProjection::displacement_and_velocity;
  throw InputError("field projection '" + std::string(name) + "' is not one of none, u, u-v");
}

std::string_view to_string(FieldProjection p) {
  switch (p) {
    case FieldProjection::none: return "none";
    case FieldProjection::displacement: return "u";
    case FieldProjection::displacement_and_velocity: return "u-v";
  }
  return "?";
}

void DynamicCrackOptions::validate() const {
  (void)make_cohesive_law(law, cohesive);  // f_t, G_f, keys, f_c: the registry's one-line errors
  if (strain_rate_effect) strain_rate.validate();
  if (!(crack_speed_limit_m_s > 0))
    throw InputError("crack speed limit (" + format_quantity(crack_speed_limit_m_s, "m/s") + ") must be > 0");
  const auto length = [](const char* what, double v) {
    if (!std::isfinite(v) || v < 0) throw InputError(std::string(what) + " (" + format_quantity(v, "m") + ") must be >= 0 (0: the default)");
  };
  length("crack segment length", segment_length_m);
  length("minimum crack spacing", min_crack_spacing_m);
  length("minimum crack radius", min_crack_radius_m);
  if (!std::isfinite(penalty_factor) || !(penalty_factor > 0))
    throw InputError("crack face penalty factor (" + format_number(penalty_factor) + ") must be > 0");
  if (cohesive_gauss < 1 || cohesive_gauss > 8)
    throw InputError("crack face Gauss points (" + std::to_string(cohesive_gauss) + ") must be in [1, 8]");
  if (check_every < 1) throw InputError("crack check interval (" + std::to_string(check_every) + " steps) must be >= 1");
  if (!(face_offset_fraction > 0 && face_offset_fraction < 0.01))
    throw InputError("crack face offset fraction (" + format_number(face_offset_fraction) + ") must be in (0, 0.01)");
}

DynamicCracks::DynamicCracks(ElasticModel& model, CrackSet& cracks, DynamicCrackOptions options)
    : model_(&model),
      cracks_(&cracks),
      o_(std::move(options)),
      gauss_grid_({Vec2::Zero()}, 1.0),
      node_grid_({Vec2::Zero()}, 1.0) {
  o_.validate();
  if (model.mls().cracks() != &cracks)
    throw InputError("dynamic cracks: the CrackSet is not the one the model's MLS reads");
  const double h = model.discretisation().spacing_m;
  a_ = o_.segment_length_m > 0 ? o_.segment_length_m : h;
  k_ = o_.penalty_factor * model.material().E_Pa / a_;
  spacing_min_ = o_.min_crack_spacing_m > 0 ? o_.min_crack_spacing_m : 2 * a_;
  radius_min_ = o_.min_crack_radius_m > 0 ? o_.min_crack_radius_m : a_;
  max_turn_rad_ = 2 * std::asin(std::min(1.0, a_ / (2 * radius_min_)));
  offset_ = o_.face_offset_fraction * h;
  overshoot_ = 0.5 * h;
  body_ = {INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const Rect& c : model.discretisation().cells)
    body_ = {std::min(body_.x0, c.x0), std::min(body_.y0, c.y0), std::max(body_.x1, c.x1), std::max(body_.y1, c.y1)};
  const double rho_t = model.material().density_kg_m3 * model.material().thickness_m;
  for (const GaussPoint& g : model.discretisation().points) {
    gauss_x_.push_back(g.x);
    point_mass_.push_back(rho_t * g.weight_m2);
  }
  gauss_grid_ = NodeGrid(gauss_x_, h);
  node_grid_ = NodeGrid(model.mls().nodes(), h);
  tips_.resize(cracks.cracks().size());
}

bool DynamicCracks::inside(const Vec2& p) const {
  return p.x() > body_.x0 && p.x() < body_.x1 && p.y() > body_.y0 && p.y() < body_.y1;
}

std::int32_t DynamicCracks::make_law(double f_t_dyn_Pa) {
  CohesiveParameters p = o_.cohesive;
  p.f_t_Pa = f_t_dyn_Pa;  // Eq. (19): the dynamic strength; Eq. (20): w_max from it and G_f
  laws_.push_back(make_cohesive_law(o_.law, p));
  return std::int32_t(laws_.size() - 1);
}

void DynamicCracks::add_face_segment(const Segment& s, std::int32_t law, std::size_t crack) {
  const SegmentGauss g = segment_gauss_points(s, o_.cohesive_gauss);
  for (const SegmentGaussPoint& q : g.points) {
    CrackFacePoint p;
    p.x = q.x;
    p.normal = g.normal;
    p.length_weight_m = q.length_weight_m;
    p.law = law;
    p.w_initial_m = law >= 0 ? laws_[std::size_t(law)]->f_t_Pa() / k_ : 0.0;  // the initial secant is k (header)
    p.w_hist_m = p.w_initial_m;
    p.crack = crack;
    p.segment = s;
    points_.push_back(std::move(p));  // shape functions: refresh()
  }
}

double DynamicCracks::face_w_max_m(std::size_t k) const {
  const CrackFacePoint& p = points_.at(k);
  return p.law >= 0 ? laws_[std::size_t(p.law)]->w_max_m() : 0.0;
}

std::vector<Segment> DynamicCracks::open_segments() const {
  std::vector<Segment> out;
  // a segment's face points are laid together (add_face_segment), so a run of points with the same segment is one
  for (std::size_t k = 0; k < points_.size();) {
    const Segment& s = points_[k].segment;
    bool open = true;
    std::size_t e = k;
    for (; e < points_.size() && points_[e].crack == points_[k].crack && points_[e].segment.a == s.a && points_[e].segment.b == s.b; ++e)
      open = open && points_[e].w_hist_m >= face_w_max_m(e);
    if (open) out.push_back(s);
    k = e;
  }
  return out;
}

void DynamicCracks::refresh() {
  model_->update_shape_functions();
  const auto& mls = model_->mls();
  for (std::size_t k = 0; k < points_.size(); ++k) {
    auto& p = points_[k];
    const std::string where = "crack face point " + std::to_string(k) + " of crack " + std::to_string(p.crack);
    p.plus = mls.evaluate(p.x + offset_ * p.normal, where + " (+ face)");
    p.minus = mls.evaluate(p.x - offset_ * p.normal, where + " (- face)");
  }
}

bool DynamicCracks::clip(const Vec2& a, Vec2& b, Vec2& b_in_body, std::size_t self) const {
  const Segment s{a, b};
  double t_cut = 2;  // parameter on a-b of the first face or crack it reaches
  if (!inside(b)) {
    const Vec2 d = b - a;
    for (int axis = 0; axis < 2; ++axis) {
      if (d[axis] == 0) continue;
      for (double bound : {axis == 0 ? body_.x0 : body_.y0, axis == 0 ? body_.x1 : body_.y1}) {
        const double t = (bound - a[axis]) / d[axis];
        if (t > 0 && t <= 1) t_cut = std::min(t_cut, t);
      }
    }
  }
  const auto& all = cracks_->cracks();
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (k == self) continue;
    for (std::size_t i = 0; i + 1 < all[k].points.size(); ++i) {
      const Segment q{all[k].points[i], all[k].points[i + 1]};
      if (segments_cross(s, q, false)) t_cut = std::min(t_cut, crossing_parameter(s, q));
    }
  }
  if (t_cut > 1) {
    b_in_body = b;
    return false;
  }
  const Vec2 dir = (b - a).normalized();
  b_in_body = a + t_cut * (b - a);
  b = b_in_body + overshoot_ * dir;  // run on beyond the face or the other crack: its weights are cut too
  return true;
}

bool DynamicCracks::clear(const Segment& s) const {
  const double eps = 0.05 * a_;
  const Vec2 mid = 0.5 * (s.a + s.b);
  const double r = 0.5 * (s.b - s.a).norm() + eps;
  for (std::int32_t i : node_grid_.within(mid, r))
    if (distance_to_segment(model_->mls().nodes()[std::size_t(i)], s) < eps) return false;
  for (std::int32_t i : gauss_grid_.within(mid, r))
    if (distance_to_segment(gauss_x_[std::size_t(i)], s) < eps) return false;
  return true;
}

std::size_t DynamicCracks::add_crack(const std::vector<Vec2>& polyline, bool traction_free, bool tips) {
  Crack c;
  c.points = polyline;
  c.tip_at_start = tips && inside(polyline.front());
  c.tip_at_end = tips && inside(polyline.back());
  const std::size_t index = cracks_->add(c);
  tips_.resize(cracks_->cracks().size());
  const std::int32_t law = traction_free ? -1 : make_law(o_.cohesive.f_t_Pa);
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    Vec2 a = polyline[i], b = polyline[i + 1];
    if (!inside(a) && !inside(b)) continue;
    if (!inside(a)) std::swap(a, b);
    Vec2 b_in = b;
    if (!inside(b)) clip(a, b, b_in, index);
    add_face_segment({a, b_in}, law, index);
  }
  refresh();
  return index;
}

std::vector<DynamicCracks::Critical> DynamicCracks::critical_points(const std::vector<PointState>& states) const {
  std::vector<Critical> out;
  const double f_t = o_.cohesive.f_t_Pa;
  for (std::size_t p = 0; p < states.size(); ++p) {
    const auto [s1, dir] = largest_principal(states[p].stress);
    if (!(s1 >= f_t)) continue;  // f_t,dyn >= f_t: no point below the static strength is critical
    const double f_dyn =
        o_.strain_rate_effect ? dynamic_tensile_strength_Pa(f_t, states[p].strain_rate_1_s, o_.strain_rate) : f_t;
    if (s1 >= f_dyn) out.push_back({std::int64_t(p), s1 / f_dyn, f_dyn, dir});
  }
  std::sort(out.begin(), out.end(), [](const Critical& x, const Critical& y) {
    return x.ratio != y.ratio ? x.ratio > y.ratio : x.point < y.point;
  });
  return out;
}

bool DynamicCracks::grow_tip(std::size_t k, bool at_end, double t_s, const std::vector<Critical>& critical) {
  const Crack& c = cracks_->cracks()[k];
  if (!(at_end ? c.tip_at_end : c.tip_at_start)) return false;
  Tip& tip_state = tips_[k][at_end ? 1 : 0];
  const double elapsed = t_s - tip_state.t_last_s;
  if (o_.crack_speed_limit_m_s * elapsed < a_) return false;  // (a): speed <= v_max
  const auto& pts = c.points;
  const Vec2 tip = at_end ? pts.back() : pts.front();
  const Vec2 heading = (at_end ? Vec2(pts.back() - pts[pts.size() - 2]) : Vec2(pts.front() - pts[1])).normalized();
  // the tip's points: critical, within one segment length, ahead of the tip (the most critical first)
  const Critical* best = nullptr;
  for (const Critical& q : critical) {
    const Vec2 d = gauss_x_[std::size_t(q.point)] - tip;
    if (d.norm() <= a_ && d.dot(heading) > 0) {
      best = &q;
      break;
    }
  }
  if (!best) return false;
  Vec2 dir = perpendicular(best->direction);  // normal to the largest principal stress
  if (dir.dot(heading) < 0) dir = -dir;
  // (b): the crack radius - the turn from the heading clamped to max_turn
  const double turn = std::atan2(heading.x() * dir.y() - heading.y() * dir.x(), heading.dot(dir));
  dir = rotate(heading, std::clamp(turn, -max_turn_rad_, max_turn_rad_));
  Vec2 next = tip + a_ * dir;
  // clear of nodes and Gauss points: turn a little (within the radius limit) if needed
  const double base = std::clamp(turn, -max_turn_rad_, max_turn_rad_);
  for (int tries = 1; tries <= 8 && !clear({tip, next}); ++tries) {
    const double delta = 0.05 * ((tries + 1) / 2) * (tries % 2 ? 1 : -1);
    next = tip + a_ * rotate(heading, std::clamp(base + delta, -max_turn_rad_, max_turn_rad_));
  }
  Vec2 in_body = next;
  const bool stopped = clip(tip, next, in_body, k);  // (c)
  const double length = (in_body - tip).norm();
  if (!(length > 1e-9 * a_)) return false;
  const double f_dyn = best->f_t_dyn;
  const std::int32_t law = make_law(f_dyn);
  cracks_->extend_end(k, at_end, next);
  if (stopped) cracks_->close_tip(k, at_end);
  add_face_segment({tip, in_body}, law, k);
  CrackEvent e;
  e.t_s = t_s;
  e.crack = k;
  e.at_end = at_end;
  e.from = tip;
  e.to = in_body;
  e.length_m = length;
  e.speed_m_s = length / elapsed;
  e.stress_ratio = best->ratio;
  e.f_t_dyn_Pa = f_dyn;
  e.point = best->point;
  events_.push_back(e);
  tip_state.t_last_s = t_s;
  return true;
}

bool DynamicCracks::initiate(const Critical& q, double t_s) {
  const Vec2 x = gauss_x_[std::size_t(q.point)];
  if (cracks_->distance(x) < spacing_min_) return false;
  const Vec2 dir = perpendicular(q.direction), normal = q.direction;
  // shift along the normal until no node or Gauss point lies on (near) the line
  Vec2 centre = x;
  for (int tries = 0; tries <= 8; ++tries) {
    const double shift = 0.1 * a_ * ((tries + 1) / 2) * (tries % 2 ? 1 : -1);
    centre = x + shift * normal;
    if (clear({centre - 0.5 * a_ * dir, centre + 0.5 * a_ * dir})) break;
  }
  if (!inside(centre)) return false;
  Vec2 start = centre - 0.5 * a_ * dir, end = centre + 0.5 * a_ * dir;
  Vec2 start_in = start, end_in = end;
  const std::size_t self = cracks_->cracks().size();
  const bool start_cut = clip(centre, start, start_in, self);
  const bool end_cut = clip(centre, end, end_in, self);
  Crack c;
  c.points = {start, centre, end};
  c.tip_at_start = !start_cut;
  c.tip_at_end = !end_cut;
  const std::size_t k = cracks_->add(c);
  tips_.resize(cracks_->cracks().size());
  tips_[k][0].t_last_s = tips_[k][1].t_last_s = t_s;
  const std::int32_t law = make_law(q.f_t_dyn);
  add_face_segment({start_in, centre}, law, k);
  add_face_segment({centre, end_in}, law, k);
  CrackEvent e;
  e.t_s = t_s;
  e.crack = k;
  e.initiation = true;
  e.from = e.to = centre;
  e.length_m = (end_in - start_in).norm();
  e.stress_ratio = q.ratio;
  e.f_t_dyn_Pa = q.f_t_dyn;
  e.point = q.point;
  events_.push_back(e);
  return true;
}

double DynamicCracks::kinetic_J(const Eigen::VectorXd& v) const {
  double ke = 0;
  for (Eigen::Index d = 0; d < v.size(); ++d) ke += 0.5 * mass_[d / 2] * v[d] * v[d];
  return ke;
}

void DynamicCracks::project(const std::vector<ShapeFunctions>& before, double t_s, Eigen::VectorXd& u, Eigen::VectorXd& v) {
  if (mass_.size() == 0) mass_ = lumped_mass(*model_);  // a caller driving advance() itself
  const ParameterProjection p(before, model_->shape_functions(), point_mass_, model_->mls().node_count());
  Projection rec{t_s, p.changed_points(), p.nodes().size(), 0, 0, p.ok()};
  if (p.changed_points() > 0 && p.ok()) {
    const double ke_before = kinetic_J(v);
    Eigen::VectorXd u_new = p.project(u);
    Eigen::VectorXd v_new = o_.project_fields == FieldProjection::displacement_and_velocity ? p.project(v) : v;
    rec.misfit_u = p.relative_misfit(u, u_new);
    rec.misfit_v = p.relative_misfit(v, v_new);
    u = std::move(u_new);
    v = std::move(v_new);
    kinetic_jump_J_ += kinetic_J(v) - ke_before;
  }
  projections_.push_back(rec);
}

bool DynamicCracks::advance(double t_s, Eigen::VectorXd& u, Eigen::VectorXd& v, const std::vector<PointState>& states) {
  for (std::size_t k = 0; k < points_.size(); ++k) points_[k].w_hist_m = std::max(points_[k].w_hist_m, opening_m(k, u));
  if (calls_++ % o_.check_every != 0) return false;
  const std::vector<Critical> critical = critical_points(states);
  if (critical.empty()) return false;
  bool changed = false;
  // The energies before a change depend only on u and the state, which an attempt changes only when it
  // is kept: computed once per kept state, not per attempt (most attempts - every tip, every critical
  // point - change nothing). The same sums in the same order as before, so the same bits.
  bool have_before = false;
  double stored_before = 0, dissipated_before = 0, e_before = 0;
  // one change at a time, each kept only if every point still gets shape functions (see the header)
  const auto attempt = [&](const auto& change, std::int64_t point) {
    if (!have_before) {
      stored_before = stored_J(u), dissipated_before = dissipated_J();
      e_before = 0.5 * u.dot(model_->internal_force(u)) + stored_before + dissipated_before;
      have_before = true;
    }
    // what to restore from; a change only appends face points (add_face_segment), so their count is enough
    const CrackSet cracks_before = *cracks_;
    const std::size_t points_before = points_.size();
    const auto tips_before = tips_;
    const std::size_t events_before = events_.size(), laws_before = laws_.size();
    if (!change()) return;
    std::vector<ShapeFunctions> shape_before;  // the change moved the CrackSet only: these are still the old ones
    if (o_.project_fields != FieldProjection::none) shape_before = model_->shape_functions();
    try {
      refresh();
      if (o_.project_fields != FieldProjection::none) project(shape_before, t_s, u, v);
      // the new faces start at the jump the cut approximation shows there (header: w_birth)
      for (std::size_t k = points_before; k < points_.size(); ++k) points_[k].w_birth_m = opening_m(k, u);
      // older faces whose opening the cut moved past their history: committed now, into the jump
      for (std::size_t k = 0; k < points_before; ++k) points_[k].w_hist_m = std::max(points_[k].w_hist_m, opening_m(k, u));
      const double stored_after = stored_J(u), dissipated_after = dissipated_J();
      energy_jump_J_ += 0.5 * u.dot(model_->internal_force(u)) + stored_after + dissipated_after - e_before;
      faces_jump_J_ += stored_after + dissipated_after - (stored_before + dissipated_before);
      changed = true;
      have_before = false;  // a new state: the next attempt's energies are its own
    } catch (const InputError&) {
      cracks_->restore(cracks_before);  // a new version: the model recomputes what it had
      points_.resize(points_before);  // the older points' shape functions: the refresh below recomputes them
      tips_ = tips_before;
      events_.resize(events_before);
      laws_.resize(laws_before);
      refused_.push_back({t_s, point});
      refused_points_.insert(point);
      refresh();  // the geometry that held before: succeeds as it did then
    }
  };
  const std::size_t existing = cracks_->cracks().size();
  for (std::size_t k = 0; k < existing; ++k)
    for (bool at_end : {false, true}) {
      if (k < cracks_->cracks().size()) attempt([&] { return grow_tip(k, at_end, t_s, critical); }, -1);
    }
  for (const Critical& q : critical)
    if (!refused_points_.count(q.point)) attempt([&] { return initiate(q, t_s); }, q.point);
  return changed;
}

double DynamicCracks::opening_m(std::size_t k, const Eigen::VectorXd& u) const {
  const auto& p = points_[k];
  Vec2 jump = Vec2::Zero();
  for_jump(p, [&](std::int32_t node, double c) { jump += c * Vec2(u[2 * node], u[2 * node + 1]); });
  return jump.dot(p.normal) - p.w_birth_m;
}

void DynamicCracks::add_forces(const Eigen::VectorXd& u, Eigen::VectorXd& f) const {
  const double t = model_->material().thickness_m;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const auto& p = points_[k];
    const double w = opening_m(k, u);
    double traction = 0;
    if (p.law >= 0)
      traction = cohesive_response(*laws_[std::size_t(p.law)], w, p.w_hist_m, p.w_initial_m).traction_Pa;
    else if (w < 0)
      traction = k_ * w;  // contact of traction-free faces
    if (traction == 0) continue;
    const double tw = traction * t * p.length_weight_m;
    for_jump(p, [&](std::int32_t node, double c) {
      f[2 * node] += c * p.normal.x() * tw;
      f[2 * node + 1] += c * p.normal.y() * tw;
    });
  }
}

Eigen::SparseMatrix<double> DynamicCracks::stiffness_bound() const {
  const double t = model_->material().thickness_m;
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<std::pair<std::int32_t, double>> coeff;
  for (const auto& p : points_) {
    coeff.clear();
    for_jump(p, [&](std::int32_t node, double c) { coeff.emplace_back(node, c); });
    const double kt = k_ * t * p.length_weight_m;  // every point at the penalty: the secants are below it
    for (const auto& [a, ca] : coeff)
      for (const auto& [b, cb] : coeff)
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j) triplets.emplace_back(2 * a + i, 2 * b + j, ca * cb * p.normal[i] * p.normal[j] * kt);
  }
  const auto n = Eigen::Index(model_->dof_count());
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(triplets.begin(), triplets.end());
  return K;
}

double DynamicCracks::dissipated_J() const {
  const double t = model_->material().thickness_m;
  double total = 0;
  for (const auto& p : points_)
    if (p.law >= 0)
      total += cohesive_dissipated_J_m2(*laws_[std::size_t(p.law)], p.w_hist_m, p.w_initial_m) * t * p.length_weight_m;
  return total;
}

double DynamicCracks::stored_J(const Eigen::VectorXd& u) const {
  const double t = model_->material().thickness_m;
  double total = 0;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const auto& p = points_[k];
    const double w = opening_m(k, u);
    double e = 0;
    if (w < 0) {
      e = 0.5 * k_ * w * w;  // the contact penalty (cohesive_response's closed branch is k too)
    } else if (p.law >= 0) {  // on the secant through the origin (the envelope's point when w > w_hist)
      const double wh = std::max(p.w_hist_m, w);
      e = 0.5 * laws_[std::size_t(p.law)]->traction_Pa(wh) / wh * w * w;
    }
    total += e * t * p.length_weight_m;
  }
  return total;
}

}  // namespace mesowave::efg
