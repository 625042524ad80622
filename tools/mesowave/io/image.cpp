#include "mesowave/io/image.hpp"

#include <png.h>
#include <tiffio.h>

#include <array>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>

#include "mesowave/core/error.hpp"

namespace mesowave::io {
namespace fs = std::filesystem;

namespace {

// A header of a few bytes can claim any size; the pixels are allocated before
// the data is read. Beyond this an image is refused, not allocated (gigabytes
// for a damaged header): 2^27 pixels, an 11585 x 11585 slice.
constexpr std::uint64_t kMaxPixels = std::uint64_t(1) << 27;

std::string too_many_pixels(const std::string& origin, std::uint64_t width, std::uint64_t height) {
  return origin + ": " + std::to_string(width) + " x " + std::to_string(height) +
         " pixels is more than mesowave reads in one image (2^27); crop or split it";
}

struct FileCloser {
  void operator()(std::FILE* f) const {
    if (f) std::fclose(f);
  }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

File open_file(const fs::path& path, const char* mode) {
  File f(std::fopen(path.c_str(), mode));
  if (!f) throw InputError("cannot open " + path.string() + (mode[0] == 'r' ? " for reading" : " for writing"));
  return f;
}

// Rec. 601 luma, rounded: the usual "convert to grayscale" of image programs.
std::uint16_t luma(double r, double g, double b) { return std::uint16_t(std::lround(0.299 * r + 0.587 * g + 0.114 * b)); }

// ---- PNG --------------------------------------------------------------------
// libpng reports errors by longjmp to the png_jmpbuf; the functions that call
// setjmp below hold no C++ object whose destructor a longjmp could skip (the
// buffers live in the caller's frame), so the jump is well defined.

struct PngMessage {
  char text[256] = {0};
};

void png_error_to_message(png_structp png, png_const_charp message) {
  auto* m = static_cast<PngMessage*>(png_get_error_ptr(png));
  std::snprintf(m->text, sizeof m->text, "%s", message ? message : "libpng error");
  std::longjmp(png_jmpbuf(png), 1);
}

void png_ignore_warning(png_structp, png_const_charp) {}

struct PngDecoded {
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, channels = 0;
  std::vector<png_byte> data;
  std::vector<png_bytep> rows;
};

// Returns false (message set) on a libpng error.
bool png_decode(std::FILE* f, PngDecoded* out, PngMessage* message) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, message, png_error_to_message, png_ignore_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, f);
  png_read_info(png, info);
  png_set_expand(png);  // palette -> RGB, gray < 8 bit -> 8 bit, tRNS -> alpha
  png_set_strip_alpha(png);
  if (png_get_bit_depth(png, info) == 16) png_set_swap(png);  // host (little-endian) order
  png_read_update_info(png, info);
  out->width = png_get_image_width(png, info);
  out->height = png_get_image_height(png, info);
  if (std::uint64_t(out->width) * out->height > kMaxPixels) {
    png_destroy_read_struct(&png, &info, nullptr);
    return true;  // the caller refuses it by its size
  }
  out->bit_depth = png_get_bit_depth(png, info);
  out->channels = png_get_channels(png, info);
  const std::size_t rowbytes = png_get_rowbytes(png, info);
  out->data.resize(rowbytes * out->height);
  out->rows.resize(out->height);
  for (png_uint_32 y = 0; y < out->height; ++y) out->rows[y] = out->data.data() + y * rowbytes;
  png_read_image(png, out->rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

struct PngToEncode {
  png_uint_32 width = 0, height = 0;
  int bit_depth = 8, color_type = PNG_COLOR_TYPE_GRAY;
  std::vector<png_bytep> rows;
};

bool png_encode(std::FILE* f, PngToEncode* in, PngMessage* message) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, message, png_error_to_message, png_ignore_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, in->width, in->height, in->bit_depth, in->color_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  if (in->bit_depth == 16) png_set_swap(png);
  png_write_image(png, in->rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

// ---- TIFF -------------------------------------------------------------------
// libtiff reports through global handlers; the last error is kept for the
// InputError that follows the failing call.

thread_local std::string tiff_last_error;

void tiff_error_handler(const char* module, const char* fmt, va_list ap) {
  char buffer[512];
  std::vsnprintf(buffer, sizeof buffer, fmt, ap);
  tiff_last_error = std::string(module ? module : "libtiff") + ": " + buffer;
}

void tiff_warning_handler(const char*, const char*, va_list) {}

struct TiffCloser {
  void operator()(TIFF* t) const {
    if (t) TIFFClose(t);
  }
};
using Tiff = std::unique_ptr<TIFF, TiffCloser>;

Tiff open_tiff(const fs::path& path, const char* mode) {
  TIFFSetErrorHandler(tiff_error_handler);
  TIFFSetWarningHandler(tiff_warning_handler);
  tiff_last_error.clear();
  Tiff t(TIFFOpen(path.c_str(), mode));
  if (!t)
    throw InputError("cannot open TIFF " + path.string() + (tiff_last_error.empty() ? "" : " (" + tiff_last_error + ")"));
  return t;
}

// Sample `s` of pixel `i` in a decoded row buffer of the given depth/format.
double tiff_sample(const std::uint8_t* buf, std::size_t index, int bits, bool is_signed) {
  if (bits == 1) return (buf[index / 8] >> (7 - index % 8)) & 1u;
  if (bits == 8) return is_signed ? double(std::int8_t(buf[index])) : double(buf[index]);
  std::uint16_t v;
  std::memcpy(&v, buf + 2 * index, 2);
  return is_signed ? double(std::int16_t(v)) : double(v);
}

GrayImage read_tiff_page(TIFF* tif, const fs::path& path, int page) {
  const std::string origin = path.filename().string() + "[page " + std::to_string(page + 1) + "]";
  std::uint32_t width = 0, height = 0;
  std::uint16_t bits = 1, spp = 1, format = SAMPLEFORMAT_UINT, photometric = PHOTOMETRIC_MINISBLACK,
                planar = PLANARCONFIG_CONTIG;
  TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &width);
  TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &height);
  TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &bits);
  TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &spp);
  TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &format);
  TIFFGetField(tif, TIFFTAG_PHOTOMETRIC, &photometric);
  TIFFGetFieldDefaulted(tif, TIFFTAG_PLANARCONFIG, &planar);
  if (width == 0 || height == 0) throw InputError(origin + ": empty image (0 x 0 pixels)");
  if (std::uint64_t(width) * height > kMaxPixels) throw InputError(too_many_pixels(origin, width, height));
  if (format == SAMPLEFORMAT_IEEEFP)
    throw InputError(origin + ": floating-point samples are not supported; rescale the slices to 16-bit integers");
  if (format != SAMPLEFORMAT_UINT && format != SAMPLEFORMAT_INT && format != SAMPLEFORMAT_VOID)
    throw InputError(origin + ": unsupported TIFF sample format " + std::to_string(format));
  if (bits != 1 && bits != 8 && bits != 16)
    throw InputError(origin + ": " + std::to_string(bits) + "-bit samples are not supported (only 1, 8 and 16 bit)");
  if (photometric == PHOTOMETRIC_PALETTE)
    throw InputError(origin + ": palette (indexed-colour) TIFF is not supported; save it as grayscale");
  // Its samples are not R, G, B, and subsampled chroma packs fewer than
  // width x 3 samples into a row (the reader would run past the row).
  if (photometric == PHOTOMETRIC_YCBCR)
    throw InputError(origin + ": YCbCr TIFF is not supported; save it as grayscale or RGB");
  if (spp != 1 && spp != 3 && spp != 4)
    throw InputError(origin + ": " + std::to_string(spp) + " samples per pixel (expected gray or RGB)");
  if (spp > 1 && planar != PLANARCONFIG_CONTIG)
    throw InputError(origin + ": separate colour planes are not supported; save it as grayscale");
  const bool is_signed = format == SAMPLEFORMAT_INT;

  GrayImage image;
  image.width = int(width);
  image.height = int(height);
  image.bit_depth = bits == 16 ? 16 : 8;
  image.origin = origin;
  image.pixels.assign(std::size_t(width) * height, 0);
  const double offset = is_signed ? (bits == 16 ? 32768.0 : bits == 8 ? 128.0 : 0.0) : 0.0;
  const double bilevel_scale = bits == 1 ? 255.0 : 1.0;
  const double full = double(image.levels() - 1);

  auto store = [&](const std::uint8_t* buf, std::uint32_t buf_width, std::uint32_t x0, std::uint32_t y,
                   std::uint32_t count) {
    // Signed samples are offset before the luma, so every value stays in
    // 0 .. full (a negative luma would not fit the gray level: found by UBSan).
    auto sample = [&](std::size_t index) { return tiff_sample(buf, index, bits, is_signed) + offset; };
    for (std::uint32_t i = 0; i < count; ++i) {
      double v;
      if (spp == 1) {
        v = sample(i);
      } else {
        const std::size_t base = std::size_t(i) * spp;
        v = luma(sample(base), sample(base + 1), sample(base + 2));
      }
      v *= bilevel_scale;
      if (photometric == PHOTOMETRIC_MINISWHITE) v = full - v;
      image.pixels[std::size_t(y) * width + x0 + i] = std::uint16_t(v);
    }
    (void)buf_width;
  };

  // store() reads spp samples of `bits` per pixel: a row buffer libtiff sizes
  // otherwise (a damaged or exotic layout) is refused, not overrun.
  auto holds = [&](tmsize_t row_bytes, std::uint32_t pixels) {
    return row_bytes > 0 && std::uint64_t(row_bytes) >= (std::uint64_t(pixels) * spp * bits + 7) / 8;
  };
  const std::string bad_layout = origin + ": rows smaller than their pixels (a damaged or unsupported TIFF layout)";

  tiff_last_error.clear();
  if (TIFFIsTiled(tif)) {
    std::uint32_t tw = 0, th = 0;
    TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tw);
    TIFFGetField(tif, TIFFTAG_TILELENGTH, &th);
    if (tw == 0 || th == 0) throw InputError(origin + ": tiles of " + std::to_string(tw) + " x " + std::to_string(th) + " pixels");
    const tmsize_t tile_size = TIFFTileSize(tif), tile_row_size = TIFFTileRowSize(tif);
    if (!holds(tile_row_size, tw) || tile_size / tile_row_size < tmsize_t(th)) throw InputError(bad_layout);
    std::vector<std::uint8_t> tile(static_cast<std::size_t>(tile_size));
    const std::size_t tile_row_bytes = std::size_t(tile_row_size);
    for (std::uint32_t ty = 0; ty < height; ty += th)
      for (std::uint32_t tx = 0; tx < width; tx += tw) {
        if (TIFFReadTile(tif, tile.data(), tx, ty, 0, 0) < 0)
          throw InputError(origin + ": cannot read tile (" + tiff_last_error + ")");
        for (std::uint32_t r = 0; r < th && ty + r < height; ++r)
          store(tile.data() + r * tile_row_bytes, tw, tx, ty + r, std::min(tw, width - tx));
      }
  } else {
    const tmsize_t row_size = TIFFScanlineSize(tif);
    if (!holds(row_size, width)) throw InputError(bad_layout);
    std::vector<std::uint8_t> row(static_cast<std::size_t>(row_size));
    for (std::uint32_t y = 0; y < height; ++y) {
      if (TIFFReadScanline(tif, row.data(), y, 0) < 0)
        throw InputError(origin + ": cannot read row " + std::to_string(y) + " (" + tiff_last_error + ")");
      store(row.data(), width, 0, y, width);
    }
  }
  std::string note;
  if (spp > 1) note = "RGB converted to gray (Rec. 601 luma)";
  if (is_signed) note += std::string(note.empty() ? "" : "; ") + "signed samples offset by " + std::to_string(int(offset));
  if (bits == 1) note += std::string(note.empty() ? "" : "; ") + "bilevel expanded to 0/255";
  if (photometric == PHOTOMETRIC_MINISWHITE) note += std::string(note.empty() ? "" : "; ") + "min-is-white inverted";
  image.note = note;
  return image;
}

