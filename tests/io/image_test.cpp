// Grayscale image files: PNG (8/16 bit, RGB converted by Rec. 601 luma) and
// TIFF (multi-page 16-bit stacks) written and read back bit for bit.
#include <gtest/gtest.h>

#include "mesowave/core/error.hpp"
#include "mesowave/io/image.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;

namespace {

io::GrayImage ramp(int w, int h, int bits) {
  io::GrayImage g;
  g.width = w;
  g.height = h;
  g.bit_depth = bits;
  for (int i = 0; i < w * h; ++i) g.pixels.push_back(std::uint16_t((i * 2654435761u) % g.levels()));
  return g;
}

}  // namespace

TEST(Image, Png8And16BitRoundTrip) {
  test::TempDir dir;
  for (int bits : {8, 16}) {
    const auto g = ramp(13, 7, bits);
    const auto file = dir / ("g" + std::to_string(bits) + ".png");
    io::write_png_gray(file, g);
    const auto back = io::read_gray_images(file);
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].width, 13);
    EXPECT_EQ(back[0].height, 7);
    EXPECT_EQ(back[0].bit_depth, bits);
    EXPECT_EQ(back[0].pixels, g.pixels);
    EXPECT_TRUE(back[0].note.empty());
  }
}

TEST(Image, TiffMultiPage16BitStack) {
  test::TempDir dir;
  std::vector<io::GrayImage> pages = {ramp(9, 5, 16), ramp(9, 5, 16), ramp(9, 5, 16)};
  pages[1].pixels[3] = 65535;
  pages[2].pixels[0] = 1;
  io::write_tiff_gray_stack(dir / "s.tif", pages);
  const auto back = io::read_gray_images(dir / "s.tif");
  ASSERT_EQ(back.size(), 3u);
  for (std::size_t p = 0; p < 3; ++p) {
    EXPECT_EQ(back[p].bit_depth, 16);
    EXPECT_EQ(back[p].pixels, pages[p].pixels) << "page " << p;
  }
  EXPECT_EQ(back[2].origin, "s.tif[page 3]");
}

TEST(Image, RgbPngBecomesRec601Luma) {
  test::TempDir dir;
  io::RgbImage rgb;
  rgb.width = 3;
  rgb.height = 1;
  rgb.rgb = {255, 0, 0, 0, 255, 0, 10, 20, 200};
  io::write_png_rgb(dir / "c.png", rgb);
  const auto g = io::read_png_gray(dir / "c.png");
  // 0.299 R + 0.587 G + 0.114 B, rounded: 76.245 -> 76, 149.685 -> 150,
  // 2.99 + 11.74 + 22.8 = 37.53 -> 38.
  EXPECT_EQ(g.pixels, (std::vector<std::uint16_t>{76, 150, 38}));
  EXPECT_NE(g.note.find("RGB converted"), std::string::npos);
}

TEST(Image, RefusesWhatIsNotAnImage) {
  test::TempDir dir;
  test::write_file(dir / "x.png", "not an image at all");
  EXPECT_THROW(io::read_gray_images(dir / "x.png"), InputError);
  EXPECT_THROW(io::read_gray_images(dir / "missing.png"), InputError);
  test::write_file(dir / "t.png", std::string("\x89PNG\r\n\x1a\n", 8) + "truncated");
  EXPECT_THROW(io::read_gray_images(dir / "t.png"), InputError);
}
