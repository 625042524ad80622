#include "mesowave/lab/porosity_report.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/format.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/gnuplot.hpp"

namespace mesowave::lab {

namespace {
std::vector<double> porosity_pct(const PorosityResult& r) {
  std::vector<double> p;
  for (const auto& ip : r.images) p.push_back(100.0 * ip.porosity());
  return p;
}
}  // namespace

nlohmann::ordered_json porosity_summary(const PorosityResult& result, const std::vector<io::GrayImage>& images,
                                        const PorosityReportContext& c) {
  const auto p = porosity_pct(result);
  double mean = 0, sd = 0;
  for (double v : p) mean += v / double(p.size());
  for (double v : p) sd += (v - mean) * (v - mean);
  sd = p.size() > 1 ? std::sqrt(sd / double(p.size() - 1)) : 0.0;
  std::size_t regions = 0, removed_regions = 0, removed_px = 0;
  for (const auto& ip : result.images) {
    regions += ip.segmentation.regions;
    removed_regions += ip.segmentation.regions_removed;
    removed_px += ip.segmentation.removed_px;
  }
  const bool bright = c.options.tone == PoreTone::bright;
  nlohmann::ordered_json j;
  j["images"] = result.images.size();
  j["files"] = c.files;
  j["kind"] = c.kind.empty() ? "unspecified" : c.kind;
  j["pores"] = bright ? "bright" : "dark";
  j["bit_depth"] = images.front().bit_depth;
  j["threshold_method"] = c.options.level ? "given level"
                          : c.options.otsu_per_image ? "Otsu per image" : "Otsu over the whole set";
  if (c.options.level) {
    j["threshold"] = *c.options.level;
  } else if (result.set_threshold) {
    j["threshold"] = result.set_threshold->level;
    j["otsu_separability"] = result.set_threshold->separability;
  }
  j["porosity_pct"] = 100.0 * result.porosity;
  j["porosity_image_mean_pct"] = mean;
  j["porosity_image_sd_pct"] = sd;
  j["porosity_image_min_pct"] = *std::min_element(p.begin(), p.end());
  j["porosity_image_max_pct"] = *std::max_element(p.begin(), p.end());
  j["roi_px"] = result.roi_px;
  j["pore_px"] = result.pore_px;
  j["pore_regions"] = regions;
  j["min_pore_area_px"] = c.options.min_region_px;
  j["removed_regions"] = removed_regions;
  j["removed_px"] = removed_px;
  if (c.pixel_um) {
    j["pixel_size_um"] = *c.pixel_um;
    j["roi_area_mm2"] = double(result.roi_px) * std::pow(*c.pixel_um * 1e-3, 2);
  }
  j["warnings"] = result.warnings;
  return j;
}

std::string porosity_csv(const PorosityResult& result, const PorosityReportContext& c) {
  std::vector<std::string> header = {"index", "source", "width_px", "height_px"};
  if (c.slice_spacing_mm > 0) header.push_back("z_mm");
  header.insert(header.end(), {"threshold", "otsu_separability", "roi_px", "pore_px", "porosity_pct", "pore_regions",
                               "removed_regions", "removed_px"});
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < result.images.size(); ++i) {
    const auto& ip = result.images[i];
    const auto& s = ip.segmentation;
    std::vector<std::string> row = {std::to_string(i + 1), ip.origin, std::to_string(ip.width), std::to_string(ip.height)};
    if (c.slice_spacing_mm > 0) row.push_back(format_fixed(double(i) * c.slice_spacing_mm, 4));
    row.insert(row.end(), {std::to_string(ip.threshold), format_fixed(ip.separability, 4), std::to_string(s.roi_px),
                           std::to_string(s.pore_px), format_fixed(100.0 * ip.porosity(), 4), std::to_string(s.regions),
                           std::to_string(s.regions_removed), std::to_string(s.removed_px)});
    rows.push_back(std::move(row));
  }
  return io::to_csv(header, rows);
}

std::string porosity_profile_script(const PorosityResult& result, const PorosityReportContext& c,
                                    const std::filesystem::path& png) {
  std::vector<double> x, p = porosity_pct(result);
  for (std::size_t i = 0; i < p.size(); ++i) x.push_back(c.slice_spacing_mm > 0 ? double(i) * c.slice_spacing_mm : double(i + 1));
  const std::string whole = format_exact(100.0 * result.porosity);
  return "set terminal pngcairo size 900,500 font 'Sans,11'\nset output " + io::gnuplot_quote(png) + "\n" +
         io::gnuplot_datablock("p", {x, p}) + "set xlabel '" + (c.slice_spacing_mm > 0 ? "z [mm]" : "slice") +
         "'\nset ylabel 'porosity [%]'\nset grid\nset key top right\nset title 'Porosity profile (" +
         (c.options.tone == PoreTone::bright ? "bright" : "dark") +
         " pores)'\nplot $p using 1:2 with linespoints pt 7 ps 0.6 lc rgb '#c0392b' title 'per slice', " + whole +
         " with lines dt 2 lw 2 lc rgb '#2c3e50' title sprintf('whole set %.2f %%', " + whole + ")\n";
}

io::RgbImage porosity_overlay_grid(const PorosityResult& result, const std::vector<io::GrayImage>& images,
                                   const std::vector<std::vector<std::uint8_t>>& rois, std::size_t max_images,
                                   int tile_px) {
  const std::size_t n = images.size(), m = std::min(n, std::max<std::size_t>(1, max_images));
  std::vector<io::RgbImage> tiles;
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t i = m == 1 ? n / 2 : std::size_t(std::lround(double(k) * double(n - 1) / double(m - 1)));
    tiles.push_back(pore_overlay(images[i], result.images[i].segmentation, rois[i], tile_px));
  }
  return montage(tiles);
}

}  // namespace mesowave::lab
