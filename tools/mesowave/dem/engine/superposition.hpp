#pragma once
// One DEM run for every burst frequency (issue 17 item 1). The leapfrog step
// (model.hpp) on the linearised network (or the axial chain) WITHOUT damping is
// a discrete-time linear time-invariant system in the external forces: with
// f_n the force of step n and h_n a sensor's sample after step n for a unit
// force on step 0 alone (the impulse response),
//
//   y_n = sum_{k=0..n} f_k h_{n-k}                                       (discrete convolution)
//
// is exactly what a direct run with the force f records, up to round-off
// (tests/dem/engine/superposition_test.cpp: ~1e-13 of the peak). So one run per
// actuator with a unit impulse on step 0 gives the signals of every burst.
// Why an impulse and not a broadband burst divided out in the frequency domain:
// the impulse IS the discrete system's response, so the convolution is exact and
// needs no division by a spectrum that is small somewhere (a Hann burst's
// spectrum has zeros), no window and no wrap-around.
//
// Viscous mass-proportional damping (scene.hpp: [model] damping_law = "viscous",
// c = 4 alpha_d f, the same amplitude loss per cycle as Eq. 7 at the burst's
// centre frequency f) is linear, and the damped step is the undamped one
// windowed: the implicit-midpoint update (sphere_system.cpp)
//   (1 + c dt/2) x_{n+1} = 2 x_n - (1 - c dt/2) x_{n-1} + dt^2 M^-1 (f_n - K x_n)
// with x_n = r^n y_n, r = sqrt((1 - c dt/2)/(1 + c dt/2)), is the undamped step for
// y driven by r^-n f_n / s, s = sqrt(1 - (c dt/2)^2), with K shifted by -c^2 M / 4
// (relative frequency alpha_d^2 / (2 pi^2) ~ 5e-6, neglected). So ONE undamped
// run serves every frequency, each with its own c:
//   x_{n+1} = sum_k f_k r^{n-k} X_{n-k} / (1 + c dt/2),   X the undamped displacement response,
// and the velocity and acceleration are its first and second differences over dt,
// as the leapfrog defines them.
//
// The paper's local damping F (1 - alpha_d sgn(F v)) (Eq. 7) is positively
// homogeneous but not additive, so with alpha_d > 0 the superposed signals are
// an approximation whose error is measured, not assumed (docs/benchmarks.md,
// "One run, every frequency"; the record states it and --check-kHz measures it
// in the run itself against one direct run).
//
// Cost: one run per actuator (the step loop, as a direct run), then per
// frequency a direct convolution (signal/superposition.hpp), (samples) x (burst steps) multiply-adds per
// sensor and actuator: for the cube's 30,000 steps, 6 sensors and the 1,000-step
// 100 kHz burst 1.8e8, about 0.1-0.2 s; direct summation in a fixed order keeps
// it exact to round-off and the same bits for any thread count (an FFT would be
// cheaper only for much longer bursts).
//
// Refused (InputError, one line): a scene superposition does not hold for - an
// actuator that is not a force (prescribed motion, walls: constraints and
// one-sided contact), a sensor that is not a linear functional of the motion
// (the magnitude of a vector, forces, strains, broken bonds), a [test], and a
// model that is not linear (the full law: contact detection, breakage, friction).
// The linear model's validity (peak bond force / strength below the scene's
// bound) cannot be measured without the burst run's bond forces, so it is
// bounded, by the lower of two bounds that hold without damping (and with it,
// as dissipation only lowers the stored energy):
//  - the triangle inequality: a bond force of the burst run is sum_k f_k g_{n-k},
//    so its peak is at most sum_k |f_k| times the unit impulse's peak ratio
//    (loose, 40-100x: g is broadband, the burst is not);
//  - energy: leapfrog conserves H = x.K x / 2 + v_{n-1/2}.M v_{n+1/2} / 2, which
//    equals the work W_n = sum_k f_k . (v_{k-1/2} + v_{k+1/2}) dt / 2 the
//    actuators did (their velocities come from the impulse run too). Per mode
//    H = w^2 x^2 (1 - (w dt/2)^2) / 2 + vbar^2 / 2, so the elastic energy, and
//    with it any one bond's F_n^2 / (2 K_n) + |F_s|^2 / (2 a0 K_s), is at most
//    max W / (1 - (dt / dt_eig)^2), dt_eig = 2 / sqrt(lambda_max) (Lanczos).
//    Yade's law with unequal radii is slightly non-symmetric and its energy
//    wanders by ~1e-3 (energy_test.cpp): the bound takes 1 % more energy.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesowave/dem/engine/simulation.hpp"
#include "mesowave/dem/packing/packing.hpp"
#include "mesowave/dem/scene/scene.hpp"
#include "mesowave/signal/signal.hpp"
#include "mesowave/signal/superposition.hpp"

