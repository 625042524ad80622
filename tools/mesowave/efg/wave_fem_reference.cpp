#include "mesowave/efg/wave_fem_reference.hpp"

#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/fem/model.hpp"
#include "mesowave/fem/solver.hpp"

namespace mesowave::efg {

double continuum_velocity_m_s(const WaveStripOptions& o, double c, double x, double t) {
  const PressureHistory p = o.pressure();
  const auto at = [&](double tau) { return tau < 0 ? 0.0 : p(tau); };
  return (at(t - x / c) + at(t - (2 * o.length_m - x) / c)) / (o.density_kg_m3 * c);
}

FemBarReference fem_bar_reference(const WaveStripOptions& o, const signal::HannBurst& burst, const WaveStripResult& efg) {
  const double h = o.spacing_m;
  fem::FemModel m = fem::box_hexahedra({o.E_Pa, o.nu, o.density_kg_m3}, {o.length_m, h, h}, h);
  for (std::size_t d = 0; d < m.dof_count(); ++d)
    if (d % 3 != 0) m.fixed[d] = 1;  // u_y = u_z = 0: uniaxial strain, as the strip's rollers
  fem::BurstLoad load{{}, signal::HannBurst(burst.centre_frequency_hz(), burst.cycles(), burst.amplitude() * h * h)};
  for (const auto& [node, w] : fem::surface_patch(m, 0, 0.0, {0, h / 2, h / 2}, INFINITY))
    load.dof_weights.emplace_back(node * 3, w);  // the x dof of each face node
  FemBarReference ref;
  std::vector<fem::Probe> probes;
  for (const Sensor& s : efg.sensors) {
    const std::size_t node = m.nearest_node({s.x.x(), 0, 0});
    // the EFG sensor and the FEM node must be the same point for one closed form to judge both
    if (std::abs(m.position(node)[0] - s.x.x()) > 1e-9 * o.length_m)
      throw InputError("--fem-reference: sensor x (" + format_quantity(s.x.x(), "m") +
                       ") must lie on a node of the FEM bar (a multiple of the spacing " + format_quantity(h, "m") + ")");
    ref.sensor_x_m.push_back(m.position(node)[0]);
    probes.push_back({s.name, node * 3, fem::MotionQuantity::velocity, "x", 1.0});
  }
  fem::ExplicitOptions fo;
  fo.dt_s = 0.9 * m.stable_dt();
  fo.steps = std::int64_t(std::ceil(efg.run.t_end_s / fo.dt_s)) + 1;
  const fem::ExplicitResult fr = fem::run_explicit(m, load, probes, fo);
  ref.elements = m.element_count();
  ref.dt_s = fo.dt_s;
  ref.wall_s = fr.wall_s;
  const auto& t = efg.run.sample_t_s;
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const auto& fv = fr.signals[k].samples;
    std::vector<double> v;
    double peak = 0, e_efg = 0, e_fem = 0, e_between = 0;
    std::size_t n = 0;
    for (double tt = 0; tt < efg.run.t_end_s; tt += 0.1 * fo.dt_s)
      peak = std::max(peak, std::abs(continuum_velocity_m_s(o, efg.c_p_m_s, ref.sensor_x_m[k], tt)));
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double s = t[i] / fo.dt_s;  // the FEM's samples at n dt, linearly between them
      const auto s0 = std::size_t(s);
      if (s0 + 1 >= fv.size()) {
        v.push_back(NAN);
        continue;
      }
      const double vf = fv[s0] + (s - double(s0)) * (fv[s0 + 1] - fv[s0]);
      v.push_back(vf);
      const double exact = continuum_velocity_m_s(o, efg.c_p_m_s, ref.sensor_x_m[k], t[i]);
      const double ve = efg.run.sensors[k][i].velocity_m_s[0];
      e_efg += (ve - exact) * (ve - exact), e_fem += (vf - exact) * (vf - exact), e_between += (ve - vf) * (ve - vf);
      ++n;
    }
    const double norm = n > 0 && peak > 0 ? 1 / (peak * std::sqrt(double(n))) : NAN;
    ref.efg_error.push_back(std::sqrt(e_efg) * norm);
    ref.fem_error.push_back(std::sqrt(e_fem) * norm);
    ref.efg_fem_difference.push_back(std::sqrt(e_between) * norm);
    ref.v_x_m_s.push_back(std::move(v));
  }
  return ref;
}

}  // namespace mesowave::efg