bool starts_with_bytes(const fs::path& path, const std::vector<unsigned char>& magic) {
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> head(magic.size());
  in.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size()));
  return in.gcount() == std::streamsize(head.size()) && head == magic;
}

}  // namespace

GrayImage read_png_gray(const fs::path& path) {
  auto f = open_file(path, "rb");
  PngDecoded decoded;
  PngMessage message;
  if (!png_decode(f.get(), &decoded, &message))
    throw InputError("cannot read PNG " + path.string() + ": " + (message.text[0] ? message.text : "libpng failure"));
  if (decoded.width == 0 || decoded.height == 0) throw InputError(path.string() + ": empty image (0 x 0 pixels)");
  if (std::uint64_t(decoded.width) * decoded.height > kMaxPixels)
    throw InputError(too_many_pixels(path.string(), decoded.width, decoded.height));
  GrayImage image;
  image.width = int(decoded.width);
  image.height = int(decoded.height);
  image.bit_depth = decoded.bit_depth == 16 ? 16 : 8;
  image.origin = path.filename().string();
  image.pixels.resize(std::size_t(decoded.width) * decoded.height);
  const int ch = decoded.channels;
  for (png_uint_32 y = 0; y < decoded.height; ++y) {
    const png_byte* row = decoded.rows[y];
    for (png_uint_32 x = 0; x < decoded.width; ++x) {
      auto sample = [&](int c) -> double {
        const std::size_t i = std::size_t(x) * ch + c;
        if (image.bit_depth == 8) return row[i];
        std::uint16_t v;
        std::memcpy(&v, row + 2 * i, 2);
        return v;
      };
      const std::uint16_t v = (ch >= 3) ? luma(sample(0), sample(1), sample(2)) : std::uint16_t(sample(0));
      image.pixels[std::size_t(y) * decoded.width + x] = v;
    }
  }
  if (ch >= 3) image.note = "RGB converted to gray (Rec. 601 luma)";
  return image;
}