namespace mesowave::dem {

/// Why superposition cannot run `scene` (what is not a linear force input or a
/// linear sensor), or "" if it can (the model is checked by impulse_responses).
std::string superposition_obstacle(const Scene& scene);

/// Every sensor's response to a unit force impulse (1 N on step 0) of each actuator.
struct ImpulseResponses {
  RunReport report;  ///< the last impulse run's (wall_s and steps summed over the runs)
  /// response[a][s][n]: sensor s after step n, actuator a pushing 1 N on step 0, the others nothing.
  std::vector<std::vector<std::vector<double>>> response;
  /// Each sensor's signal as a direct run writes it (name, quantity, unit, t0, dt), without samples.
  std::vector<signal::Signal> layout;
  std::vector<std::int64_t> interval_steps;  ///< each sensor's sampling interval in steps
  std::vector<double> impulse_peak_force_ratio;  ///< per actuator: largest bond force / strength of its unit impulse
  /// actuator_velocity[c][a]: actuator a's mean velocity along its direction, v_{n+1/2}, for the impulse of c.
  std::vector<std::vector<std::vector<double>>> actuator_velocity;
  /// displacement[a][s][n]: sensor s's displacement twin (same spheres and component), x_{n+1} - x_0.
  std::vector<std::vector<std::vector<double>>> displacement;
  /// [model] damping_law viscous: the scene's alpha_d, each frequency's c = 4 alpha_d f (the impulse ran undamped); 0 otherwise.
  double viscous_alpha = 0;
  /// max over bonds of max(K_n / s_n^2, a0 K_s / s_s^2) [1/(N m)], s the strengths T R^2, C R^2
  /// (K_n R for bonds that never break, as the kernels): one bond's (force / strength)^2 <= 2 x this x its energy.
  double bond_compliance_max = 0;
  double wall_s = 0;                         ///< the impulse runs' step loops, in all
};

/// Runs the scene once per actuator with a unit impulse. InputError when
/// superposition_obstacle says why not, or when the model chosen is not linear.
ImpulseResponses impulse_responses(const Scene& scene, const Packing& packing, SimulationOptions options = {});

/// The sensors' signals for the scene's bursts (every actuator's amplitude,
/// cycles and delay as the scene has them) at centre frequency `frequency_hz`.
struct SuperposedRun {
  double frequency_hz = 0;
  std::vector<signal::Signal> signals;  ///< the same samples and times as the direct run's
  double force_l1_N = 0;                ///< sum over actuators and steps of |f_n|
  /// >= the direct run's peak bond force / strength (without damping; the lower of the two bounds):
  double peak_force_ratio_bound = 0;
  double triangle_bound = 0;  ///< sum over actuators of sum_n |f_n| x its impulse's peak ratio
  double energy_bound = 0;    ///< sqrt(2 W_max bond_compliance_max / (1 - (dt / dt_eig)^2)) x 1.005
  double work_max_J = 0;      ///< largest work the bursts have done, W_n = sum_k f_k (v_{k-1/2} + v_{k+1/2}) dt / 2
  double validity_bound = 0;            ///< what it was checked against (0: unbreakable bonds, none)
  bool bound_proves_validity = true;    ///< peak_force_ratio_bound < validity_bound (or no bound)
  double convolution_s = 0;             ///< wall time of the convolutions
  double viscous_damping_1_s = 0;       ///< c = 4 alpha_d f of damping_law viscous (0: none)
};

/// y_n = sum_k f_k h_{n-k} at each sensor's sampled steps, and the bound on the
/// peak bond force / strength (run_superposed refuses a frequency whose bound does
/// not prove the linear model valid unless a direct run there measures it).
SuperposedRun superpose(const ImpulseResponses& responses, const Scene& scene, double frequency_hz);

/// The convolution, the error against a direct run and the file names are
/// generic (signal/superposition.hpp, shared with the FEM's fem/superposition.hpp).
using signal::SuperpositionError;
using signal::superposition_error;
using signal::frequency_text;
using signal::frequency_path;

/// A direct run's comparison with the superposed signals at its frequency.
struct SuperpositionCheck {
  double frequency_hz = 0;
  SuperpositionError error;
  double direct_wall_s = 0;  ///< the direct run's step loop
  double direct_peak_force_ratio = 0;  ///< what the direct run measured (its own validity check passed)
};
nlohmann::ordered_json to_json(const SuperpositionCheck& check);

/// The record of one frequency: the impulse run's summary (run_report.hpp) with
/// the burst's frequency, and "method": "superposition" with its validity:
/// exact (no damping) or the local damping's measured error ("check" at this
/// frequency if a direct run was made there, "checks" all that were made).
nlohmann::ordered_json superposition_summary(const ImpulseResponses& responses, const SuperposedRun& run,
                                             const std::vector<SuperpositionCheck>& checks = {});

/// What mw-dem run --frequencies-kHz does: the impulse runs, the signals of
/// every frequency with its record, and optionally direct runs at some of the
/// frequencies (`check_kHz`) whose measured errors every record states.
struct SuperposedFrequency {
  SuperposedRun run;
  nlohmann::ordered_json summary;  ///< superposition_summary
};
struct SuperposedSet {
  ImpulseResponses responses;
  std::vector<SuperposedFrequency> frequencies;
  std::vector<SuperpositionCheck> checks;
  nlohmann::ordered_json summary;   ///< the whole run: the validity, each frequency's bound and cost
};
/// `check_unproven`: also run directly every frequency whose bound does not prove the
/// linear model valid (the bound depends on the material and packing, so a pipeline
/// cannot list them beforehand); those checks measure the peak, and every record says
/// which frequencies were checked. InputError for a frequency that is not positive or
/// given twice, a check frequency not among them, whatever impulse_responses refuses,
/// and a frequency whose bound does not prove the linear model valid and is not checked.
SuperposedSet run_superposed(const Scene& scene, const Packing& packing, const SimulationOptions& options,
                             const std::vector<double>& frequencies_kHz, const std::vector<double>& check_kHz = {},
                             bool check_unproven = false);

}  // namespace mesowave::dem
