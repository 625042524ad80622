#pragma once
// What mw-specimen writes (flowchart step 1): the density of one specimen
// from its mass and dimensions as given on the command line, or of a batch
// from a table of specimens (one row each) with the batch's mean and
// scatter - values in the units the user measures (g, mm), as lab sheets
// write them.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "mesowave/io/csv.hpp"
#include "mesowave/lab/specimen_density.hpp"

namespace mesowave::lab {

/// One specimen as measured (g, mm); a batch row's defaults.
struct SpecimenMeasurement {
  std::string shape = "cube";  ///< cube | prism | cylinder
  std::optional<double> mass_g, side_mm, length_mm, width_mm, height_mm, diameter_mm;
  double mass_resolution_g = 0.1;      ///< the balance's
  double length_resolution_mm = 0.01;  ///< the caliper's
};

/// Flat JSON: shape, mass_g, the shape's dimensions, the resolutions,
/// volume_m3, density_kg_m3, u_density_kg_m3. InputError for a missing or
/// non-positive mass or dimension (named by its option, e.g. --side-mm).
nlohmann::ordered_json specimen_density_summary(const SpecimenMeasurement& specimen);

struct DensityBatchReport {
  nlohmann::ordered_json summary;  ///< specimens, density_kg_m3 (mean), std, sem, u, min, max
  std::string table_csv;           ///< specimen, shape, mass_g, volume_m3, density_kg_m3, u_density_kg_m3
};

/// The batch of `table` (columns: specimen, shape, mass_g, side_mm |
/// length_mm width_mm height_mm | diameter_mm height_mm, and optionally
/// mass_resolution_g, length_resolution_mm, note); a row without shape or
/// resolutions takes `defaults`'. InputError naming the file (and line) for an
/// unknown column, no rows, or a missing or non-positive value.
DensityBatchReport density_batch_report(const io::CsvTable& table, const SpecimenMeasurement& defaults);

}  // namespace mesowave::lab
