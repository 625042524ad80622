#include "mesowave/lab/porosity.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::lab {

namespace {

// Below this separability the histogram is hardly bimodal and Otsu's level is
// a guess a person should look at (eta is 1 for two pure levels).
constexpr double kWeakSeparability = 0.5;

std::string pct(double fraction) { return format_fixed(100.0 * fraction, 2) + " %"; }

}  // namespace

OtsuThreshold otsu_threshold(std::span<const std::uint64_t> histogram) {
  std::size_t occupied = 0;
  long double n = 0, m = 0;  // pixel count and first moment (sum of levels)
  for (std::size_t i = 0; i < histogram.size(); ++i) {
    if (histogram[i]) ++occupied;
    n += histogram[i];
    m += (long double)i * histogram[i];
  }
  if (occupied < 2)
    throw InputError(occupied == 0 ? "no pixels to threshold (empty region of interest)"
                                   : "all pixels have one gray level: Otsu's threshold is undefined (give a level)");
  const long double mu_t = m / n;
  long double var_t = 0;
  for (std::size_t i = 0; i < histogram.size(); ++i) var_t += histogram[i] * ((long double)i - mu_t) * ((long double)i - mu_t);
  var_t /= n;

  long double w0 = 0, m0 = 0, best = -1;
  unsigned best_level = 0;
  for (std::size_t t = 0; t + 1 < histogram.size(); ++t) {
    w0 += histogram[t];
    m0 += (long double)t * histogram[t];
    if (w0 <= 0 || w0 >= n) continue;
    const long double omega = w0 / n, mu = m0 / n;
    const long double d = mu_t * omega - mu;
    const long double sigma_b = d * d / (omega * (1 - omega));  // Otsu Eq. (18)
    if (sigma_b > best) {
      best = sigma_b;
      best_level = unsigned(t);
    }
  }
  return {best_level, double(best / var_t)};
}

std::vector<std::uint64_t> gray_histogram(const io::GrayImage& image, const std::vector<std::uint8_t>& roi) {
  std::vector<std::uint64_t> histogram(image.levels(), 0);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    if (roi.empty() || roi[i]) ++histogram[image.pixels[i]];
  return histogram;
}

std::vector<std::uint8_t> roi_mask(const io::GrayImage& image, const RegionOfInterest& roi) {
  const int w = image.width, h = image.height;
  std::vector<std::uint8_t> mask(image.pixels.size(), 1);
  if (roi.rect) {
    const auto [x0, y0, rw, rh] = *roi.rect;
    if (x0 < 0 || y0 < 0 || rw <= 0 || rh <= 0 || x0 + rw > w || y0 + rh > h)
      throw InputError("ROI rectangle " + std::to_string(x0) + "," + std::to_string(y0) + "," + std::to_string(rw) +
                       "," + std::to_string(rh) + " does not lie inside " + image.origin + " (" + std::to_string(w) +
                       " x " + std::to_string(h) + " px)");
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (x < x0 || x >= x0 + rw || y < y0 || y >= y0 + rh) mask[std::size_t(y) * w + x] = 0;
  }
  if (roi.circle) {
    const auto [cx, cy, r] = *roi.circle;
    if (!(r > 0)) throw InputError("ROI circle radius must be positive");
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;  // pixel centres
        if (dx * dx + dy * dy > r * r) mask[std::size_t(y) * w + x] = 0;
      }
  }
  if (roi.mask) {
    if (roi.mask->width != w || roi.mask->height != h)
      throw InputError("mask " + roi.mask->origin + " is " + std::to_string(roi.mask->width) + " x " +
                       std::to_string(roi.mask->height) + " px but " + image.origin + " is " + std::to_string(w) +
                       " x " + std::to_string(h) + " px");
    for (std::size_t i = 0; i < mask.size(); ++i)
      if (roi.mask->pixels[i] == 0) mask[i] = 0;
  }
  if (std::none_of(mask.begin(), mask.end(), [](std::uint8_t v) { return v != 0; }))
    throw InputError("the region of interest leaves no pixel of " + image.origin);
  return mask;
}

