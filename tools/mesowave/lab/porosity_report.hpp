#pragma once
// What mw-porosity writes: the JSON summary, the per-image (per-slice) table -
// the porosity profile along a stack - its plot, and the overlay grid.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/lab/porosity.hpp"

namespace mesowave::lab {

struct PorosityReportContext {
  std::string kind;                    ///< face | ct | "" (polarity given directly)
  std::size_t files = 0;
  PorosityOptions options;
  std::optional<double> pixel_um;      ///< pixel size, if known
  double slice_spacing_mm = 0;         ///< 0: unknown (the profile is over slice numbers)
};

/// Flat JSON: porosity_pct of the set, statistics over images, threshold, warnings.
nlohmann::ordered_json porosity_summary(const PorosityResult& result, const std::vector<io::GrayImage>& images,
                                        const PorosityReportContext& context);

/// index, source, width_px, height_px, [z_mm,] threshold, otsu_separability, roi_px,
/// pore_px, porosity_pct, pore_regions, removed_regions, removed_px.
std::string porosity_csv(const PorosityResult& result, const PorosityReportContext& context);

/// gnuplot script: porosity per slice against z (or slice number), the set's value as a line.
std::string porosity_profile_script(const PorosityResult& result, const PorosityReportContext& context,
                                    const std::filesystem::path& png);

/// Overlays of at most `max_images` images, evenly spaced through the set, in a grid.
io::RgbImage porosity_overlay_grid(const PorosityResult& result, const std::vector<io::GrayImage>& images,
                                   const std::vector<std::vector<std::uint8_t>>& rois, std::size_t max_images,
                                   int tile_px);

}  // namespace mesowave::lab
