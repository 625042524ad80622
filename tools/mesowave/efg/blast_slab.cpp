#include "mesowave/efg/blast_slab.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/efg/discretisation.hpp"

namespace mesowave::efg {

namespace {

double p_wave_modulus(const ElasticMaterial2D& m) { return m.E_Pa * (1 - m.nu) / ((1 + m.nu) * (1 - 2 * m.nu)); }

/// The part of a -> b inside the rectangle (Liang-Barsky); false when none.
bool clip_to(const Rect& r, Vec2& a, Vec2& b) {
  double t0 = 0, t1 = 1;
  const Vec2 d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - r.x0, r.x1 - a.x(), a.y() - r.y0, r.y1 - a.y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
  }
  if (t0 >= t1) return false;
  const Vec2 a0 = a;
  a = a0 + t0 * d;
  b = a0 + t1 * d;
  return true;
}

std::vector<Vec2> clip_polyline(const Rect& r, const std::vector<Vec2>& line) {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    Vec2 a = line[i], b = line[i + 1];
    if (!clip_to(r, a, b)) continue;
    if (out.empty() || (out.back() - a).norm() > 1e-12) out.push_back(a);
    out.push_back(b);
  }
  return out;
}

// The DynamicsCracks hook of the run: DynamicCracks itself, and around it what the slab reports - the
// faces' work by the run's rule (header), the cracks' energies at the run's samples, the crack polylines
// and the Gauss points' volumetric strains at the run's snapshots, the points' final states.
class RecordedCracks final : public DynamicsCracks {
 public:
  RecordedCracks(DynamicCracks& cracks, const ElasticModel& model, const BlastSlabOptions& o, const Rect& body,
                 double crushing_eps_v)
      : c_(cracks), model_(model), o_(o), body_(body), crushing_eps_v_(crushing_eps_v) {}

  void add_forces(const Eigen::VectorXd& u, Eigen::VectorXd& f) const override {
    f_faces_ = Eigen::VectorXd::Zero(f.size());
    c_.add_forces(u, f_faces_);
    f += f_faces_;
  }

  void start(const Eigen::VectorXd& mass_per_node) override { c_.start(mass_per_node); }

  bool advance(double t_s, Eigen::VectorXd& u, Eigen::VectorXd& v, const std::vector<PointState>& states) override {
    // W_faces += f^n . (dt_n / 2)(v^{n-1/2} + v^{n+1/2}), the run's rule (explicit_dynamics.hpp), with the
    // run's own half-step velocities (v^{-1/2} = 0; v^{n-1/2} as the last advance left it, projected or not)
    const double dt_half = t_s - t_n_;
    const double dt_avg = n_ == 0 ? 0.5 * dt_half : 0.5 * (dt_prev_ + dt_half);
    if (n_ == 0) v_prev_ = Eigen::VectorXd::Zero(v.size());
    faces_work_J_ += f_faces_.dot(Eigen::VectorXd((0.5 * dt_avg) * (v_prev_ + v)));
    const bool last = t_s >= o_.duration_s;
    if (o_.snapshot_stride > 0 && (n_ % o_.snapshot_stride == 0 || last)) {  // the run's snapshot of step n
      snapshot_cracks_.push_back(cracks_now());
      snapshot_points_.push_back(points_now(states));
    }
    const bool changed = c_.advance(t_s, u, v, states);
    v_prev_ = v;
    if (n_ % o_.sample_stride == 0 || last)
      samples_.push_back({0.5 * (t_n_ + t_s), faces_work_J_, c_.dissipated_J(), c_.stored_J(u), c_.energy_jump_J(), c_.faces_jump_J()});
    if (last) final_points_ = points_now(states, &final_crater_);
    dt_prev_ = dt_half;
    t_n_ = t_s;
    ++n_;
    return changed;
  }

  Eigen::SparseMatrix<double> stiffness_bound() const override { return c_.stiffness_bound(); }

