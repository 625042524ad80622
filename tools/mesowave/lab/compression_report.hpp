#pragma once
// What mw-compress writes: the JSON summary, the per-cycle table, the curves
// as CSV and a figure like the concrete paper's Fig. 5 (gnuplot script).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/lab/compression_analysis.hpp"

namespace mesowave::lab {

struct CompressionAnalysis {
  std::optional<CompressionRecord> cyclic_record, failure_record;
  std::optional<CyclicResult> cyclic;
  std::optional<CrossheadFit> fit;
  std::optional<FailureResult> failure;
  double area_m2 = 0;
  double gauge_length_m = 0;
  std::optional<double> specimen_height_m;
  std::optional<double> multiplier;        ///< the one applied to the failure test's crosshead
  std::string multiplier_source;           ///< "fitted on the cyclic test" or "given"
  std::string geometry_note;               ///< where the area came from
};

/// Flat JSON (keys end in their unit): E_st_GPa (and E_st_measured_GPa for
/// mw-estatic --from), sigma_max_MPa, crosshead_multiplier with its fit, the
/// readings, warnings and notes.
nlohmann::ordered_json compression_summary(const CompressionAnalysis& a);
/// The summary's products (the --from contract, app::declare_products): the step-4 results a
/// later tool takes - E_st_measured_GPa (mw-estatic, mw-calibrate cube) with a cyclic test,
/// sigma_max_MPa (mw-calibrate cube) with a failure test; every other entry is the record.
std::vector<std::string> compression_products(const CompressionAnalysis& a);

/// One row per load cycle: readings, holds, loading rate, secant modulus.
std::string cycles_csv(const CompressionAnalysis& a);
/// t_s, stress_MPa, mean extensometer strain, crosshead strain, corrected strain.
std::string cyclic_curve_csv(const CompressionAnalysis& a);
std::string failure_curve_csv(const CompressionAnalysis& a);

/// gnuplot script for a two-panel figure like Fig. 5: (a) stress-time of the
/// cyclic test with the readings marked; (b) stress-strain of the cyclic test
/// (extensometers; crosshead as recorded) and of the failure test (crosshead x
/// multiplier).
std::string figure5_script(const CompressionAnalysis& a, const std::filesystem::path& png, const std::string& title);

}  // namespace mesowave::lab
