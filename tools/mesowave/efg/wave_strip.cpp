#include "mesowave/efg/wave_strip.hpp"

#include <chrono>
#include <cmath>
#include <optional>

#include "mesowave/core/check.hpp"

namespace mesowave::efg {

namespace {

ElasticMaterial2D strip_material(const WaveStripOptions& o) {
  ElasticMaterial2D m{o.E_Pa, o.nu, o.thickness_m, o.density_kg_m3, PlaneState::plane_strain};
  m.validate();
  require_positive("density", o.density_kg_m3, "kg/m3");
  return m;
}

double p_wave_modulus(const WaveStripOptions& o) { return o.E_Pa * (1 - o.nu) / ((1 + o.nu) * (1 - 2 * o.nu)); }

}  // namespace

std::vector<DispersionPoint> stencil_dispersion(const WaveStripOptions& o, const std::vector<double>& khs, double dt_s) {
  require_positive("spacing", o.spacing_m, "m");
  for (double kh : khs)
    if (!(kh > 0 && kh <= M_PI)) throw InputError("wavenumber k h (" + format_number(kh) + ") must lie in (0, pi]");
  // A square patch wide enough that the centre node's row is the infinite grid's: every node within
  // two support radii of it present (the shape functions at its points depend on those).
  const int half = int(std::ceil(2 * o.support_scale)) + 2;
  const int cells = 2 * half;
  const double h = o.spacing_m;
  const Discretisation disc = rectangular_grid({0, 0, cells * h, cells * h}, cells, cells, o.gauss);
  const MlsApproximation mls(disc.nodes, support_radii_by_spacing(disc.nodes, h, o.support_scale), o.mls);
  const ElasticModel model(disc, strip_material(o), mls);
  const Eigen::VectorXd m = lumped_mass(model);
  const Eigen::SparseMatrix<double> K = model.stiffness();
  const std::size_t I = std::size_t(half) * std::size_t(cells + 1) + std::size_t(half);  // centre node
  const double c_p = std::sqrt(p_wave_modulus(o) / o.density_kg_m3);
  std::vector<DispersionPoint> out;
  for (double kh : khs) {
    const double k = kh / h;
    double k_hat = 0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, Eigen::Index(2 * I)); it; ++it)
      if (it.row() % 2 == 0)  // K^xx_JI (symmetric)
        k_hat += it.value() * std::cos(k * (disc.nodes[std::size_t(it.row() / 2)].x() - disc.nodes[I].x()));
    const double omega = std::sqrt(std::max(0.0, k_hat / m[Eigen::Index(I)]));
    DispersionPoint d{kh, omega / k / c_p, 0};
    if (dt_s > 0 && omega * dt_s / 2 <= 1) d.with_time_step = 2 / dt_s * std::asin(omega * dt_s / 2) / k / c_p;
    out.push_back(d);
  }
  return out;
}

double peak_time(const std::vector<double>& t, const std::vector<double>& values, double t_max) {
  std::size_t best = 0;
  for (std::size_t i = 0; i < t.size() && t[i] < t_max; ++i)
    if (values[i] > values[best]) best = i;
  if (best == 0 || best + 1 >= t.size()) return t.empty() ? 0.0 : t[best];
  const double a = values[best - 1], b = values[best], c = values[best + 1];
  const double den = a - 2 * b + c;
  const double shift = den != 0 ? 0.5 * (a - c) / den : 0.0;  // vertex of the parabola, in samples
  const double dt = 0.5 * (t[best + 1] - t[best - 1]);
  return t[best] + shift * dt;
}

PressureHistory WaveStripOptions::pressure() const {
  if (custom) return custom;
  if (pulse == "triangular") {
    triangular.validate();
    return triangular;
  }
  if (pulse == "friedlander") {
    friedlander.validate();
    return friedlander;
  }
  throw InputError("pulse '" + pulse + "' must be triangular or friedlander");
}

double WaveStripOptions::pulse_peak_time_s() const {
  if (custom) return 0;
  return pulse == "friedlander" ? friedlander.start_s : triangular.start_s + triangular.rise_s;
}

