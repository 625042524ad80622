#pragma once
// Grayscale raster images as laboratories hand them over: microscope photographs
// (PNG, often 8 bit, sometimes RGB) and reconstructed micro-CT slices (TIFF,
// 8 or 16 bit, one file per slice or one multi-page stack).
//
// Reading: PNG through libpng, TIFF through libtiff. Gray 8/16 bit is read as
// is; RGB(A) colour images are converted to gray with the Rec. 601 luma weights
// (0.299 R + 0.587 G + 0.114 B) and the conversion is reported in `note`;
// palette images are expanded first. Floating-point and 32-bit TIFF samples are
// refused with an InputError (rescale them to 16 bit first): thresholds are
// defined on integer gray levels here.
//
// Writing: 8/16-bit gray PNG, 8-bit RGB PNG (overlays), multi-page gray TIFF
// (deflate-compressed) for synthetic CT stacks.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace mesowave::io {

struct GrayImage {
  int width = 0;
  int height = 0;
  int bit_depth = 8;              ///< 8 or 16: gray levels are 0 .. 2^bit_depth - 1
  std::vector<std::uint16_t> pixels;  ///< row-major, width * height
  std::string origin;             ///< "file.tif[page 3]" for messages and tables
  std::string note;               ///< what the reader did to it ("RGB converted to gray"), or ""

  std::size_t size() const { return pixels.size(); }
  std::uint16_t at(int x, int y) const { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
  std::uint32_t levels() const { return 1u << bit_depth; }
};

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< row-major, 3 bytes per pixel
};

/// Every image in `path`: one for a PNG, one per page (directory) for a TIFF.
/// The format is chosen by the file's signature, not its name. InputError for
/// unreadable, empty (0 x 0), floating-point or otherwise unsupported files,
/// and for images over 2^27 pixels (a damaged header would claim gigabytes).
std::vector<GrayImage> read_gray_images(const std::filesystem::path& path);

GrayImage read_png_gray(const std::filesystem::path& path);
std::vector<GrayImage> read_tiff_gray(const std::filesystem::path& path);

void write_png_gray(const std::filesystem::path& path, const GrayImage& image);
void write_png_rgb(const std::filesystem::path& path, const RgbImage& image);
/// One page per image; all pages must share the bit depth.
void write_tiff_gray_stack(const std::filesystem::path& path, const std::vector<GrayImage>& pages);

}  // namespace mesowave::io
