#include "mesowave/dem/engine/time_step.hpp"

#include <cmath>

namespace mesowave::dem {

CriticalTimeStep critical_time_step(const Model& model, double min_radius_m, double density, double E_dem_Pa,
                                    double damping) {
  CriticalTimeStep c;
  c.paper_estimate_s = min_radius_m * std::sqrt(density / E_dem_Pa);
  const double gershgorin = model.scaled_stiffness_row_sum_bound();
  c.stiffness_bound_s = gershgorin > 0 ? 2.0 / std::sqrt(gershgorin) : INFINITY;
  const Model::Rows rows = model.stiffness_rows();
  const auto lanczos = largest_eigenvalue(
      LanczosRows{model.degrees_of_freedom(), rows.first, rows.count},
      [&](const double* x, double* y) { model.scaled_stiffness_action(x, y); },
      [&](const double* a, const double* b) { return model.stiffness_dot(a, b); });
  // The top Ritz value approaches lambda_max from below; adding its residual
  // keeps the estimate on the safe side. Gershgorin caps it.
  c.lambda_max = std::min(lanczos.ritz + lanczos.residual, gershgorin);
  c.lanczos_iterations = lanczos.iterations;
  c.eigenvalue_s = c.lambda_max > 0 ? 2.0 / std::sqrt(c.lambda_max) : INFINITY;
  c.limit_s = c.eigenvalue_s / std::sqrt(1.0 + damping);
  return c;
}

}  // namespace mesowave::dem