  struct Sample {
    double t_s, faces_work_J, dissipated_J, stored_J, energy_jump_J, faces_jump_J;
  };
  const std::vector<Sample>& samples() const { return samples_; }
  const std::vector<CrackSnapshot>& snapshot_cracks() const { return snapshot_cracks_; }
  const std::vector<GaussPointSnapshot>& snapshot_points() const { return snapshot_points_; }
  const GaussPointSnapshot& final_points() const { return final_points_; }
  const CraterMeasure& final_crater() const { return final_crater_; }

  CrackSnapshot cracks_now() const {
    CrackSnapshot s;
    for (const Crack& k : c_.cracks().cracks()) {
      auto line = clip_polyline(body_, k.points);
      if (line.size() >= 2) s.polylines.push_back(std::move(line));
    }
    return s;
  }

 private:
  GaussPointSnapshot points_now(const std::vector<PointState>& states, CraterMeasure* crater = nullptr) const {
    GaussPointSnapshot g;
    const auto& pts = model_.discretisation().points;
    CraterInput in{body_, {}, {}, {}, c_.open_segments(), o_.spacing_m, crushing_eps_v_};
    for (std::size_t k = 0; k < states.size(); ++k) {
      g.x.push_back(pts[k].x);
      g.eps_v.push_back(volumetric_strain(states[k].strain, model_.material()));
      g.min_eps_v.push_back(states[k].min_eps_v);
      g.max_Y.push_back(states[k].max_Y);
      in.area_m2.push_back(pts[k].weight_m2);
    }
    in.x = g.x;
    in.min_eps_v = g.min_eps_v;
    CraterMeasure m = measure_crater(in);
    g.crater = m.label;
    if (crater) *crater = std::move(m);
    return g;
  }

  DynamicCracks& c_;
  const ElasticModel& model_;
  const BlastSlabOptions& o_;
  Rect body_;
  double crushing_eps_v_;
  CraterMeasure final_crater_;
  mutable Eigen::VectorXd f_faces_;
  Eigen::VectorXd v_prev_;
  double t_n_ = 0, dt_prev_ = 0, faces_work_J_ = 0;
  std::int64_t n_ = 0;
  std::vector<Sample> samples_;
  std::vector<CrackSnapshot> snapshot_cracks_;
  std::vector<GaussPointSnapshot> snapshot_points_;
  GaussPointSnapshot final_points_;
};

}  // namespace

bool clip_segment_to(const Rect& r, Vec2& a, Vec2& b) { return clip_to(r, a, b); }

double ContactCharge::cj_pressure_Pa() const { return density_kg_m3 * detonation_velocity_m_s * detonation_velocity_m_s / (gamma + 1); }

void BlastSlabOptions::validate() const {
  require_positive("slab span", span_m, "m");
  require_positive("slab thickness", thickness_m, "m");
  require_positive("node spacing", spacing_m, "m");
  if (thickness_m < 4 * spacing_m)
    throw InputError("slab thickness (" + format_quantity(thickness_m, "m") + ") must hold at least 4 node spacings (" +
                     format_quantity(spacing_m, "m") + ")");
  if (!(support_scale >= 1.5 && support_scale <= 5))
    throw InputError("support scale (" + format_number(support_scale) + ") must lie in [1.5, 5] spacings");
  concrete.validate();
  require_positive("concrete density", concrete.density_kg_m3, "kg/m3");
  hugoniot.validate();
  cracks.validate();
  viscosity.validate();
  require_positive("charge width", charge.width_m, "m");
  if (charge.width_m > span_m)
    throw InputError("charge width (" + format_quantity(charge.width_m, "m") + ") must not exceed the span (" +
                     format_quantity(span_m, "m") + ")");
  require_positive("charge thickness", charge.thickness_m, "m");
  require_positive("explosive density", charge.density_kg_m3, "kg/m3");
  require_positive("detonation velocity", charge.detonation_velocity_m_s, "m/s");
  require_positive("gamma of the detonation products", charge.gamma);
  require_positive("fall time in charge transits", charge.fall_transits);
  if (!std::isfinite(charge.peak_Pa) || charge.peak_Pa < 0)
    throw InputError("peak pressure (" + format_quantity(charge.peak_Pa, "Pa") + ") must be >= 0 (0: from the charge)");
  require_positive("duration", duration_s, "s");
  if (!(dt_fraction > 0 && dt_fraction <= 1)) throw InputError("dt fraction (" + format_number(dt_fraction) + ") must lie in (0, 1]");
  if (!(std::isfinite(dt_s) && dt_s >= 0))
    throw InputError("time step (" + format_quantity(dt_s, "s") + ") must be >= 0 (0: the fraction of the stable step)");
  if (sample_stride < 1) throw InputError("sample stride (" + std::to_string(sample_stride) + ") must be >= 1");
  if (snapshot_stride < 0) throw InputError("snapshot stride (" + std::to_string(snapshot_stride) + ") must be >= 0");
  if (!(std::isfinite(crushing_eps_v) && crushing_eps_v >= 0))
    throw InputError("crushing volumetric strain (" + format_number(crushing_eps_v) + ") must be >= 0 (0: the Y-function's minimum)");
}

