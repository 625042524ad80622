#include "mesowave/dem/engine/run_report.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>

#include "mesowave/dem/contact/material_parameters.hpp"
#include "mesowave/dem/scene/plugins.hpp"
#include "mesowave/io/csv.hpp"

namespace mesowave::dem {
namespace {

nlohmann::ordered_json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nullptr; }

}  // namespace

nlohmann::ordered_json to_json(const RunReport& r) {
  nlohmann::ordered_json j;
  j["scene"] = r.scene;
  j["model"] = r.choice.model;
  j["model_reason"] = r.choice.reason;
  j["estimated_peak_force_ratio"] = finite_or_null(r.choice.estimated_force_ratio);
  j["spheres"] = r.spheres;
  j["bonds"] = r.bonds;
  j["contacts"] = r.contacts;
  j["degrees_of_freedom"] = r.degrees_of_freedom;
  j["threads"] = r.threads;
  if (!r.distribution.empty()) j["mpi"] = r.distribution;  // one process: absent, so its summary is unchanged
  j["dt_s"] = r.dt_s;
  j["steps"] = r.steps;
  j["duration_s"] = r.duration_s;
  j["dt_cr_paper_estimate_s"] = finite_or_null(r.dt_cr.paper_estimate_s);
  j["dt_cr_stiffness_bound_s"] = finite_or_null(r.dt_cr.stiffness_bound_s);
  j["dt_cr_eigenvalue_s"] = finite_or_null(r.dt_cr.eigenvalue_s);
  j["dt_limit_s"] = finite_or_null(r.dt_cr.limit_s);
  j["lambda_max_1_s2"] = r.dt_cr.lambda_max;
  if (r.dt_cr.boundary_lambda > 0) j["wall_lambda_1_s2"] = r.dt_cr.boundary_lambda;
  j["lanczos_iterations"] = r.dt_cr.lanczos_iterations;
  j["memory_estimate_MiB"] = double(r.memory_bytes) / (1024.0 * 1024.0);
  nlohmann::ordered_json m;
  for (const MaterialParameter& p : material_parameters()) m[p.report_key] = finite_or_null(r.material.*p.field);
  m["law"] = r.contact_law;
  const nlohmann::ordered_json law = contact_laws().get(r.contact_law, "law").describe(r.law_parameters);
  for (const auto& [key, value] : law.items()) m[key] = value;
  j["material"] = m;
  auto vec = [](const Vec3& v) { return nlohmann::ordered_json::array({v.x + 0.0, v.y + 0.0, v.z + 0.0}); };
  j["actuator_loads"] = nlohmann::ordered_json::array();
  for (const auto& a : r.actuator_placements) {
    nlohmann::ordered_json e;
    e["name"] = a.name;
    e["kind"] = a.kind;
    e["spheres"] = a.spheres;
    e["direction"] = vec(a.direction);
    e[actuator_kinds().get(a.kind, "actuator " + a.name).report_key] = a.amplitude;
    e["frequency_hz"] = a.frequency_hz;
    e["cycles"] = a.cycles;
    e["delay_s"] = a.delay_s;
    j["actuator_loads"].push_back(e);
  }
  j["sensor_points"] = nlohmann::ordered_json::array();
  for (const auto& s : r.sensor_placements) {
    nlohmann::ordered_json e;
    e["name"] = s.name;
    e["quantity"] = s.kind;
    e["spheres"] = s.spheres;
    if (!s.spheres_b.empty()) e["spheres_b"] = s.spheres_b;  // an extensometer: strain = (u_b - u_a) . e / L0
    e["component"] = vec(s.direction);
    j["sensor_points"].push_back(e);
  }
  j["actuators"] = r.actuators;
  j["sensors"] = r.sensors;
  j["notes"] = r.notes;
  j["setup_s"] = r.setup_s;
  if (!r.ran) return j;
  j["wall_s"] = r.wall_s;
  j["steps_per_s"] = r.steps_per_s;
  j["ns_per_contact_step"] = r.ns_per_contact_step;
  j["broken_bonds"] = r.broken_bonds;
  j["peak_force_ratio"] = r.peak_force_ratio;
  j["validity_bound"] = r.validity_bound > 0 ? nlohmann::ordered_json(r.validity_bound) : nullptr;
  nlohmann::ordered_json e;
  e["kinetic_J"] = r.energy.kinetic_J;
  e["elastic_J"] = r.energy.elastic_J;
  e["external_work_J"] = r.energy.external_work_J;
  e["damping_dissipated_J"] = r.energy.damping_J;
  e["plastic_dissipated_J"] = r.energy.plastic_J;
  e["residual_J"] = r.energy.residual();
  e["residual_relative"] = r.energy.external_work_J != 0 ? finite_or_null(r.energy.residual() / std::abs(r.energy.external_work_J))
                                                          : nullptr;
  e["peak_stored_J"] = r.peak_stored_J;
  j["energy"] = e;
  if (!r.stop_reason.empty()) j["stop_reason"] = r.stop_reason;
  if (r.test) j["test"] = to_json(*r.test);
  return j;
}