std::vector<GrayImage> read_tiff_gray(const fs::path& path) {
  auto tif = open_tiff(path, "r");
  std::vector<GrayImage> pages;
  int page = 0;
  do {
    pages.push_back(read_tiff_page(tif.get(), path, page++));
  } while (TIFFReadDirectory(tif.get()));
  return pages;
}

std::vector<GrayImage> read_gray_images(const fs::path& path) {
  if (!fs::is_regular_file(path)) throw InputError("image " + path.string() + " does not exist or is not a file");
  if (starts_with_bytes(path, {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'})) return {read_png_gray(path)};
  if (starts_with_bytes(path, {'I', 'I', 42, 0}) || starts_with_bytes(path, {'M', 'M', 0, 42}) ||
      starts_with_bytes(path, {'I', 'I', 43, 0}) || starts_with_bytes(path, {'M', 'M', 0, 43}))
    return read_tiff_gray(path);
  throw InputError(path.string() + " is neither a PNG nor a TIFF image (by its first bytes)");
}

void write_png_gray(const fs::path& path, const GrayImage& image) {
  if (image.width <= 0 || image.height <= 0 || image.pixels.size() != std::size_t(image.width) * image.height)
    throw InputError("cannot write " + path.string() + ": image size does not match its pixels");
  std::vector<std::uint8_t> bytes;
  if (image.bit_depth == 16) {
    bytes.resize(image.pixels.size() * 2);
    std::memcpy(bytes.data(), image.pixels.data(), bytes.size());
  } else {
    bytes.resize(image.pixels.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = std::uint8_t(image.pixels[i]);
  }
  PngToEncode enc;
  enc.width = png_uint_32(image.width);
  enc.height = png_uint_32(image.height);
  enc.bit_depth = image.bit_depth == 16 ? 16 : 8;
  enc.color_type = PNG_COLOR_TYPE_GRAY;
  const std::size_t row_bytes = std::size_t(image.width) * (enc.bit_depth / 8);
  for (int y = 0; y < image.height; ++y) enc.rows.push_back(bytes.data() + std::size_t(y) * row_bytes);
  auto f = open_file(path, "wb");
  PngMessage message;
  if (!png_encode(f.get(), &enc, &message)) throw InputError("cannot write PNG " + path.string() + ": " + message.text);
}

void write_png_rgb(const fs::path& path, const RgbImage& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgb.size() != std::size_t(image.width) * image.height * 3)
    throw InputError("cannot write " + path.string() + ": image size does not match its pixels");
  PngToEncode enc;
  enc.width = png_uint_32(image.width);
  enc.height = png_uint_32(image.height);
  enc.bit_depth = 8;
  enc.color_type = PNG_COLOR_TYPE_RGB;
  auto* base = const_cast<std::uint8_t*>(image.rgb.data());
  for (int y = 0; y < image.height; ++y) enc.rows.push_back(base + std::size_t(y) * image.width * 3);
  auto f = open_file(path, "wb");
  PngMessage message;
  if (!png_encode(f.get(), &enc, &message)) throw InputError("cannot write PNG " + path.string() + ": " + message.text);
}

void write_tiff_gray_stack(const fs::path& path, const std::vector<GrayImage>& pages) {
  if (pages.empty()) throw InputError("cannot write " + path.string() + ": no pages");
  auto tif = open_tiff(path, "w");
  const bool deflate = TIFFIsCODECConfigured(COMPRESSION_ADOBE_DEFLATE);
  for (std::size_t p = 0; p < pages.size(); ++p) {
    const GrayImage& page = pages[p];
    if (page.bit_depth != pages.front().bit_depth)
      throw InputError("cannot write " + path.string() + ": pages differ in bit depth");
    TIFFSetField(tif.get(), TIFFTAG_IMAGEWIDTH, std::uint32_t(page.width));
    TIFFSetField(tif.get(), TIFFTAG_IMAGELENGTH, std::uint32_t(page.height));
    TIFFSetField(tif.get(), TIFFTAG_BITSPERSAMPLE, std::uint16_t(page.bit_depth));
    TIFFSetField(tif.get(), TIFFTAG_SAMPLESPERPIXEL, std::uint16_t(1));
    TIFFSetField(tif.get(), TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
    TIFFSetField(tif.get(), TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(tif.get(), TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_UINT);
    TIFFSetField(tif.get(), TIFFTAG_ROWSPERSTRIP, std::uint32_t(page.height));
    if (deflate) {
      TIFFSetField(tif.get(), TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
      TIFFSetField(tif.get(), TIFFTAG_PREDICTOR, PREDICTOR_HORIZONTAL);
    }
    TIFFSetField(tif.get(), TIFFTAG_SUBFILETYPE, FILETYPE_PAGE);
    TIFFSetField(tif.get(), TIFFTAG_PAGENUMBER, std::uint16_t(p), std::uint16_t(pages.size()));
    std::vector<std::uint8_t> row(std::size_t(page.width) * (page.bit_depth / 8));
    for (int y = 0; y < page.height; ++y) {
      for (int x = 0; x < page.width; ++x) {
        const std::uint16_t v = page.at(x, y);
        if (page.bit_depth == 16) std::memcpy(row.data() + 2 * x, &v, 2);
        else row[x] = std::uint8_t(v);
      }
      if (TIFFWriteScanline(tif.get(), row.data(), std::uint32_t(y), 0) < 0)
        throw InputError("cannot write " + path.string() + " (" + tiff_last_error + ")");
    }
    if (!TIFFWriteDirectory(tif.get())) throw InputError("cannot write " + path.string() + " (" + tiff_last_error + ")");
  }
}

}  // namespace mesowave::io
