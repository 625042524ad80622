#include "mesowave/dem/engine/superposition.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/dem/contact/bond_network.hpp"
#include "mesowave/dem/engine/run_report.hpp"
#include "mesowave/dem/engine/sphere_set.hpp"
#include "mesowave/dem/loading/force_actuator.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "mesowave/signal/superposition.hpp"

namespace mesowave::dem {
namespace {

// The validity bound a direct run checks its peak ratio against (simulation.cpp), 0 for none.
double model_validity_bound(const RunReport& r, const Scene& scene) {
  if (r.choice.model == "linear") return scene.linear_validity_bound;
  if (r.choice.model == "chain" && scene.material.breakable()) return 1.0;
  return 0.0;
}

// max over bonds of max(K_n / s_n^2, a0 K_s / s_s^2), the strengths as the kernels take them.
double bond_compliance_max(const Packing& packing, const CohesiveFrictionalMaterial& m) {
  const SphereSet s = make_sphere_set(packing, m.density_kg_m3);
  const BondNetwork b = make_bond_network(s, m.bond_factor);
  const bool finite_T = std::isfinite(m.tensile_strength_Pa), finite_C = std::isfinite(m.cohesion_Pa);
  double worst = 0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    const double ri = s.radius_m[b.first[k]], rj = s.radius_m[b.second[k]], r = std::min(ri, rj);
    const double kn = normal_stiffness(m, ri, rj), ks = shear_stiffness(m, ri, rj);
    const double a0 = (ri + rj) / (ri + rj - b.overlap0_m[k]);
    const double sn = finite_T ? m.tensile_strength_Pa * r * r : kn * r;
    const double ss = finite_C ? m.cohesion_Pa * r * r : kn * r;
    worst = std::max({worst, kn / (sn * sn), a0 * ks / (ss * ss)});
  }
  return worst;
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
  // Viscous damping: the impulse runs undamped, each frequency windows it with its own c (superposition.hpp).
  Scene run_scene = scene;
  if (scene.damping_law == "viscous") {
    out.viscous_alpha = scene.material.damping;
    run_scene.material.damping = 0;
    run_scene.damping_law = "local";
  }
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
    Simulation sim(run_scene, packing, o);
    const ModelChoice& choice = sim.choice();
    if (choice.model != "linear" && choice.model != "chain")
      throw InputError("superposition needs a linear model, but scene " + scene.name + " runs on the " + choice.model +
                       " model (" + choice.reason + ")");
    RunReport r = sim.run();
    out.wall_s += r.wall_s;
    out.impulse_peak_force_ratio.push_back(r.peak_force_ratio);
    const std::size_t sensors = scene.sensors.size();  // then one velocity per actuator (simulation.hpp)
    std::vector<std::vector<double>> velocity, displacement;
    for (std::size_t s = sensors; s < sensors + actuators; ++s) velocity.push_back(std::move(r.signals[s].samples));
    for (std::size_t s = sensors + actuators; s < r.signals.size(); ++s)
      displacement.push_back(std::move(r.signals[s].samples));
    out.actuator_velocity.push_back(std::move(velocity));
    out.displacement.push_back(std::move(displacement));
    r.signals.resize(sensors);
    r.sensors.resize(sensors);
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
  if (out.viscous_alpha > 0) {
    out.report.material.damping = out.viscous_alpha;  // the record states the scene's alpha_d and its law
    out.report.notes.push_back("damping_law viscous: the impulse ran undamped; each frequency's signals are its "
                               "response windowed by r^n, r = sqrt((1 - c dt/2)/(1 + c dt/2)), c = 4 alpha_d f");
  }
  out.bond_compliance_max = bond_compliance_max(packing, out.report.material);
  return out;
}

SuperposedRun superpose(const ImpulseResponses& h, const Scene& scene, double frequency_hz) {
  const auto start = std::chrono::steady_clock::now();
  const double dt = h.report.dt_s;
  const std::int64_t steps = h.report.steps;
  SuperposedRun out;
  out.frequency_hz = frequency_hz;
  // Viscous damping: the window r^m / (1 + c dt/2) and the force that drives the undamped y (superposition.hpp).
  const double c = 4.0 * h.viscous_alpha * frequency_hz, half = 0.5 * c * dt;
  const double r_step = std::sqrt((1.0 - half) / (1.0 + half)), s_factor = std::sqrt(1.0 - half * half);
  out.viscous_damping_1_s = c;
  // The force of every step, as ForceActuator applies it (burst_force_N at t_n = n dt).
  std::vector<signal::ForceHistory> histories;
  for (std::size_t a = 0; a < scene.actuators.size(); ++a) {
    const ActuatorSpec& spec = scene.actuators[a];
    const signal::HannBurst burst(frequency_hz, spec.cycles, spec.amplitude, spec.delay_s);
    histories.push_back(signal::force_history([&burst](double t) { return burst_force_N(burst, t); }, dt, steps));
    out.force_l1_N += histories.back().l1_N;
    out.triangle_bound += histories.back().l1_N * h.impulse_peak_force_ratio[a];
  }
  std::vector<std::vector<double>> force;
  std::vector<std::int64_t> first, last;  // the nonzero span
  for (const auto& g : histories) force.push_back(g.force_N), first.push_back(g.first), last.push_back(g.last);
  // The work of the bursts: each actuator's velocity v_{k+1/2} = sum_c sum_j f_c,j hv_{c->a, k-j}, needed only
  // where some force is not zero (W changes only there).
  double work = 0;
  // With viscous damping the stored energy is r^2n that of y, which the modulated force r^-k f_k / s drives.
  std::vector<std::vector<double>> drive = force;
  if (c > 0)
    for (auto& g : drive) {
      double scale = 1.0 / s_factor;
      for (double& x : g) x *= scale, scale /= r_step;
    }
  {
    std::vector<std::vector<double>> v(force.size(), std::vector<double>(std::size_t(steps), 0.0));
    std::int64_t span_begin = steps, span_end = -1;
    for (std::size_t a = 0; a < force.size(); ++a)
      if (last[a] >= 0) span_begin = std::min(span_begin, first[a]), span_end = std::max(span_end, last[a]);
    for (std::size_t a = 0; a < force.size(); ++a)
      for (std::int64_t k = std::max<std::int64_t>(span_begin - 1, 0); k <= span_end; ++k) {
        double sum = 0;
        for (std::size_t c = 0; c < force.size(); ++c)
          for (std::int64_t j = first[c]; j <= std::min(last[c], k); ++j)
            sum += drive[c][std::size_t(j)] * h.actuator_velocity[c][a][std::size_t(k - j)];
        v[a][std::size_t(k)] = sum;
      }
    for (std::int64_t k = span_begin; k <= span_end; ++k) {
      for (std::size_t a = 0; a < force.size(); ++a) {
        const double before = k > 0 ? v[a][std::size_t(k - 1)] : 0.0;
        work += drive[a][std::size_t(k)] * (before + v[a][std::size_t(k)]) * 0.5 * dt;
      }
      out.work_max_J = std::max(out.work_max_J, work);
    }
  }
  const double ratio = dt / h.report.dt_cr.eigenvalue_s;
  out.energy_bound = ratio < 1 ? std::sqrt(2.0 * 1.01 * out.work_max_J * h.bond_compliance_max / (1.0 - ratio * ratio))
                               : std::numeric_limits<double>::infinity();
  out.peak_force_ratio_bound = std::min(out.triangle_bound, out.energy_bound);
  out.validity_bound = model_validity_bound(h.report, scene);
  out.bound_proves_validity = out.validity_bound == 0 || out.peak_force_ratio_bound < out.validity_bound;

  std::vector<double> window;  // r^m / (1 + c dt/2)
  if (c > 0) {
    window.resize(std::size_t(steps));
    double w = 1.0 / (1.0 + half);
    for (auto& x : window) x = w, w *= r_step;
  }
  for (std::size_t s = 0; s < h.layout.size(); ++s) {
    signal::Signal sig = h.layout[s];
    const std::int64_t every = h.interval_steps[s];
    const std::int64_t samples = (steps - 1) / every + 1;
    std::vector<signal::ConvolutionTerm> terms;
    for (std::size_t a = 0; a < histories.size(); ++a)
      terms.push_back({&histories[a], c == 0 ? h.response[a][s] : h.displacement[a][s]});
    if (c == 0) {
      sig.samples = signal::convolve_sampled(terms, every, samples);
    } else {
      // The damped displacement after every step, then the sensor's quantity by the leapfrog's differences.
      const std::vector<double> x = signal::convolve_sampled(terms, 1, steps, window);
      auto at = [&](std::int64_t n) { return n >= 0 ? x[std::size_t(n)] : 0.0; };  // x_{n+1}; x_0 = x_{-1} = 0
      sig.samples.assign(std::size_t(samples), 0.0);
      double* y = sig.samples.data();
      for (std::int64_t m = 0; m < samples; ++m) {
        const std::int64_t n = m * every;
        if (sig.quantity == "displacement") y[m] = at(n);
        else if (sig.quantity == "velocity") y[m] = (at(n) - at(n - 1)) / dt;
        else y[m] = ((at(n) - at(n - 1)) - (at(n - 1) - at(n - 2))) / (dt * dt);
      }
    }
    out.signals.push_back(std::move(sig));
  }
  out.convolution_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

nlohmann::ordered_json to_json(const SuperpositionCheck& check) {
  nlohmann::ordered_json c;
  c["frequency_kHz"] = check.frequency_hz / units::kHz;
  c["against"] = "a direct run of the same scene at this frequency";
  c["min_pcc"] = check.error.min_pcc;
  c["max_diff_over_peak"] = check.error.max_diff_over_peak_all;
  c["direct_wall_s"] = check.direct_wall_s;
  c["direct_peak_force_ratio"] = check.direct_peak_force_ratio;
  nlohmann::ordered_json per = nlohmann::ordered_json::array();
  for (std::size_t s = 0; s < check.error.sensors.size(); ++s)
    per.push_back({{"sensor", check.error.sensors[s]}, {"pcc", check.error.pcc[s]},
                   {"max_diff_over_peak", check.error.max_diff_over_peak[s]}});
  c["sensors"] = per;
  return c;
}

nlohmann::ordered_json superposition_summary(const ImpulseResponses& h, const SuperposedRun& run,
                                             const std::vector<SuperpositionCheck>& checks) {
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
  const bool viscous = h.viscous_alpha > 0;
  v["exact"] = alpha == 0;
  v["damping"] = alpha;
  v["damping_law"] = viscous ? "viscous" : "local";
  if (viscous) v["viscous_damping_1_s"] = run.viscous_damping_1_s;
  v["why"] = alpha == 0 ? "without damping the step is a linear time-invariant system in the forces: the convolution "
                          "equals a direct run to round-off"
             : viscous
                 ? "viscous mass-proportional damping c = 4 alpha_d f is linear: the undamped impulse response "
                   "windowed by r^n, r = sqrt((1 - c dt/2)/(1 + c dt/2)), is the damped one but for a stiffness "
                   "shift of c^2 M / 4 (relative frequency alpha_d^2 / (2 pi^2)); the error is measured (check)"
                 : "the local damping F (1 - alpha_d sgn(F v)) (Eq. 7) is not additive: the superposed signals "
                   "approximate a direct run's; the error is measured, not assumed (check; docs/benchmarks.md, "
                   "\"One run, every frequency\")";
  v["impulse_runs"] = h.response.size();
  v["impulse_wall_s"] = h.wall_s;
  v["convolution_s"] = run.convolution_s;
  v["force_l1_N"] = run.force_l1_N;
  v["peak_force_ratio"] = "a bound, the lower of: sum_n |f_n| x the unit impulse's peak ratio (triangle inequality) and "
                         "sqrt(2 W_max max_b compliance / (1 - (dt/dt_eig)^2)) (energy: W_max the work done)";
  const SuperpositionCheck* here = nullptr;
  for (const auto& c : checks)
    if (c.frequency_hz == run.frequency_hz) here = &c;
  v["validity"] = run.bound_proves_validity
                      ? "the bound on the peak bond force / strength is below the validity bound"
                      : "the bound does not prove it; the direct run at this frequency measured " +
                            format_number(here ? here->direct_peak_force_ratio : 0.0) + ", below the validity bound";
  v["triangle_bound"] = run.triangle_bound;
  v["energy_bound"] = std::isfinite(run.energy_bound) ? nlohmann::ordered_json(run.energy_bound) : nullptr;
  v["work_max_J"] = run.work_max_J;
  v["check"] = nullptr;
  v["checks"] = nlohmann::ordered_json::array();
  for (const auto& c : checks) {
    if (c.frequency_hz == run.frequency_hz) v["check"] = to_json(c);
    v["checks"].push_back({{"frequency_kHz", c.frequency_hz / units::kHz}, {"min_pcc", c.error.min_pcc},
                           {"max_diff_over_peak", c.error.max_diff_over_peak_all}});
  }
  j["superposition"] = v;
  for (const auto& [key, value] : base.items())
    if (key != "scene" && key != "energy") j[key] = value;
  return j;
}

SuperposedSet run_superposed(const Scene& scene, const Packing& packing, const SimulationOptions& options,
                             const std::vector<double>& frequencies_kHz, const std::vector<double>& check_kHz,
                             bool check_unproven) {
  signal::check_frequencies(frequencies_kHz, check_kHz);
  SuperposedSet set;
  set.responses = impulse_responses(scene, packing, options);
  std::vector<SuperposedRun> runs;
  for (double f : frequencies_kHz) runs.push_back(superpose(set.responses, scene, f * units::kHz));
  // check_unproven: the frequencies whose bound does not prove the linear model join the checks, so a
  // pipeline need not know beforehand which those are (they depend on the material and the packing).
  std::vector<double> direct_kHz = check_kHz;
  if (check_unproven)
    for (std::size_t i = 0; i < runs.size(); ++i)
      if (!runs[i].bound_proves_validity &&
          std::find(direct_kHz.begin(), direct_kHz.end(), frequencies_kHz[i]) == direct_kHz.end())
        direct_kHz.push_back(frequencies_kHz[i]);
  for (double c : direct_kHz) {
    Scene direct = scene;
    for (auto& a : direct.actuators) a.frequency_hz = c * units::kHz;
    SimulationOptions o = options;
    o.on_progress = nullptr;
    o.on_snapshot = nullptr;
    const RunReport r = Simulation(direct, packing, o).run();
    for (const auto& run : runs)
      if (run.frequency_hz == c * units::kHz)
        set.checks.push_back({run.frequency_hz, superposition_error(r.signals, run.signals), r.wall_s,
                              r.peak_force_ratio});
  }
  // A bound that does not prove the linear model valid needs a direct run at that frequency, which
  // measures the peak itself (and refuses a run above the bound, as every direct run does).
  for (const auto& run : runs) {
    if (run.bound_proves_validity) continue;
    bool measured = false;
    for (const auto& c : set.checks) measured = measured || c.frequency_hz == run.frequency_hz;
    if (!measured)
      throw InputError("superposition at " + frequency_text(run.frequency_hz) + " kHz: the bound on the peak bond "
                       "force / strength, " + format_number(run.peak_force_ratio_bound) + " (the lower of the "
                       "impulse's and the work's), does not prove it below the validity bound " +
                       format_number(run.validity_bound) + " (linear_validity_bound); add " +
                       frequency_text(run.frequency_hz) + " to --check-kHz (or give --check-unproven) to measure "
                       "it in a direct run");
  }
  nlohmann::ordered_json per = nlohmann::ordered_json::array();
  for (auto& run : runs) {
    nlohmann::ordered_json summary = superposition_summary(set.responses, run, set.checks);
    per.push_back({{"frequency_kHz", run.frequency_hz / units::kHz},
                   {"peak_force_ratio_bound", run.peak_force_ratio_bound},
                   {"convolution_s", run.convolution_s}});
    set.frequencies.push_back({std::move(run), std::move(summary)});
  }
  set.summary = superposition_summary(set.responses, set.frequencies.front().run, {});
  auto& v = set.summary["superposition"];
  v["convolution_s"] = nullptr;
  v.erase("check");
  v["checks"] = nlohmann::ordered_json::array();
  for (const auto& c : set.checks) v["checks"].push_back(to_json(c));
  set.summary["frequencies"] = per;
  set.summary["peak_force_ratio"] = nullptr;  // one per frequency: "frequencies"
  for (auto& a : set.summary["actuator_loads"]) a["frequency_hz"] = nullptr;
  return set;
}

}  // namespace mesowave::dem
