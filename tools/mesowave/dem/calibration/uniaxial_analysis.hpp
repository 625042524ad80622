#pragma once
// Virtual lab tests on a packing: the concrete paper's uniaxial compression of
// the cube between two frictionless walls (Section 4.2, Table 2; flowchart step
// 6) and the rod paper's quasi-static tension of a chain (Section 3, Table 1).
// A scene's [test] table names the sensors that make up the test; this file
// turns their signals into what a lab reports, with the lab's definitions:
//   stress  sigma = P / A, P the mean of the platen forces, A the loaded area;
//   strain  eps   = the mean of the axial extensometers (compression positive
//                   in a compression test), eps_l that of the lateral ones;
//   E_glob  the secant between two stress levels on the loading branch,
//           (sigma_a - sigma_b) / (eps(sigma_a) - eps(sigma_b)) - EN 12390-13
//           takes its secant between sigma_b (0.10-0.15 f_c) and sigma_a = f_c/3,
//           so the default levels are 10 % and 1/3 of the peak - and a
//           least-squares slope over the same range;
//   nu_glob -(eps_l(sigma_a) - eps_l(sigma_b)) / (eps(sigma_a) - eps(sigma_b));
//   I       the inertial number eps_dot d sqrt(rho_p / sigma), d the mean sphere
//           diameter: below 1e-4 the loading is quasi-static (the paper keeps it
//           there); evaluated where the modulus is read, from sigma_b to the peak.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/signal/signal.hpp"

namespace mesowave::dem {

struct UniaxialTestSpec {
  enum class Kind { none, compression, tension } kind = Kind::none;
  std::vector<std::string> load;     ///< force sensors (platen reactions), averaged
  std::vector<std::string> axial;    ///< extensometers along the load, averaged
  std::vector<std::string> lateral;  ///< extensometers across it (nu needs them)
  std::string broken_bonds;          ///< a broken-bond counter (optional)
  double area_m2 = 0;                ///< loaded area; 0: from the packing (Simulation)
  double levels[2] = {0.10, 1.0 / 3.0};  ///< modulus levels: fractions of the peak ...
  bool levels_absolute = false;      ///< ... or stresses [Pa]
  double stop_drop = 0;              ///< stop once sigma < (1 - stop_drop) x peak (0: never) ...
  double stop_armed_above_Pa = 0;    ///< ... counting peaks above this stress only (a machine's break detection)
  double stop_at_Pa = 0;             ///< stop once sigma reaches this (0: never): an elastic run
  double inertial_number_bound = 1e-4;  ///< 0: not checked

  bool active() const { return kind != Kind::none; }
  std::string kind_name() const { return kind == Kind::compression ? "compression" : kind == Kind::tension ? "tension" : "none"; }
  /// The test's sensors must sample together: all names, in the order load, axial, lateral, broken_bonds.
  std::vector<std::string> sensor_names() const;
};

/// What the simulation knows about the specimen that the analysis needs.
struct UniaxialTestSpecimen {
  double area_m2 = 0;               ///< loaded area
  double grain_diameter_m = 0;      ///< mean sphere diameter (inertial number)
  double particle_density_kg_m3 = 0;
};

/// Decides, after each step, whether the test is over (the stop rules of the spec).
class UniaxialTestMonitor {
public:
  UniaxialTestMonitor(const UniaxialTestSpec& spec, double area_m2) : spec_(spec), area_(area_m2) {}
  /// `loads`: the latest force of each load sensor [N]. Returns true to stop.
  bool stop_after(const std::vector<double>& loads);
  std::string reason() const { return reason_; }
  double peak_Pa() const { return peak_; }
  /// Continues a test whose stress has reached `peak_Pa` so far (a restarted run).
  void resume(double peak_Pa) { peak_ = peak_Pa; }

private:
  UniaxialTestSpec spec_;
  double area_;
  double peak_ = 0;
  std::string reason_;
};

struct UniaxialTestResult {
  std::string kind;
  double area_m2 = 0;
  // Curves, one point per sample of the test's sensors.
  std::vector<double> time_s, stress_Pa, axial_strain, lateral_strain, broken_bonds;
  // Peak.
  std::size_t peak_index = 0;
  double peak_stress_Pa = 0, strain_at_peak = 0, time_at_peak_s = 0;
  bool peak_reached = false;        ///< the stress fell after its maximum (false: still rising at the end)
  // Modulus and Poisson's ratio.
  double sigma_b_Pa = 0, sigma_a_Pa = 0, eps_b = 0, eps_a = 0;
  double E_secant_Pa = 0;
  std::optional<double> nu_secant;
  double E_fit_Pa = 0, E_fit_r2 = 0;
  std::optional<double> nu_fit;
  std::size_t fit_points = 0;
  // Loading.
  double strain_rate_1_s = 0;       ///< mean axial strain rate from sigma_b to sigma_a
  double inertial_number_max = 0;   ///< from sigma_b to the peak
  double inertial_number_bound = 0;
  std::size_t broken_bonds_at_peak = 0, broken_bonds_final = 0;
  std::vector<std::string> notes;
};

/// InputError when a sensor is missing, the curve never reaches the upper
/// modulus level, the strain does not grow with the stress, or the inertial
/// number exceeds its bound (the loading was not quasi-static).
UniaxialTestResult analyse_uniaxial_test(const std::vector<signal::Signal>& signals, const UniaxialTestSpec& spec,
                                         const UniaxialTestSpecimen& specimen);

/// The curves as CSV: t_s, stress_MPa, axial_strain, lateral_strain, broken_bonds.
std::string uniaxial_curves_csv(const UniaxialTestResult& r);
/// The curves as signals (stress [Pa], axial and lateral strain, broken bonds) for the signal file.
std::vector<signal::Signal> uniaxial_curve_signals(const UniaxialTestResult& r);

}  // namespace mesowave::dem