PoreSegmentation segment_pores(const io::GrayImage& image, const std::vector<std::uint8_t>& roi, unsigned threshold,
                               PoreTone tone, std::size_t min_region_px, int connectivity) {
  if (connectivity != 4 && connectivity != 8) throw InputError("connectivity must be 4 or 8");
  const int w = image.width, h = image.height;
  PoreSegmentation s;
  s.pore.assign(image.pixels.size(), 0);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (!roi.empty() && !roi[i]) continue;
    ++s.roi_px;
    const unsigned v = image.pixels[i];
    if (tone == PoreTone::bright ? v > threshold : v <= threshold) s.pore[i] = 1;
  }
  // Connected pore regions, labelled by flood fill with an explicit stack.
  std::vector<std::int32_t> label(image.pixels.size(), -1);
  std::vector<std::size_t> stack, members;
  for (std::size_t start = 0; start < s.pore.size(); ++start) {
    if (s.pore[start] != 1 || label[start] >= 0) continue;
    members.clear();
    stack.assign(1, start);
    label[start] = 1;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      members.push_back(i);
      const int x = int(i % std::size_t(w)), y = int(i / std::size_t(w));
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dx == 0 && dy == 0) || (connectivity == 4 && dx != 0 && dy != 0)) continue;
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          const std::size_t j = std::size_t(ny) * w + nx;
          if (s.pore[j] == 1 && label[j] < 0) {
            label[j] = 1;
            stack.push_back(j);
          }
        }
    }
    if (members.size() < min_region_px) {
      for (std::size_t i : members) s.pore[i] = 2;
      ++s.regions_removed;
      s.removed_px += members.size();
    } else {
      ++s.regions;
      s.pore_px += members.size();
    }
  }
  return s;
}

PorosityResult measure_porosity(const std::vector<io::GrayImage>& images,
                                const std::vector<std::vector<std::uint8_t>>& rois, const PorosityOptions& options) {
  if (images.empty()) throw InputError("no images to measure");
  if (rois.size() != images.size()) throw InputError("one region of interest per image is needed");
  for (const auto& image : images)
    if (options.level && *options.level >= image.levels())
      throw InputError("threshold level " + std::to_string(*options.level) + " lies outside the " +
                       std::to_string(image.bit_depth) + "-bit range of " + image.origin + " (0.." +
                       std::to_string(image.levels() - 1) + ")");

  PorosityResult result;
  if (!options.level && !options.otsu_per_image) {
    std::vector<std::uint64_t> total(images.front().levels(), 0);
    for (std::size_t i = 0; i < images.size(); ++i) {
      if (images[i].bit_depth != images.front().bit_depth)
        throw InputError("one Otsu threshold for the whole set needs one bit depth, but " + images[i].origin + " is " +
                         std::to_string(images[i].bit_depth) + " bit and " + images.front().origin + " is " +
                         std::to_string(images.front().bit_depth) + " bit");
      const auto h = gray_histogram(images[i], rois[i]);
      for (std::size_t l = 0; l < h.size(); ++l) total[l] += h[l];
    }
    try {
      result.set_threshold = otsu_threshold(total);
    } catch (const InputError& e) {
      throw InputError(std::string("the images (as one set): ") + e.what());
    }
  }

  for (std::size_t i = 0; i < images.size(); ++i) {
    const auto& image = images[i];
    ImagePorosity ip;
    ip.origin = image.origin;
    ip.width = image.width;
    ip.height = image.height;
    if (options.level) {
      ip.threshold = *options.level;
    } else if (result.set_threshold) {
      ip.threshold = result.set_threshold->level;
      ip.separability = result.set_threshold->separability;
    } else {
      try {
        const auto otsu = otsu_threshold(gray_histogram(image, rois[i]));
        ip.threshold = otsu.level;
        ip.separability = otsu.separability;
      } catch (const InputError& e) {
        throw InputError(image.origin + ": " + e.what());
      }
      if (ip.separability < kWeakSeparability)
        result.warnings.push_back(image.origin + ": gray levels are not clearly bimodal (Otsu separability " +
                                  format_fixed(ip.separability, 2) + " < " + format_fixed(kWeakSeparability, 1) +
                                  "); check the threshold on the overlay");
    }
    ip.segmentation = segment_pores(image, rois[i], ip.threshold, options.tone, options.min_region_px,
                                    options.connectivity);
    if (ip.segmentation.pore_px == 0)
      result.warnings.push_back(image.origin + ": no pore pixel found (porosity 0)");
    else if (ip.segmentation.pore_px == ip.segmentation.roi_px)
      result.warnings.push_back(image.origin + ": every pixel of the ROI counted as pore (porosity 100 %): wrong "
                                "pore polarity or threshold?");
    result.roi_px += ip.segmentation.roi_px;
    result.pore_px += ip.segmentation.pore_px;
    result.images.push_back(std::move(ip));
  }
  result.porosity = double(result.pore_px) / double(result.roi_px);
  if (result.set_threshold && result.set_threshold->separability < kWeakSeparability)
    result.warnings.push_back("gray levels of the set are not clearly bimodal (Otsu separability " +
                              format_fixed(result.set_threshold->separability, 2) + " < " +
                              format_fixed(kWeakSeparability, 1) + "); check the threshold on the overlay");
  if (result.porosity > 0.5)
    result.warnings.push_back("more than half of the ROI counted as pore (" + pct(result.porosity) +
                              "): pores are normally the minority phase; check the pore polarity (bright for "
                              "plaster-filled faces, dark for micro-CT)");
  return result;
}

