#include "mesowave/dem/engine/superposition.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/dem/engine/run_report.hpp"
#include "mesowave/dem/loading/force_actuator.hpp"
#include "mesowave/signal/correlation.hpp"
#include "mesowave/signal/hann_burst.hpp"

namespace mesowave::dem {
namespace {

// The validity bound a direct run checks its peak ratio against (simulation.cpp), 0 for none.
double model_validity_bound(const RunReport& r, const Scene& scene) {
  if (r.choice.model == "linear") return scene.linear_validity_bound;
  if (r.choice.model == "chain" && scene.material.breakable()) return 1.0;
  return 0.0;
}

}  // namespace

std::string superposition_obstacle(const Scene& scene) {
  if (scene.actuators.empty()) return "it has no actuator";
  for (const auto& a : scene.actuators)
    if (a.kind != "force")
      return "actuator " + a.name + " is a " + a.kind + " actuator, not a force burst (a prescribed motion is a "
             "constraint, a wall's contact one-sided)";
  for (const auto& s : scene.sensors) {
    if (s.kind != "motion")
      return "sensor " + s.name + " is a " + s.kind + " sensor; superposition takes motion sensors only";
    if (s.component == "magnitude")
      return "sensor " + s.name + " records the magnitude of a vector, which is not linear in the loads";
  }
  if (scene.test.active()) return "it has a [test] (stop rules, breakage)";
  return "";
}

ImpulseResponses impulse_responses(const Scene& scene, const Packing& packing, SimulationOptions options) {
  if (const std::string why = superposition_obstacle(scene); !why.empty())
    throw InputError("superposition is not valid for scene " + scene.name + ": " + why);
  ImpulseResponses out;
  const auto progress = options.on_progress;
  const std::size_t actuators = scene.actuators.size();
  options.on_snapshot = nullptr;
  for (std::size_t a = 0; a < actuators; ++a) {
    SimulationOptions o = options;
    o.impulse_actuator = int(a);
    if (progress)
      o.on_progress = [&progress, a, actuators](std::int64_t done, std::int64_t total) {
        progress(std::int64_t(a) * total + done, std::int64_t(actuators) * total);
      };
    Simulation sim(scene, packing, o);
    const ModelChoice& choice = sim.choice();
    if (choice.model != "linear" && choice.model != "chain")
      throw InputError("superposition needs a linear model, but scene " + scene.name + " runs on the " + choice.model +
                       " model (" + choice.reason + ")");
    RunReport r = sim.run();
    out.wall_s += r.wall_s;
    out.impulse_peak_force_ratio.push_back(r.peak_force_ratio);
    std::vector<std::vector<double>> per_sensor;
    for (std::size_t s = 0; s < r.signals.size(); ++s) {
      if (a == 0) {
        signal::Signal layout = r.signals[s];
        layout.samples.clear();
        layout.dt_s = double(r.sample_interval_steps[s]) * r.dt_s;
        out.layout.push_back(std::move(layout));
      }
      per_sensor.push_back(std::move(r.signals[s].samples));
    }
    out.response.push_back(std::move(per_sensor));
    out.interval_steps = r.sample_interval_steps;
    r.signals.clear();
    out.report = std::move(r);
  }
  out.report.wall_s = out.wall_s;
  return out;
}

SuperposedRun superpose(const ImpulseResponses& h, const Scene& scene, double frequency_hz) {
  const auto start = std::chrono::steady_clock::now();
  const double dt = h.report.dt_s;
  const std::int64_t steps = h.report.steps;
  SuperposedRun out;
  out.frequency_hz = frequency_hz;
  // The force of every step, as ForceActuator applies it (burst_force_N at t_n = n dt).
  std::vector<std::vector<double>> force(scene.actuators.size());
  std::vector<std::int64_t> first(force.size(), 0), last(force.size(), -1);  // the nonzero span
  for (std::size_t a = 0; a < force.size(); ++a) {
    const ActuatorSpec& spec = scene.actuators[a];
    const signal::HannBurst burst(frequency_hz, spec.cycles, spec.amplitude, spec.delay_s);
    force[a].assign(std::size_t(steps), 0.0);
    double l1 = 0;
    for (std::int64_t n = 0; n < steps; ++n) {
      const double f = burst_force_N(burst, double(n) * dt);
      force[a][std::size_t(n)] = f;
      if (f != 0) {
        if (last[a] < 0) first[a] = n;
        last[a] = n;
      }
      l1 += std::abs(f);
    }
    out.force_l1_N += l1;
    out.peak_force_ratio_bound += l1 * h.impulse_peak_force_ratio[a];
  }
  out.validity_bound = model_validity_bound(h.report, scene);
  if (out.validity_bound > 0 && !(out.peak_force_ratio_bound < out.validity_bound))
    throw InputError("superposition at " + format_number(frequency_hz / 1e3) +
                     " kHz: the peak bond force / strength may reach " + format_number(out.peak_force_ratio_bound) +
                     " (sum |f_n| x the unit impulse's peak ratio), above the validity bound " +
                     format_number(out.validity_bound) + " (linear_validity_bound); rerun directly with --model full");

  for (std::size_t s = 0; s < h.layout.size(); ++s) {
    signal::Signal sig = h.layout[s];
    const std::int64_t every = h.interval_steps[s];
    const std::int64_t samples = (steps - 1) / every + 1;
    sig.samples.assign(std::size_t(samples), 0.0);
    double* y = sig.samples.data();
    // Each output is its own sum in a fixed order: the same bits for any thread count.
#pragma omp parallel for schedule(static)
    for (std::int64_t m = 0; m < samples; ++m) {
      const std::int64_t n = m * every;
      double sum = 0;
      for (std::size_t a = 0; a < force.size(); ++a) {
        const double* f = force[a].data();
        const double* r = h.response[a][s].data();
        const std::int64_t end = std::min(last[a], n);
        for (std::int64_t k = first[a]; k <= end; ++k) sum += f[k] * r[n - k];
      }
      y[m] = sum;
    }
    out.signals.push_back(std::move(sig));
  }
  out.convolution_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

SuperpositionError superposition_error(const std::vector<signal::Signal>& direct,
                                       const std::vector<signal::Signal>& superposed) {
  if (direct.size() != superposed.size())
    throw InputError("superposition check: " + std::to_string(direct.size()) + " direct signals against " +
                     std::to_string(superposed.size()) + " superposed");
  SuperpositionError e;
  for (std::size_t s = 0; s < direct.size(); ++s) {
    const signal::Signal &d = direct[s], &p = superposed[s];
    if (d.name != p.name || d.size() != p.size() || d.dt_s != p.dt_s || d.t0_s != p.t0_s)
      throw InputError("superposition check: sensor " + d.name + " and " + p.name + " do not share a time base");
    double peak = 0, diff = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
      peak = std::max(peak, std::abs(d.samples[i]));
      diff = std::max(diff, std::abs(p.samples[i] - d.samples[i]));
    }
    e.sensors.push_back(d.name);
    e.pcc.push_back(signal::pearson(d.samples, p.samples, "sensor " + d.name));
    e.max_diff_over_peak.push_back(peak > 0 ? diff / peak : diff);
    e.min_pcc = std::min(e.min_pcc, e.pcc.back());
    e.max_diff_over_peak_all = std::max(e.max_diff_over_peak_all, e.max_diff_over_peak.back());
  }
  return e;
}

nlohmann::ordered_json superposition_summary(const ImpulseResponses& h, const SuperposedRun& run,
                                             const SuperpositionError* check, double check_frequency_hz) {
  RunReport r = h.report;
  for (auto& a : r.actuator_placements) a.frequency_hz = run.frequency_hz;
  for (auto& a : r.actuators)
    a = "the scene's burst at " + format_number(run.frequency_hz / 1e3) +
        " kHz convolved with the response to " + a;
  r.peak_force_ratio = run.peak_force_ratio_bound;
  r.validity_bound = run.validity_bound;
  const nlohmann::ordered_json base = to_json(r);
  const double alpha = r.material.damping;

  nlohmann::ordered_json j;
  j["scene"] = base["scene"];
  j["method"] = "superposition";
  j["method_reason"] =
      "the leapfrog step on the " + r.choice.model + " model is linear in the actuators' forces: each signal is "
      "y_n = sum_k f_k h_{n-k}, the burst f convolved with the sensor's response h to a unit impulse of the "
      "actuator on step 0 (one run per actuator for every frequency)";
  nlohmann::ordered_json v;
  v["exact"] = alpha == 0;
  v["damping"] = alpha;
  v["why"] = alpha == 0
                 ? "without damping the step is a linear time-invariant system in the forces: the convolution equals "
                   "a direct run to round-off"
                 : "the local damping F (1 - alpha_d sgn(F v)) (Eq. 7) is not additive: the superposed signals "
                   "approximate a direct run's; the error is measured, not assumed (check; docs/benchmarks.md, "
                   "\"One run, every frequency\")";
  v["impulse_runs"] = h.response.size();
  v["impulse_wall_s"] = h.wall_s;
  v["convolution_s"] = run.convolution_s;
  v["force_l1_N"] = run.force_l1_N;
  v["peak_force_ratio"] = "a bound: sum_n |f_n| x the unit impulse's peak bond force / strength (triangle inequality)";
  if (check) {
    nlohmann::ordered_json c;
    c["frequency_kHz"] = check_frequency_hz / 1e3;
    c["against"] = "a direct run of the same scene at this frequency";
    c["min_pcc"] = check->min_pcc;
    c["max_diff_over_peak"] = check->max_diff_over_peak_all;
    nlohmann::ordered_json per = nlohmann::ordered_json::array();
    for (std::size_t s = 0; s < check->sensors.size(); ++s)
      per.push_back({{"sensor", check->sensors[s]}, {"pcc", check->pcc[s]},
                     {"max_diff_over_peak", check->max_diff_over_peak[s]}});
    c["sensors"] = per;
    v["check"] = c;
  } else {
    v["check"] = nullptr;
  }
  j["superposition"] = v;
  for (const auto& [key, value] : base.items())
    if (key != "scene" && key != "energy") j[key] = value;
  return j;
}

}  // namespace mesowave::dem