double hugoniot_threshold_pressure_Pa(const ElasticMaterial2D& concrete, const HugoniotParameters& p) {
  ElasticMaterial2D m = concrete;
  m.state = PlaneState::plane_strain;
  return p_wave_modulus(m) * hugoniot_compression_integral(-p.e_v_th, p);  // P(e_v,th) = e_v,th: Y = 1 up to it
}

TriangularPulse contact_pulse(const ContactCharge& c, const ElasticMaterial2D& concrete) {
  double peak = c.peak_Pa;
  if (peak == 0) {
    const double Zc = concrete.density_kg_m3 * std::sqrt(p_wave_modulus(concrete) / concrete.density_kg_m3);
    const double Ze = c.density_kg_m3 * c.detonation_velocity_m_s;
    peak = 2 * Zc / (Zc + Ze) * c.cj_pressure_Pa();
  }
  const double transit = c.thickness_m / c.detonation_velocity_m_s;
  return TriangularPulse{peak, transit, c.fall_transits * transit, 0.0};
}

BlastSlabResult run_blast_slab(const BlastSlabOptions& o) {
  o.validate();
  const auto start = std::chrono::steady_clock::now();
  ElasticMaterial2D concrete = o.concrete;
  concrete.state = PlaneState::plane_strain;
  BlastSlabResult r;
  r.pulse = contact_pulse(o.charge, concrete);
  r.pulse.validate();
  r.threshold_pressure_Pa = hugoniot_threshold_pressure_Pa(concrete, o.hugoniot);

  const Rect body{0, 0, o.span_m, o.thickness_m};
  const int nx = int(std::lround(o.span_m / o.spacing_m)), ny = int(std::lround(o.thickness_m / o.spacing_m));
  const Discretisation disc = rectangular_grid(body, nx, ny, o.gauss);
  CrackSet cracks;
  const MlsApproximation mls(disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, o.support_scale), {}, &cracks);
  ElasticModel model(disc, concrete, mls);
  const HugoniotElastic law(concrete, o.hugoniot);
  // the top face under the charge, walked right to left (the body below, on its left)
  const double xc = 0.5 * o.span_m, half = 0.5 * o.charge.width_m;
  const ExplicitDynamics dyn(model, law, nullptr,
                             {{{Vec2(xc + half, o.thickness_m), Vec2(xc - half, o.thickness_m)}, r.pulse, "charge"}});
  DynamicCracks dc(model, cracks, o.cracks);
  r.crushing_eps_v = o.crushing_eps_v > 0 ? o.crushing_eps_v : default_crushing_eps_v(o.hugoniot);
  RecordedCracks recorded(dc, model, o, body, r.crushing_eps_v);
  r.nodes = disc.nodes.size();
  r.points = disc.points.size();
  r.penalty_Pa_per_m = dc.penalty_Pa_per_m();
  r.segment_length_m = dc.segment_length_m();
  r.min_spacing_m = dc.min_crack_spacing_m();
  r.min_radius_m = dc.min_crack_radius_m();
  r.max_turn_rad = dc.max_turn_rad();
  r.setup_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  DynamicsOptions d;
  d.duration_s = o.duration_s;
  d.dt_fraction = o.dt_fraction;
  d.dt_s = o.dt_s;
  d.stiffness_check_every = o.stiffness_check_every;
  d.sample_stride = o.sample_stride;
  d.snapshot_stride = o.snapshot_stride;
  d.min_points_per_thread = o.min_points_per_thread;
  d.viscosity = o.viscosity;
  d.progress = o.progress;
  d.cracks = &recorded;
  r.run = dyn.run(d);

  r.events = dc.events();
  r.refused = dc.refused().size();
  r.crack_length_m.assign(dc.cracks().cracks().size(), 0.0);
  for (const CrackEvent& e : r.events) {
    r.crack_length_m[e.crack] += e.length_m;
    if (!e.initiation) r.max_crack_speed_m_s = std::max(r.max_crack_speed_m_s, e.speed_m_s);
  }
  r.crack_polylines = recorded.cracks_now().polylines;

  r.final_points = recorded.final_points();
  r.crater = recorded.final_crater();
  r.open_segments = dc.open_segments();
  const GaussPointSnapshot& g = r.final_points;
  double x_min = INFINITY, x_max = -INFINITY, y_min = INFINITY;
  for (std::size_t k = 0; k < g.x.size(); ++k) {
    r.max_compression_eps_v = std::max(r.max_compression_eps_v, -g.min_eps_v[k]);
    if (!(g.min_eps_v[k] < -o.hugoniot.e_v_th)) continue;
    ++r.compacted_points;
    x_min = std::min(x_min, g.x[k].x()), x_max = std::max(x_max, g.x[k].x()), y_min = std::min(y_min, g.x[k].y());
  }
  if (r.compacted_points > 0) {
    r.compacted_x_min_m = x_min, r.compacted_x_max_m = x_max;
    r.compacted_width_m = x_max - x_min;
    r.compacted_depth_m = o.thickness_m - y_min;
  }
  // the compacted zone's area, and its part joined to the loaded face through compacted points (the crater's
  // flood fill of efg/crater with e_v,th for eps_crush and no cuts): a deep point that a crack's cut marked
  // compacted (docs/efg.md) moves the depth above, not this one
  CraterInput joined{body, g.x, {}, g.min_eps_v, {}, o.spacing_m, o.hugoniot.e_v_th};
  for (const GaussPoint& p : disc.points) joined.area_m2.push_back(p.weight_m2);
  for (std::size_t k = 0; k < g.x.size(); ++k)
    if (g.min_eps_v[k] < -o.hugoniot.e_v_th) r.compacted_area_m2 += joined.area_m2[k];
  if (o.hugoniot.e_v_th > 0) {
    const CraterMeasure m = measure_crater(joined);
    r.compacted_joined_depth_m = m.depth_m, r.compacted_joined_area_m2 = m.area_m2;
  }

  // the run's energy samples and the hook's, taken at the same steps
  const auto& s = recorded.samples();
  if (s.size() != r.run.energy.size())
    throw std::logic_error("blast slab: " + std::to_string(s.size()) + " crack energy samples against the run's " +
                std::to_string(r.run.energy.size()));
  for (std::size_t k = 0; k < s.size(); ++k) {
    const EnergySample& e = r.run.energy[k];
    BlastEnergySample b{e.t_s, e.kinetic_J, e.internal_work_J, e.external_work_J, e.damping_J,
                        s[k].faces_work_J, s[k].dissipated_J, s[k].stored_J, s[k].energy_jump_J, e.kinetic_jump_J,
                        s[k].faces_jump_J, e.viscous_J};
    r.max_abs_balance_J = std::max(r.max_abs_balance_J, std::abs(b.balance_J()));
    r.max_abs_run_balance_J = std::max(r.max_abs_run_balance_J, std::abs(b.run_balance_J()));
    r.energy.push_back(b);
  }
  const auto& sc = recorded.snapshot_cracks();
  const auto& sp = recorded.snapshot_points();
  for (std::size_t k = 0; k < r.run.snapshots.size() && k < sc.size(); ++k)
    r.snapshots.push_back({r.run.snapshots[k].first, r.run.snapshots[k].second, sc[k], sp[k]});
  r.run.snapshots.clear();
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace mesowave::efg