WaveStripResult run_wave_strip(const WaveStripOptions& o) {
  require_positive("strip length", o.length_m, "m");
  require_positive("strip width", o.width_m, "m");
  require_positive("node spacing", o.spacing_m, "m");
  const ElasticMaterial2D material = strip_material(o);
  const int nx = std::max(1, int(std::lround(o.length_m / o.spacing_m)));
  const int ny = int(std::lround(o.width_m / o.spacing_m));
  if (ny < 2)
    throw InputError("strip width (" + format_quantity(o.width_m, "m") + ") must hold at least 2 node spacings (" +
                     format_quantity(o.spacing_m, "m") + ")");
  const PressureHistory pressure = o.pressure();
  const double pulse_peak = o.pulse_peak_time_s();
  WaveStripResult r;
  r.P_modulus_Pa = p_wave_modulus(o);
  r.c_p_m_s = std::sqrt(r.P_modulus_Pa / o.density_kg_m3);
  r.pulse_peak_time_s = pulse_peak;
  std::vector<double> xs = o.sensor_x_m;
  if (xs.empty()) xs = {0.25 * o.length_m, 0.5 * o.length_m, 0.75 * o.length_m};
  for (double x : xs)
    if (!std::isfinite(x) || x < 0 || x > o.length_m)
      throw InputError("sensor x (" + format_quantity(x, "m") + ") must lie on the strip [0, " +
                       format_quantity(o.length_m, "m") + "]");

  const auto start = std::chrono::steady_clock::now();
  const Rect body{0, 0, o.length_m, o.width_m};
  const Discretisation disc = rectangular_grid(body, nx, ny, o.gauss);
  const MlsApproximation mls(disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, o.support_scale), o.mls);
  const ElasticModel model(disc, material, mls);
  std::optional<ConstraintSet> rollers;
  if (o.rollers) {
    const auto zero = [](const Vec2&) { return 0.0; };
    rollers.emplace(model, std::vector<PointConstraint>{},
                    std::vector<EdgeConstraint>{{{Vec2(0, 0), Vec2(o.length_m, 0)}, 1, zero, "roller y = 0"},
                                                {{Vec2(0, o.width_m), Vec2(o.length_m, o.width_m)}, 1, zero, "roller y = W"}});
  }
  const LinearElasticPoint linear(material);
  const PointMaterial& law = o.material ? *o.material : linear;
  // The end x = 0, walked from (0, W) to (0, 0): the body on its left.
  const ExplicitDynamics dyn(model, law, rollers ? &*rollers : nullptr, {{{Vec2(0, o.width_m), Vec2(0, 0)}, pressure, "end x = 0"}});
  r.setup_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.nodes = disc.nodes.size();
  r.points = disc.points.size();
  for (std::size_t k = 0; k < xs.size(); ++k)
    r.sensors.push_back({"x" + std::to_string(k), Vec2(xs[k], 0.5 * o.width_m)});
  DynamicsOptions d = o.dynamics;
  if (d.duration_s == 0) d.duration_s = 1.1 * o.length_m / r.c_p_m_s + pulse_peak;
  r.run = dyn.run(d, r.sensors);

  for (std::size_t k = 0; k < xs.size(); ++k) {
    std::vector<double> compression;
    for (const SensorSample& s : r.run.sensors[k]) compression.push_back(-s.stress_Pa[0]);
    const double t_max = (2 * o.length_m - xs[k]) / r.c_p_m_s;  // the reflection from x = L
    r.peak_time_s.push_back(peak_time(r.run.sample_t_s, compression, t_max));
    double peak = 0;
    for (std::size_t i = 0; i < compression.size() && r.run.sample_t_s[i] < t_max; ++i) peak = std::max(peak, compression[i]);
    r.peak_stress_Pa.push_back(peak);
  }
  if (xs.size() >= 2 && r.peak_time_s.back() != r.peak_time_s.front()) {
    r.peak_speed_m_s = (xs.back() - xs.front()) / (r.peak_time_s.back() - r.peak_time_s.front());
    r.peak_speed_error = r.peak_speed_m_s / r.c_p_m_s - 1;
  }
  return r;
}

}  // namespace mesowave::efg
