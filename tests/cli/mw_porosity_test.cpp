// mw-porosity on the shipped synthetic set (micro-CT stack and microscope
// faces, truth beside them) and on the hard cases a lab can hand over.
#include <gtest/gtest.h>

#include "cli/labraw_support.hpp"
#include "mesowave/io/image.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::test;

// Issue 7's acceptance figure: porosity within 0.3 percentage points of the truth.
TEST(MwPorosity, ShippedCtStackWithinThreeTenthsOfAPointOfTruth) {
  TempDir dir;
  const auto r = run_tool("mw-porosity", {"--kind", "ct", (raw_dir() / "ct-stack.tif").string(), "--roi", "6,6,96,96",
                                          "--from", (raw_dir() / "ct-truth.toml").string(), "--csv",
                                          (dir / "slices.csv").string(), "--overlay", (dir / "ct.png").string(),
                                          "--out", (dir / "p.json").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = parse_json(r.out);
  EXPECT_EQ(j["images"], 32);
  EXPECT_EQ(j["pores"], "dark");
  EXPECT_NEAR(j["porosity_pct"].get<double>(), truth("ct-truth.toml", "true_porosity"), 0.3);
  // The per-slice profile against the per-slice truth.
  const auto csv = read_file(dir / "slices.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 33);
  EXPECT_NE(csv.find("z_mm"), std::string::npos);  // --from filled the slice spacing
  const auto overlay = io::read_gray_images(dir / "ct.png");
  EXPECT_GT(overlay.front().width, 300);
}

TEST(MwPorosity, ShippedFaceImagesWithinThreeTenthsOfAPointOfTruth) {
  const auto r = run_tool("mw-porosity", {"--kind", "face", (raw_dir() / "face-1.png").string(),
                                          (raw_dir() / "face-2.png").string(), (raw_dir() / "face-3.png").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = parse_json(r.out);
  EXPECT_EQ(j["pores"], "bright");
  EXPECT_EQ(j["threshold_method"], "Otsu per image");
  EXPECT_NEAR(j["porosity_pct"].get<double>(), truth("faces-truth.toml", "true_porosity"), 0.3);
  EXPECT_TRUE(j["warnings"].empty());
}

TEST(MwPorosity, UniformAndOnePixelImages) {
  TempDir dir;
  io::GrayImage black;
  black.width = black.height = 8;
  black.pixels.assign(64, 0);
  io::write_png_gray(dir / "black.png", black);
  io::GrayImage white = black;
  white.pixels.assign(64, 255);
  io::write_png_gray(dir / "white.png", white);
  io::GrayImage one;
  one.width = one.height = 1;
  one.pixels = {255};
  io::write_png_gray(dir / "one.png", one);
  for (const char* f : {"black.png", "white.png", "one.png"}) {
    const auto r = run_tool("mw-porosity", {"--kind", "ct", (dir / f).string(), "--out", (dir / "o.json").string()});
    EXPECT_EQ(r.exit_status, 1) << f;
    EXPECT_NE(r.err.find("one gray level"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "o.json"));  // nothing written
  }
  const auto r = run_tool("mw-porosity", {"--kind", "ct", (dir / "black.png").string(), "--level", "100"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_DOUBLE_EQ(parse_json(r.out)["porosity_pct"].get<double>(), 100.0);
  EXPECT_NE(r.err.find("warning:"), std::string::npos);
  EXPECT_NE(r.err.find("polarity"), std::string::npos);
}

TEST(MwPorosity, SaysWhatIsMissing) {
  const auto r = run_tool("mw-porosity", {(raw_dir() / "face-1.png").string()});
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_NE(r.err.find("--kind"), std::string::npos);
  const auto roi = run_tool("mw-porosity", {"--kind", "ct", (raw_dir() / "ct-stack.tif").string(), "--roi", "100,0,50,50"});
  EXPECT_EQ(roi.exit_status, 1);
  EXPECT_NE(roi.err.find("does not lie inside"), std::string::npos) << roi.err;
}
