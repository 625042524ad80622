#include "mesowave/efg/viscosity_command.hpp"

namespace mesowave::efg {

void add_viscosity_options(CLI::App& app, double& quadratic, double& linear) {
  app.add_option("--viscosity-quadratic", quadratic,
                 "Shock viscosity C_0 (quadratic): q = rho l (C_0 l eps_dot_v^2 - C_1 c eps_dot_v) in compression, "
                 "l = sqrt(cell area), c = the point's dilatational speed (LS-DYNA: 1.5; 0 with C_1 = 0: off)")
      ->capture_default_str();
  app.add_option("--viscosity-linear", linear, "Shock viscosity C_1 (linear term, LS-DYNA: 0.06; 0 with C_0 = 0: off)")
      ->capture_default_str();
}

nlohmann::ordered_json viscosity_summary(const BulkViscosity& q, const DynamicsResult& run) {
  return {{"on", q.on()},
          {"C_0_quadratic", q.quadratic},
          {"C_1_linear", q.linear},
          {"max_q_MPa", run.max_viscous_pressure_Pa * 1e-6},
          {"viscous_work_J", run.energy.empty() ? 0.0 : run.energy.back().viscous_J},
          {"min_step_factor", run.min_viscous_step_factor}};
}

}  // namespace mesowave::efg
