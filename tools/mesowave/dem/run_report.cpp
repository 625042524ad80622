#include "mesowave/dem/run_report.hpp"

#include <cmath>

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
  j["dt_s"] = r.dt_s;
  j["steps"] = r.steps;
  j["duration_s"] = r.duration_s;
  j["dt_cr_paper_estimate_s"] = finite_or_null(r.dt_cr.paper_estimate_s);
  j["dt_cr_stiffness_bound_s"] = finite_or_null(r.dt_cr.stiffness_bound_s);
  j["dt_cr_eigenvalue_s"] = finite_or_null(r.dt_cr.eigenvalue_s);
  j["dt_limit_s"] = finite_or_null(r.dt_cr.limit_s);
  j["lambda_max_1_s2"] = r.dt_cr.lambda_max;
  j["lanczos_iterations"] = r.dt_cr.lanczos_iterations;
  j["memory_estimate_MiB"] = double(r.memory_bytes) / (1024.0 * 1024.0);
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
  return j;
}

}  // namespace mesowave::dem
