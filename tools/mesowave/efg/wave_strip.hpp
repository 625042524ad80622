#pragma once
// The linear check of the explicit EFG solver (docs/efg.md "Explicit dynamics"; shock paper
// Section 4.2 sets up the same bar for the shock): a strip [0, L] x [0, W] in plane strain with
// rollers on its long sides (v = 0 on y = 0 and y = W, weak edge rows of efg/constraints), so the
// state is uniaxial strain and a pressure p(t) on the end x = 0 travels at
//   c_p = sqrt(M / rho),  M = E (1 - nu) / ((1 + nu)(1 - 2 nu))   (the P-wave modulus)
// with sigma_xx(x, t) = -p(t - x / c_p) and v_x = p(t - x / c_p) / (rho c_p) until the reflection
// from the free end x = L returns. Sensors on the centre line y = W / 2.
//
// The numerical dispersion of the discretisation, from the stencil of an interior node I of a
// regular grid (the plane wave u_x = U exp(i k x), u_y = 0, uniform in y, which the grid's mirror
// symmetry in y decouples): omega^2(k) = sum_J K^xx_IJ cos(k (x_J - x_I)) / m_I, the lumped mass m_I;
// the phase speed omega / k against c_p (-> 1 as k h -> 0). The semi-discrete relation: the central
// difference adds its own (sin(omega dt / 2) = omega_h dt / 2, a speed-up that partly cancels the
// spatial lag); `with_time_step` reports both.
#include <string>
#include <vector>

#include "mesowave/efg/explicit_dynamics.hpp"
#include "mesowave/efg/mls.hpp"

namespace mesowave::efg {

struct WaveStripOptions {
  double length_m = 1.0, width_m = 0.05, spacing_m = 5e-3, thickness_m = 1.0;
  double E_Pa = 30e9, nu = 0.2, density_kg_m3 = 2400;
  MlsOptions mls{};
  double support_scale = 2.5;  ///< h_i = scale x spacing (MLS)
  int gauss = 2;               ///< per cell direction (the paper's 2 x 2)
  bool rollers = true;         ///< v = 0 on the long sides (uniaxial strain); false: free sides
  std::string pulse = "triangular";  ///< triangular | friedlander (efg/pressure_load)
  TriangularPulse triangular{100e6, 10e-6, 10e-6, 0};  ///< 100 MPa, 10 us rise, 10 us fall
  FriedlanderPulse friedlander{100e6, 20e-6, 1.0, 0};
  PressureHistory custom;  ///< when set, used instead of `pulse` (tests: a Hann burst)
  std::vector<double> sensor_x_m;  ///< on y = W / 2; default: L/4, L/2, 3L/4
  DynamicsOptions dynamics{};      ///< duration 0: the time the wave takes to the end and 10 % more
  const PointMaterial* material = nullptr;  ///< null: LinearElasticPoint of (E, nu)

  /// p(t) on x = 0: `custom` when set, else the `pulse` chosen (validated). InputError for another name.
  PressureHistory pressure() const;
  /// When that p(t) peaks: start + rise (triangular), the arrival (friedlander); 0 for `custom`.
  double pulse_peak_time_s() const;
};

struct DispersionPoint {
  double kh = 0;               ///< wavenumber x spacing, in (0, pi]
  double phase_speed_ratio = 0;  ///< (omega / k) / c_p, space only
  double with_time_step = 0;     ///< the same with the central difference at `dt` (0 if unstable)
};
/// The stencil's dispersion relation (see above) of a regular grid with `o`'s spacing and MLS, at
/// the wavenumbers `kh` (times the spacing; each in (0, pi]) and the time step `dt_s` (0: none).
std::vector<DispersionPoint> stencil_dispersion(const WaveStripOptions& o, const std::vector<double>& kh, double dt_s);

struct WaveStripResult {
  DynamicsResult run;
  std::vector<Sensor> sensors;
  double c_p_m_s = 0, P_modulus_Pa = 0;
  std::size_t nodes = 0, points = 0;
  double pulse_peak_time_s = 0;  ///< when p(t) peaks at x = 0
  std::vector<double> peak_time_s;  ///< per sensor: time of the largest -sigma_xx before the reflection
  std::vector<double> peak_stress_Pa;  ///< per sensor: that -sigma_xx
  double peak_speed_m_s = 0;     ///< (x_last - x_first) / (t_peak,last - t_peak,first)
  double peak_speed_error = 0;   ///< peak_speed / c_p - 1
  double setup_s = 0;            ///< MLS, mass, stable step
};

/// Builds the strip and runs it. InputError for bad sizes, material, pulse or dynamics options
/// (one line each), a sensor outside the strip, fewer than 2 cells across.
WaveStripResult run_wave_strip(const WaveStripOptions& o);
/// Peak time (parabola through the largest sample and its neighbours) of `values` sampled at `t`,
/// over t < t_max.
double peak_time(const std::vector<double>& t, const std::vector<double>& values, double t_max);

}  // namespace mesowave::efg
