#pragma once
// The shock viscosity's command-line options and summary, shared by `mw-efg wave` and `mw-efg blast`
// (efg/explicit_dynamics states the viscosity: q = rho l (C_0 l eps_dot_v^2 - C_1 c eps_dot_v) in
// compression).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "mesowave/efg/explicit_dynamics.hpp"

namespace mesowave::efg {

/// --viscosity-quadratic (C_0) and --viscosity-linear (C_1), both 0 (off) by default.
void add_viscosity_options(CLI::App& app, double& quadratic, double& linear);
/// C_0, C_1, whether on, the largest q [MPa], the viscous work [J] and the smallest step factor of the run.
nlohmann::ordered_json viscosity_summary(const BulkViscosity& q, const DynamicsResult& run);

}  // namespace mesowave::efg
