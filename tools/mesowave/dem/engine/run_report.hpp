#pragma once
// The run summary as JSON (mw-dem writes it; keys end in their unit).
#include <nlohmann/json.hpp>

#include "mesowave/dem/calibration/static_elastic.hpp"
#include "mesowave/dem/engine/simulation.hpp"

namespace mesowave::dem {

nlohmann::ordered_json to_json(const RunReport& report);
/// A [test]'s results (E_glob_GPa, nu_glob, peak_stress_MPa, inertial number ...), the "test" object of the summary.
nlohmann::ordered_json to_json(const UniaxialTestResult& test);
/// A static elastic test (mw-dem run --static): the keys mw-calibrate reads from a dynamic
/// summary (model, wall_s, test) and the solve's own (method, solver, iterations, times).
nlohmann::ordered_json to_json(const StaticElasticResult& result);

/// Signals as one CSV table for spreadsheets and gnuplot: `t_s` and one
/// column per signal (named "<name> [<unit>]") when they share a time base,
/// else a time column per signal.
std::string signals_csv(const std::vector<signal::Signal>& signals);

}  // namespace mesowave::dem
