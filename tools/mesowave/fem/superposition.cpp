#include "mesowave/fem/superposition.hpp"

#include <chrono>
#include <limits>

#include "mesowave/core/error.hpp"
#include "mesowave/core/units.hpp"

namespace mesowave::fem {

FemImpulseResponse fem_impulse_response(const FemSetup& setup, const std::function<void(std::int64_t)>& progress) {
  if (setup.spacetime)
    throw InputError("--frequencies-kHz superposes the probes' signals only: no --spacetime (one direct run per frequency)");
  ExplicitOptions opt;
  opt.dt_s = setup.stepping.dt_s;
  opt.steps = setup.stepping.steps;
  opt.sample_stride = 1;  // the convolution needs h at every step
  opt.alpha_damping_per_s = setup.spec.alpha_damping_per_s;
  opt.progress = progress;
  opt.unit_impulse = true;
  FemImpulseResponse h;
  h.threads = use_threads(setup.spec.threads, {setup.model.element_count(), opt.min_elements_per_thread, "elements"});
  h.result = run_explicit(setup.model, setup.load, setup.probes, opt);
  return h;
}

FemSetup at_frequency(const FemSetup& setup, double frequency_hz) {
  FemSetup s = setup;
  s.spec.frequency_hz = frequency_hz;
  s.load.burst = signal::HannBurst(frequency_hz, setup.load.burst.cycles(), setup.load.burst.amplitude(),
                                   setup.load.burst.delay_s());
  return s;
}

FemRun superpose_fem(const FemSetup& setup, const FemImpulseResponse& h) {
  const auto start = std::chrono::steady_clock::now();
  const Stepping& st = setup.stepping;
  if (h.result.steps != st.steps || h.result.signals.size() != setup.probes.size())
    throw InputError("superposition: the impulse response is of another stepping or other probes");
  // F^n = burst(n dt), n = 0 .. steps, as run_explicit applies it.
  const signal::HannBurst& burst = setup.load.burst;
  const signal::ForceHistory force = signal::force_history(burst, st.dt_s, st.steps + 1);
  const std::int64_t samples = st.steps / st.stride + 1;
  FemRun run;
  run.threads = h.threads;
  run.result.steps = st.steps;
  run.result.threads = h.result.threads;
  // The burst run's energies are not the impulse run's, and the convolution does not give them.
  run.result.max_kinetic_energy_J = std::numeric_limits<double>::quiet_NaN();
  run.result.final_kinetic_energy_J = std::numeric_limits<double>::quiet_NaN();
  for (const signal::Signal& response : h.result.signals) {
    signal::Signal s = response;  // name, quantity, unit, component, position as the direct run's probe
    s.dt_s = st.dt_s * double(st.stride);
    s.samples = signal::convolve_sampled({{&force, response.samples}}, st.stride, samples);
    run.result.signals.push_back(std::move(s));
  }
  complete_fem_run(setup, run);
  run.attributes["method"] = "superposition";
  run.result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

FemSuperposedSet run_fem_superposed(const FemSetup& setup, const std::vector<double>& frequencies_kHz,
                                    const std::vector<double>& check_kHz,
                                    const std::function<void(std::int64_t)>& progress) {
  signal::check_frequencies(frequencies_kHz, check_kHz);
  FemSuperposedSet set;
  set.impulse = fem_impulse_response(setup, progress);
  for (double f : frequencies_kHz) {
    FemSetup s = at_frequency(setup, f * units::kHz);
    FemRun run = superpose_fem(s, set.impulse);
    set.frequencies.push_back({std::move(s), std::move(run)});
  }
  for (double c : check_kHz)
    for (const auto& f : set.frequencies)
      if (f.setup.spec.frequency_hz == c * units::kHz) {
        const FemRun direct = run_fem_case(f.setup);
        set.checks.push_back({f.setup.spec.frequency_hz, signal::superposition_error(direct.result.signals, f.run.result.signals),
                              direct.result.wall_s});
      }
  return set;
}

nlohmann::ordered_json superposition_json(const FemSuperposedSet& set, const FemSuperposedFrequency& frequency) {
  nlohmann::ordered_json v;
  v["exact"] = true;
  v["why"] = "the explicit step (lumped mass, Rayleigh mass-proportional alpha fixed) is a linear time-invariant "
             "system in the load: each signal is y_n = sum_k F^k h_{n-k}, the burst convolved with the probe's "
             "response h to a unit force on step 0, equal to a direct run's to round-off (fem/superposition.hpp)";
  v["impulse_runs"] = 1;
  v["impulse_wall_s"] = set.impulse.result.wall_s;
  v["convolution_s"] = frequency.run.result.wall_s;
  v["frequencies_kHz"] = nlohmann::ordered_json::array();
  for (const auto& f : set.frequencies) v["frequencies_kHz"].push_back(f.setup.spec.frequency_hz / units::kHz);
  v["check"] = nullptr;
  v["checks"] = nlohmann::ordered_json::array();
  for (const auto& c : set.checks) {
    nlohmann::ordered_json j{{"frequency_kHz", c.frequency_hz / units::kHz},
                             {"against", "a direct run of the same mesh at this frequency"},
                             {"min_pcc", c.error.min_pcc},
                             {"max_diff_over_peak", c.error.max_diff_over_peak_all},
                             {"direct_wall_s", c.direct_wall_s}};
    if (c.frequency_hz == frequency.setup.spec.frequency_hz) v["check"] = j;
    v["checks"].push_back(j);
  }
  return v;
}

}  // namespace mesowave::fem
