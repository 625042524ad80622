#pragma once
// One FEM run per mesh for every burst frequency (issue 17 item 1, the FEM
// half of dem/engine/superposition.hpp). The explicit step (solver.hpp)
//   v^{n+1/2} = ((1 - alpha dt/2) v^{n-1/2} + dt M^-1 (F^n w - K u^n)) / (1 + alpha dt/2)
//   u^{n+1}   = u^n + dt v^{n+1/2}
// is linear in the load history F^0, F^1, ... and the same every step (lumped
// M, constant K, the Rayleigh mass-proportional alpha fixed, not a function of
// the burst): a discrete-time linear time-invariant system. Every recorded
// sample at step n (u^n, (v^{n-1/2} + v^{n+1/2}) / 2 or (v^{n+1/2} - v^{n-1/2}) / dt)
// depends on F^0 .. F^n only, so with h_n the probe's sample after a unit force
// on step 0 alone,
//   y_n = sum_{k=0..n} F^k h_{n-k}            (signal/superposition.hpp)
// is what a direct run with the burst F records, to round-off
// (tests/fem/superposition_test.cpp: ~1e-13 of the peak, with and without damping).
// So one impulse run per mesh gives the signals of every burst frequency (and any
// cycles or amplitude): the impulse run records every step (the convolution needs
// h at every step), the outputs are sampled every stride as a direct run's.
// Unlike the DEM's local damping, nothing here is nonlinear: the result is exact,
// not an approximation to be checked (a direct run at --check-kHz measures it anyway).
//
// Cost: the impulse run is one direct run's step loop; each frequency is then
// (samples) x (burst steps) multiply-adds per probe - for the 50 mm cube at 1 mm
// (15,001 samples, the 100 kHz burst's 500 steps, 6 probes) 4.5e7, ~0.05 s.
// Not superposed: the rod's space-time record (thousands of dofs x every step).
#include <cstdint>
#include <functional>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesowave/fem/case.hpp"
#include "mesowave/signal/superposition.hpp"

namespace mesowave::fem {

/// Every probe's response to a unit impulse of the case's load (1 N on step 0), at every step.
struct FemImpulseResponse {
  ExplicitResult result;  ///< one signal per probe, dt = the step, steps + 1 samples (n = 0 .. steps)
  ThreadChoice threads;
};
/// InputError for a setup with a space-time record (not superposed).
FemImpulseResponse fem_impulse_response(const FemSetup& setup, const std::function<void(std::int64_t)>& progress = {});

/// The same setup (mesh, load weights, probes, stepping) with the burst at `frequency_hz`.
FemSetup at_frequency(const FemSetup& setup, double frequency_hz);

/// What run_fem_case(setup) would return, from the impulse response of the same mesh:
/// the probes' signals (the setup's burst convolved with h, sampled every stride), the
/// excitation and the attributes of a direct run, plus "method" = "superposition".
/// result.wall_s is the convolution's; the kinetic energies are not known (NaN; null in the report).
FemRun superpose_fem(const FemSetup& setup, const FemImpulseResponse& impulse);

/// A direct run at one of the frequencies, against the superposed signals.
struct FemSuperpositionCheck {
  double frequency_hz = 0;
  signal::SuperpositionError error;
  double direct_wall_s = 0;
};

/// mw-fem --frequencies-kHz: one impulse run, every frequency's run and a direct run at each of `check_kHz`.
struct FemSuperposedFrequency {
  FemSetup setup;
  FemRun run;
};
struct FemSuperposedSet {
  FemImpulseResponse impulse;
  std::vector<FemSuperposedFrequency> frequencies;
  std::vector<FemSuperpositionCheck> checks;
};
/// InputError as signal::check_frequencies and fem_impulse_response.
FemSuperposedSet run_fem_superposed(const FemSetup& setup, const std::vector<double>& frequencies_kHz,
                                    const std::vector<double>& check_kHz = {},
                                    const std::function<void(std::int64_t)>& progress = {});

/// The "superposition" entry of a frequency's report (fem_report + this): the method, why it
/// is exact, the impulse run's and the convolution's cost, the checks made.
nlohmann::ordered_json superposition_json(const FemSuperposedSet& set, const FemSuperposedFrequency& frequency);

}  // namespace mesowave::fem
