// mw-porosity - flowchart step 2: porosity from microscope images of the faces
// (pores filled with white plaster: bright) or micro-CT slices (pores dark),
// concrete paper Section 3.1, Fig. 3.
//
//   mw-porosity --kind ct lab-data/concrete-cube/raw/ct-stack.tif --csv slices.csv --overlay ct.png
//   mw-porosity --kind face lab-data/concrete-cube/raw/face-*.png --overlay faces.png --out porosity.json
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/io/gnuplot.hpp"
#include "mesowave/io/image.hpp"
#include "mesowave/lab/porosity_report.hpp"

using namespace mesowave;

int main(int argc, char** argv) {
  app::Tool tool(
      "mw-porosity",
      "Porosity p = pore pixels / ROI pixels of grayscale images (PNG or TIFF, 8 or 16 bit, multi-page TIFF stacks): "
      "per image, for the whole set (the volume fraction of a CT stack of equally spaced slices) and as a profile "
      "along the stack. Pores are the pixels beyond a threshold: Otsu's (maximum between-class variance, the default) "
      "or a given level; with --kind face they are bright (plaster-filled pores on microscope images, Otsu per "
      "image), with --kind ct dark (air in micro-CT slices, one Otsu threshold for the stack). Pore regions smaller "
      "than --min-pore-area-px can be returned to the solid. An overlay PNG shows what was counted (pores red, "
      "removed regions yellow, outside the ROI blue).\n\n"
      "  mw-porosity --kind ct ct-stack.tif --roi-circle 48,48,46 --csv slices.csv --overlay ct.png --out p.json\n"
      "  mw-porosity --kind face face-1.png face-2.png --min-pore-area-px 4 --overlay faces.png");
  std::vector<std::string> files;
  std::string kind, pores, otsu_scope;
  std::optional<unsigned> level;
  std::vector<int> roi_rect;
  std::vector<double> roi_circle;
  std::filesystem::path mask_file, csv_file, overlay_file, profile_file, out;
  std::size_t min_area_px = 0;
  std::optional<double> min_area_mm2, pixel_um, spacing_um;
  int connectivity = 8, overlay_max = 16, overlay_tile = 360;
  auto& cli = tool.cli();
  cli.add_option("images", files, "PNG or TIFF files (a multi-page TIFF is a stack of slices)")->required();
  cli.add_option("--kind", kind, "face: microscope image of a face, pores filled with white plaster (bright); ct: "
                                 "micro-CT slices (pores dark)")
      ->check(CLI::IsMember({"face", "ct"}));
  cli.add_option("--pores", pores, "Pore polarity, overriding --kind: bright or dark")
      ->check(CLI::IsMember({"bright", "dark"}));
  cli.add_option("--level", level, "Threshold gray level instead of Otsu's (bright pores: > level; dark: <= level)");
  cli.add_option("--otsu-scope", otsu_scope, "Otsu threshold per image, or one for the whole set (default: image for "
                                             "--kind face, set for --kind ct)")
      ->check(CLI::IsMember({"image", "set"}));
  cli.add_option("--roi", roi_rect, "Region of interest rectangle x0,y0,width,height [px]")->delimiter(',')->expected(4);
  cli.add_option("--roi-circle", roi_circle, "Circular region of interest cx,cy,radius [px]")->delimiter(',')->expected(3);
  cli.add_option("--mask", mask_file, "Mask image of the same size: non-zero pixels are specimen")->type_name("FILE");
  cli.add_option("--min-pore-area-px", min_area_px, "Remove pore regions smaller than this many pixels");
  cli.add_option("--min-pore-area-mm2", min_area_mm2, "Remove pore regions smaller than this area (needs --pixel-size-um)");
  cli.add_option("--pixel-size-um", pixel_um, "Pixel size [um] (areas in mm2, z along the stack)");
  cli.add_option("--slice-spacing-um", spacing_um, "Distance between CT slices [um] (default: the pixel size)");
  cli.add_option("--connectivity", connectivity, "Pixel neighbourhood of a pore region: 4 or 8")->capture_default_str();
  cli.add_option("--csv", csv_file, "Per-image (per-slice) table: the porosity profile along the stack")->type_name("FILE");
  cli.add_option("--overlay", overlay_file, "PNG with pores coloured on the images (a grid if several)")->type_name("FILE");
  cli.add_option("--overlay-max-images", overlay_max, "At most this many images in the overlay grid (evenly spaced)")
      ->capture_default_str();
  cli.add_option("--overlay-tile-px", overlay_tile, "Longest side of each overlay tile [px]")->capture_default_str();
  cli.add_option("--profile-plot", profile_file, "PNG plot of porosity against slice (gnuplot)")->type_name("FILE");
  app::add_out_option(cli, out);

  return tool.run(argc, argv, [&](app::Run& run) {
    if (kind.empty() && pores.empty())
      throw InputError("say what the images are: --kind face (plaster-filled pores, bright) or --kind ct (pores dark), "
                       "or give --pores bright|dark");
    const bool bright = pores.empty() ? kind == "face" : pores == "bright";
    const bool per_image = otsu_scope.empty() ? kind == "face" : otsu_scope == "image";
    if (connectivity != 4 && connectivity != 8) throw InputError("--connectivity must be 4 or 8");
    if (pixel_um) require_positive("--pixel-size-um", *pixel_um, "um");
    if (spacing_um) require_positive("--slice-spacing-um", *spacing_um, "um");
    if (min_area_mm2) {
      if (!pixel_um) throw InputError("--min-pore-area-mm2 needs --pixel-size-um");
      require_positive("--min-pore-area-mm2", *min_area_mm2, "mm2");
      const double px_mm2 = (*pixel_um * 1e-3) * (*pixel_um * 1e-3);
      min_area_px = std::max<std::size_t>(min_area_px, std::size_t(std::ceil(*min_area_mm2 / px_mm2)));
    }
    if (overlay_max < 1 || overlay_tile < 16) throw InputError("--overlay-max-images must be >= 1, --overlay-tile-px >= 16");

    std::vector<io::GrayImage> images;
    for (const auto& f : files) {
      run.input(f);
      for (auto& image : io::read_gray_images(f)) images.push_back(std::move(image));
    }
    std::optional<io::GrayImage> mask;
    lab::RegionOfInterest roi;
    if (!mask_file.empty()) {
      run.input(mask_file);
      auto masks = io::read_gray_images(mask_file);
      if (masks.size() != 1) throw InputError("--mask " + mask_file.string() + " must hold one image");
      mask = std::move(masks.front());
      roi.mask = &*mask;
    }
    if (!roi_rect.empty()) roi.rect = std::array<int, 4>{roi_rect[0], roi_rect[1], roi_rect[2], roi_rect[3]};
    if (!roi_circle.empty()) roi.circle = std::array<double, 3>{roi_circle[0], roi_circle[1], roi_circle[2]};
    std::vector<std::vector<std::uint8_t>> rois;
    for (const auto& image : images) rois.push_back(lab::roi_mask(image, roi));

    lab::PorosityOptions options;
    options.tone = bright ? lab::PoreTone::bright : lab::PoreTone::dark;
    options.level = level;
    options.otsu_per_image = per_image;
    options.min_region_px = min_area_px;
    options.connectivity = connectivity;
    const auto result = lab::measure_porosity(images, rois, options);
    for (const auto& image : images)
      if (!image.note.empty()) std::cerr << "note: " << image.origin << ": " << image.note << "\n";
    for (const auto& w : result.warnings) std::cerr << "warning: " << w << "\n";

    lab::PorosityReportContext context{kind, files.size(), options, pixel_um,
                                       spacing_um ? *spacing_um * 1e-3 : (pixel_um ? *pixel_um * 1e-3 : 0.0)};
    const auto j = lab::porosity_summary(result, images, context);
    run.metric("porosity", 100.0 * result.porosity, "%");
    run.param("pores", bright ? "bright" : "dark");
    if (!csv_file.empty()) run.write_text(csv_file, lab::porosity_csv(result, context));
    if (!overlay_file.empty())
      io::write_png_rgb(run.output(overlay_file),
                        lab::porosity_overlay_grid(result, images, rois, std::size_t(overlay_max), overlay_tile));
    if (!profile_file.empty()) io::run_gnuplot(lab::porosity_profile_script(result, context, run.output(profile_file)));
    run.emit_json(j, out);
  });
}