nlohmann::ordered_json to_json(const UniaxialTestResult& t) {
  auto optional = [](const std::optional<double>& v) { return v ? nlohmann::ordered_json(*v) : nullptr; };
  nlohmann::ordered_json j;
  j["kind"] = t.kind;
  j["area_mm2"] = t.area_m2 * 1e6;
  j["samples"] = t.time_s.size();
  j["peak_stress_MPa"] = t.peak_stress_Pa / 1e6;
  j["peak_reached"] = t.peak_reached;
  j["strain_at_peak"] = t.strain_at_peak;
  j["time_at_peak_s"] = t.time_at_peak_s;
  j["modulus_levels_MPa"] = nlohmann::ordered_json::array({t.sigma_b_Pa / 1e6, t.sigma_a_Pa / 1e6});
  j["strains_at_levels"] = nlohmann::ordered_json::array({t.eps_b, t.eps_a});
  j["E_glob_GPa"] = t.E_secant_Pa / 1e9;
  j["nu_glob"] = optional(t.nu_secant);
  j["E_fit_GPa"] = t.fit_points >= 3 ? nlohmann::ordered_json(t.E_fit_Pa / 1e9) : nullptr;
  j["E_fit_r2"] = t.fit_points >= 3 ? nlohmann::ordered_json(t.E_fit_r2) : nullptr;
  j["nu_fit"] = optional(t.nu_fit);
  j["fit_points"] = t.fit_points;
  j["strain_rate_1_s"] = t.strain_rate_1_s;
  j["inertial_number_max"] = t.inertial_number_max;
  j["inertial_number_bound"] = t.inertial_number_bound > 0 ? nlohmann::ordered_json(t.inertial_number_bound) : nullptr;
  j["broken_bonds_at_peak"] = t.broken_bonds_at_peak;
  j["broken_bonds_final"] = t.broken_bonds_final;
  j["notes"] = t.notes;
  return j;
}

nlohmann::ordered_json to_json(const StaticElasticResult& r) {
  nlohmann::ordered_json j;
  j["model"] = "linear";
  j["method"] = "static";
  j["solver"] = r.solver;
  j["spheres"] = r.spheres;
  j["bonds"] = r.bonds;
  j["degrees_of_freedom"] = r.dofs;
  j["stiffness_nonzeros"] = r.nonzeros;
  const auto level = [](const StaticLevel& l) {
    return nlohmann::ordered_json{{"stress_MPa", l.sigma_Pa / 1e6},       {"wall_travel_um", l.travel_m * 1e6},
                                  {"axial_strain", l.axial_strain},       {"lateral_strain", l.lateral_strain},
                                  {"wall_contacts", l.wall_contacts},     {"active_set_rounds", l.active_set_rounds}};
  };
  j["levels"] = nlohmann::ordered_json::array({level(r.level_b), level(r.level_a)});
  j["solves"] = r.solves;
  j["iterations_max"] = r.iterations_max;
  j["iterations_total"] = r.iterations_total;
  j["relative_residual_max"] = r.residual_max;
  j["support_force_ratio"] = r.support_force_ratio;
  j["setup_s"] = r.setup_s;
  j["assemble_s"] = r.assemble_s;
  j["solve_s"] = r.solve_s;
  j["preconditioner_s"] = r.preconditioner_s;
  j["wall_s"] = r.wall_s;
  j["test"] = to_json(r.test);
  return j;
}

std::string signals_csv(const std::vector<signal::Signal>& signals) {
  bool shared = !signals.empty();
  for (const auto& s : signals)
    shared = shared && s.dt_s == signals[0].dt_s && s.t0_s == signals[0].t0_s && s.size() == signals[0].size();
  auto number = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return std::string(text);
  };
  std::vector<std::string> header;
  std::size_t rows = 0;
  for (const auto& s : signals) {
    if (!shared || header.empty()) header.push_back(shared ? "t_s" : s.name + " t_s");
    header.push_back(s.name + " [" + s.unit + "]");
    rows = std::max(rows, s.size());
  }
  std::vector<std::vector<std::string>> table(rows);
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t k = 0; k < signals.size(); ++k) {
      const auto& s = signals[k];
      if (!shared || k == 0) table[i].push_back(i < s.size() ? number(s.time(i)) : "");
      table[i].push_back(i < s.size() ? number(s.samples[i]) : "");
    }
  return io::to_csv(header, table);
}

}  // namespace mesowave::dem
