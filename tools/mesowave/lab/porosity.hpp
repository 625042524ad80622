#pragma once
// Flowchart step 2: porosity from images (concrete paper, Section 3.1, Fig. 3).
//
// Two kinds of image, one method: microscope photographs of the specimen's
// outer faces, whose pores were filled with white plaster (pores BRIGHT), and
// reconstructed micro-CT slices, where air is the least dense phase (pores
// DARK). A gray-level threshold separates pore from solid inside a region of
// interest (ROI); the porosity is pore pixels / ROI pixels, per image, and for
// a CT stack of equally spaced slices the volume fraction is the same ratio
// summed over all slices (each voxel the same volume).
//
// The threshold is Otsu's (N. Otsu, "A threshold selection method from
// gray-level histograms", IEEE Trans. SMC 9 (1979) 62-66) unless a level is
// given: the level t that maximises the between-class variance
//     sigma_B^2(t) = (mu_T omega(t) - mu(t))^2 / (omega(t) (1 - omega(t)))      (Otsu Eq. 18)
// with omega(t) the fraction of pixels at levels <= t, mu(t) their first moment
// and mu_T the mean level. Classes are [0, t] and (t, L-1]: bright pores are
// the levels above t, dark pores the levels at or below t. Otsu's separability
// eta = sigma_B^2(t*) / sigma_T^2 (Eq. 12) says how bimodal the histogram is.
//
// Optionally, pore regions (connected pixels, 4- or 8-connectivity) smaller than
// a given area are returned to the solid: isolated noisy pixels are not pores.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mesowave/io/image.hpp"

namespace mesowave::lab {

enum class PoreTone { bright, dark };

struct OtsuThreshold {
  unsigned level = 0;         ///< classes [0, level] and (level, L-1]
  double separability = 0;    ///< eta = sigma_B^2 / sigma_T^2 in [0, 1]
};

/// Otsu's threshold of a gray-level histogram (counts per level). Where several
/// levels give the same maximum (empty levels between the classes) the lowest
/// is returned. InputError when fewer than two levels are occupied: a uniform
/// image has no threshold.
OtsuThreshold otsu_threshold(std::span<const std::uint64_t> histogram);

/// Histogram of the pixels of `image` where `roi` is non-zero (roi empty = all).
std::vector<std::uint64_t> gray_histogram(const io::GrayImage& image, const std::vector<std::uint8_t>& roi);

/// Which pixels count: a rectangle, a circle (CT slices are round), a mask
/// image (non-zero = specimen), or their intersection; nothing = whole image.
struct RegionOfInterest {
  std::optional<std::array<int, 4>> rect;      ///< x0, y0, width, height [px]
  std::optional<std::array<double, 3>> circle; ///< centre x, centre y, radius [px]
  const io::GrayImage* mask = nullptr;         ///< same size as the image
};

/// 1 inside the ROI, 0 outside. InputError if the rectangle leaves the image,
/// the mask has another size, or nothing is left.
std::vector<std::uint8_t> roi_mask(const io::GrayImage& image, const RegionOfInterest& roi);

struct PoreSegmentation {
  std::vector<std::uint8_t> pore;       ///< per pixel: 0 solid or outside the ROI, 1 pore, 2 pore region removed as too small
  std::size_t roi_px = 0;
  std::size_t pore_px = 0;              ///< pixels counted as pore (after removal)
  std::size_t regions = 0;              ///< pore regions kept
  std::size_t regions_removed = 0;
  std::size_t removed_px = 0;
};

/// Pixels beyond `threshold` on the pore side within the ROI, then pore regions
/// smaller than `min_region_px` (connectivity 4 or 8) removed.
PoreSegmentation segment_pores(const io::GrayImage& image, const std::vector<std::uint8_t>& roi, unsigned threshold,
                               PoreTone tone, std::size_t min_region_px, int connectivity);

struct PorosityOptions {
  PoreTone tone = PoreTone::dark;
  std::optional<unsigned> level;        ///< given threshold; otherwise Otsu
  bool otsu_per_image = false;          ///< Otsu on each image's histogram, or once on the whole set (a CT stack)
  std::size_t min_region_px = 0;
  int connectivity = 8;
};

struct ImagePorosity {
  std::string origin;
  int width = 0, height = 0;
  unsigned threshold = 0;
  double separability = 0;              ///< of the Otsu threshold used (0 for a given level)
  PoreSegmentation segmentation;
  double porosity() const {
    return segmentation.roi_px ? double(segmentation.pore_px) / double(segmentation.roi_px) : 0.0;
  }
};

struct PorosityResult {
  std::vector<ImagePorosity> images;
  std::size_t roi_px = 0, pore_px = 0;
  double porosity = 0;                  ///< sum of pore pixels / sum of ROI pixels (volume fraction of a stack)
  std::optional<OtsuThreshold> set_threshold;  ///< the one threshold of the whole set, if it had one
  std::vector<std::string> warnings;    ///< results that need a person's look (polarity, bimodality, ...)
};

/// Porosity of every image and of the whole set. `rois[i]` belongs to
/// `images[i]` (empty = whole image). All images of one set must share the bit
/// depth when one Otsu threshold serves the whole set.
PorosityResult measure_porosity(const std::vector<io::GrayImage>& images,
                                const std::vector<std::vector<std::uint8_t>>& rois, const PorosityOptions& options);

/// The image in gray with pores in red, removed small regions in yellow and
/// the outside of the ROI dimmed blue, downscaled by block averaging so that
/// neither side exceeds `max_side_px` (small images are enlarged by an integer
/// factor towards it).
io::RgbImage pore_overlay(const io::GrayImage& image, const PoreSegmentation& segmentation,
                          const std::vector<std::uint8_t>& roi, int max_side_px);

/// Tiles of equal cell size in a near-square grid on a dark background.
io::RgbImage montage(const std::vector<io::RgbImage>& tiles, int gap_px = 4);

}  // namespace mesowave::lab
