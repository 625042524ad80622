#pragma once
// mw-pack's work as a library call: a packing asked for in the units of the
// options (mm, %, g, kg/m3) - generated in a box or cylinder (concrete paper
// Section 4.2; packing_generator.hpp), a line of spheres (rod paper Section 3)
// or imported (packing_import.hpp) - given the specimen's mass through the
// particle density rho_p = m_specimen / sum(V_sphere), and its flat JSON
// summary (packing_stats.hpp). A line may take its rod from the study's
// experiment (experiment/experiment.hpp, rod_of): R = D / 2, the rod's length
// and density, each option given beating the file's.
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesowave/core/threads.hpp"
#include "mesowave/dem/packing/packing.hpp"
#include "mesowave/dem/packing/packing_file.hpp"
#include "mesowave/dem/packing/packing_stats.hpp"

namespace mesowave::dem {

/// The options of `mw-pack CONTAINER`, unchecked (make_packing checks them).
struct PackingRequest {
  std::string container;  ///< box | cylinder | line | import
  std::filesystem::path packing_file;  ///< where the packing goes (named in the summary)
  std::filesystem::path input;         ///< import: the Yade text or CSV file
  std::filesystem::path sieve_curve;   ///< box/cylinder: sizes by a sieve curve instead of d_min..d_max
  std::string import_format = "auto";  ///< auto (.csv is CSV, else Yade) | csv | yade
  std::optional<double> cube_side_mm, diameter_mm, height_mm, porosity_pct, d_min_mm, d_max_mm;
  std::vector<double> size_mm, lower_mm, upper_mm;  ///< box sides X Y Z; import container corners
  std::optional<double> sphere_radius_mm, spacing_mm, spacing_R, length_mm, rod_diameter_mm;  ///< line
  /// line: the rod of this experiment fills what is not given - the sphere radius R = D / 2 (rod paper
  /// Section 4.3.2: half the rod's diameter), the rod's diameter, length and density.
  std::filesystem::path experiment;
  std::optional<double> density_kg_m3, specimen_mass_g;  ///< one of them gives rho_p
  double detection_factor = 1.1;  ///< C_f of the reported bonds
  double force_tolerance = 1e-3;
  double overlap_stiffening = 3;
  std::uint64_t seed = 1;
  int threads = 0;  ///< requested threads (core/threads.hpp; 0: the machine's free cores)
};

struct PackedSpecimen {
  Packing packing;
  PackingOrigin origin;  ///< how it was made, for the packing file's /origin
  PackingStats stats;
  std::optional<double> specimen_mass_kg;  ///< when a density or mass was given (it set rho_p)
  ThreadChoice threads;  ///< the relaxation's threads (1 for a line or an import: nothing to relax)
  std::vector<std::filesystem::path> inputs;  ///< files read (sieve curve, imported packing)
  /// The flat summary: packing_file, container, ..., the statistics, the mass; no wall time.
  nlohmann::ordered_json summary;
};

/// Makes the requested packing. `relaxation_progress` (if set) is told the
/// fraction of the relaxation done, 0 to 1, from the residual force (it falls
/// from about 10 to the tolerance roughly geometrically). InputError for a
/// missing or contradictory option, naming it.
PackedSpecimen make_packing(const PackingRequest& request,
                            const std::function<void(double)>& relaxation_progress = {});

}  // namespace mesowave::dem