io::RgbImage pore_overlay(const io::GrayImage& image, const PoreSegmentation& segmentation,
                          const std::vector<std::uint8_t>& roi, int max_side_px) {
  // Display range: 0.5 and 99.5 percentiles of the ROI, so 16-bit slices that
  // use a narrow band of levels are still visible.
  const auto histogram = gray_histogram(image, roi);
  std::uint64_t total = 0;
  for (auto c : histogram) total += c;
  auto percentile = [&](double q) {
    const double target = q * double(total);
    std::uint64_t acc = 0;
    for (std::size_t l = 0; l < histogram.size(); ++l) {
      acc += histogram[l];
      if (double(acc) >= target) return double(l);
    }
    return double(histogram.size() - 1);
  };
  double lo = percentile(0.005), hi = percentile(0.995);
  if (hi <= lo) {
    lo = 0;
    hi = double(image.levels() - 1);
  }
  const int w = image.width, h = image.height;
  const int factor = std::max(1, int(std::ceil(double(std::max(w, h)) / double(std::max(1, max_side_px)))));
  const int up = std::max(1, max_side_px / std::max(w, h));  // small images are enlarged (nearest neighbour)
  io::RgbImage out;
  out.width = (w + factor - 1) / factor;
  out.height = (h + factor - 1) / factor;
  out.rgb.assign(std::size_t(out.width) * out.height * 3, 0);
  for (int oy = 0; oy < out.height; ++oy)
    for (int ox = 0; ox < out.width; ++ox) {
      double acc[3] = {0, 0, 0};
      int n = 0;
      for (int y = oy * factor; y < std::min(h, (oy + 1) * factor); ++y)
        for (int x = ox * factor; x < std::min(w, (ox + 1) * factor); ++x) {
          const std::size_t i = std::size_t(y) * w + x;
          const double g = std::clamp((image.pixels[i] - lo) / (hi - lo), 0.0, 1.0) * 255.0;
          double c[3];
          if (!roi.empty() && !roi[i]) {
            c[0] = 0.3 * g;
            c[1] = 0.3 * g;
            c[2] = 0.3 * g + 60;
          } else if (segmentation.pore[i] == 1) {
            c[0] = 230;
            c[1] = 25;
            c[2] = 50;
          } else if (segmentation.pore[i] == 2) {
            c[0] = 255;
            c[1] = 200;
            c[2] = 0;
          } else {
            c[0] = c[1] = c[2] = g;
          }
          for (int k = 0; k < 3; ++k) acc[k] += c[k];
          ++n;
        }
      for (int k = 0; k < 3; ++k)
        out.rgb[(std::size_t(oy) * out.width + ox) * 3 + k] = std::uint8_t(std::lround(acc[k] / n));
    }
  if (up == 1) return out;
  io::RgbImage big;
  big.width = out.width * up;
  big.height = out.height * up;
  big.rgb.resize(std::size_t(big.width) * big.height * 3);
  for (int y = 0; y < big.height; ++y)
    for (int x = 0; x < big.width; ++x)
      for (int k = 0; k < 3; ++k)
        big.rgb[(std::size_t(y) * big.width + x) * 3 + k] = out.rgb[(std::size_t(y / up) * out.width + x / up) * 3 + k];
  return big;
}

io::RgbImage montage(const std::vector<io::RgbImage>& tiles, int gap_px) {
  if (tiles.empty()) throw InputError("no images for the overlay");
  if (tiles.size() == 1) return tiles.front();
  int cell_w = 0, cell_h = 0;
  for (const auto& t : tiles) {
    cell_w = std::max(cell_w, t.width);
    cell_h = std::max(cell_h, t.height);
  }
  const int cols = int(std::ceil(std::sqrt(double(tiles.size()))));
  const int rows = int((tiles.size() + cols - 1) / cols);
  io::RgbImage out;
  out.width = cols * cell_w + (cols + 1) * gap_px;
  out.height = rows * cell_h + (rows + 1) * gap_px;
  out.rgb.assign(std::size_t(out.width) * out.height * 3, 30);
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const int x0 = gap_px + int(k % cols) * (cell_w + gap_px), y0 = gap_px + int(k / cols) * (cell_h + gap_px);
    const auto& t = tiles[k];
    for (int y = 0; y < t.height; ++y)
      std::copy_n(t.rgb.begin() + std::size_t(y) * t.width * 3, std::size_t(t.width) * 3,
                  out.rgb.begin() + (std::size_t(y0 + y) * out.width + x0) * 3);
  }
  return out;
}

}  // namespace mesowave::lab
