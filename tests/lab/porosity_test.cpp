// Porosity from images: Otsu's threshold against a hand-computed histogram and
// against a second method (minimum within-class variance), connected pore
// regions, ROIs, the hard cases (uniform images, one pixel, 16-bit slices) and
// recovery of the synthetic ground truth.
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/lab/porosity.hpp"
#include "mesowave/lab/synthetic_pores.hpp"

using namespace mesowave;
using namespace mesowave::lab;

namespace {

io::GrayImage image(int w, int h, std::vector<std::uint16_t> px, int bits = 8) {
  io::GrayImage g;
  g.width = w;
  g.height = h;
  g.bit_depth = bits;
  g.pixels = std::move(px);
  g.origin = "test image";
  return g;
}

// Otsu's criterion the other way round: the level that minimises the
// within-class variance omega0 var0 + omega1 var1 (Otsu 1979, Eq. 13-15).
unsigned min_within_class_variance(const std::vector<std::uint64_t>& h) {
  double best = 0;
  bool found = false;
  unsigned level = 0;
  for (std::size_t t = 0; t + 1 < h.size(); ++t) {
    double n0 = 0, s0 = 0, q0 = 0, n1 = 0, s1 = 0, q1 = 0;
    for (std::size_t i = 0; i < h.size(); ++i) {
      const double c = double(h[i]), v = double(i);
      if (i <= t) n0 += c, s0 += c * v, q0 += c * v * v;
      else n1 += c, s1 += c * v, q1 += c * v * v;
    }
    if (n0 == 0 || n1 == 0) continue;
    const double within = (q0 - s0 * s0 / n0) + (q1 - s1 * s1 / n1);
    if (!found || within < best - 1e-9 * std::abs(best)) best = within, level = unsigned(t), found = true;
  }
  return level;
}

}  // namespace

TEST(Otsu, HandComputedHistogram) {
  // Levels 0, 1, 3 with counts 1, 1, 2: N = 4, mu_T = 7/4, var_T = 27/16.
  // sigma_B^2(0) = 49/48, sigma_B^2(1) = sigma_B^2(2) = 25/16 (level 2 is empty):
  // the lowest maximiser is 1, and eta = (25/16) / (27/16) = 25/27.
  const std::vector<std::uint64_t> h = {1, 1, 0, 2};
  const auto t = otsu_threshold(h);
  EXPECT_EQ(t.level, 1u);
  EXPECT_NEAR(t.separability, 25.0 / 27.0, 1e-12);
}

TEST(Otsu, AgreesWithMinimumWithinClassVariance) {
  std::uint64_t state = 12345;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::uint64_t> h(2 + trial % 40);
    for (auto& c : h) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      c = (state >> 33) % 50;
    }
    h.front() += 1, h.back() += 1;  // two occupied levels at least
    EXPECT_EQ(otsu_threshold(h).level, min_within_class_variance(h)) << "trial " << trial;
  }
}

TEST(Otsu, UniformAndEmptyHistogramsHaveNoThreshold) {
  EXPECT_THROW(otsu_threshold(std::vector<std::uint64_t>{0, 0, 7, 0}), InputError);
  EXPECT_THROW(otsu_threshold(std::vector<std::uint64_t>{0, 0, 0}), InputError);
}

TEST(Porosity, AllBlackAndAllWhiteImages) {
  const auto black = image(4, 4, std::vector<std::uint16_t>(16, 0));
  const auto white = image(4, 4, std::vector<std::uint16_t>(16, 255));
  PorosityOptions otsu;
  EXPECT_THROW(measure_porosity({black}, {{}}, otsu), InputError);
  EXPECT_THROW(measure_porosity({white}, {{}}, otsu), InputError);
  // With a given level the numbers are exact, and said to need a look.
  PorosityOptions given;
  given.level = 128;
  given.tone = PoreTone::dark;
  auto r = measure_porosity({black}, {{}}, given);
  EXPECT_DOUBLE_EQ(r.porosity, 1.0);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.front().find("100 %"), std::string::npos);
  given.tone = PoreTone::bright;
  r = measure_porosity({black}, {{}}, given);
  EXPECT_DOUBLE_EQ(r.porosity, 0.0);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.front().find("no pore pixel"), std::string::npos);
  given.level = 300;  // outside the 8-bit range
  EXPECT_THROW(measure_porosity({white}, {{}}, given), InputError);
}

TEST(Porosity, OnePixelImage) {
  const auto one = image(1, 1, {200});
  EXPECT_THROW(measure_porosity({one}, {{}}, PorosityOptions{}), InputError);
  PorosityOptions given;
  given.level = 100;
  given.tone = PoreTone::bright;
  const auto r = measure_porosity({one}, {{}}, given);
  EXPECT_EQ(r.roi_px, 1u);
  EXPECT_DOUBLE_EQ(r.porosity, 1.0);
  EXPECT_FALSE(r.warnings.empty());
}

TEST(Porosity, SmallRegionsAndConnectivity) {
  // 6 x 6: a 3x3 bright block, one isolated bright pixel, and a diagonal pair.
  std::vector<std::uint16_t> px(36, 10);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) px[std::size_t(y * 6 + x)] = 250;
  px[5] = 250;               // (5, 0) isolated
  px[4 * 6 + 4] = 250;       // (4, 4)
  px[5 * 6 + 5] = 250;       // (5, 5) diagonal to it
  const auto g = image(6, 6, px);
  auto s8 = segment_pores(g, {}, 100, PoreTone::bright, 2, 8);
  EXPECT_EQ(s8.regions, 2u);          // the block and the diagonal pair
  EXPECT_EQ(s8.regions_removed, 1u);  // the single pixel
  EXPECT_EQ(s8.pore_px, 11u);
  auto s4 = segment_pores(g, {}, 100, PoreTone::bright, 2, 4);
  EXPECT_EQ(s4.regions, 1u);          // the pair falls apart into two single pixels
  EXPECT_EQ(s4.regions_removed, 3u);
  EXPECT_EQ(s4.pore_px, 9u);
}

TEST(Porosity, RegionsOfInterest) {
  const auto g = image(5, 5, std::vector<std::uint16_t>(25, 0));
  RegionOfInterest circle;
  circle.circle = std::array<double, 3>{2.5, 2.5, 2.0};
  const auto m = roi_mask(g, circle);
  // Pixel centres within 2 px of the centre: dx^2 + dy^2 <= 4 for dx, dy in -2..2.
  EXPECT_EQ(std::count(m.begin(), m.end(), 1), 13);
  RegionOfInterest rect;
  rect.rect = std::array<int, 4>{1, 1, 3, 2};
  const auto r = roi_mask(g, rect);
  EXPECT_EQ(std::count(r.begin(), r.end(), 1), 6);
  rect.rect = std::array<int, 4>{3, 3, 3, 3};
  EXPECT_THROW(roi_mask(g, rect), InputError);  // leaves the image
}

TEST(Porosity, SixteenBitCtStackRecoversTheTruth) {
  for (auto shape : {PoreShape::sphere, PoreShape::irregular}) {
    SyntheticCtSpec spec;
    spec.specimen_px = 48;
    spec.slices = 12;
    spec.shape = shape;
    spec.seed = 21;
    const auto ct = synthetic_ct_stack(spec);
    ASSERT_EQ(ct.slices.front().bit_depth, 16);
    RegionOfInterest roi;
    roi.rect = ct.specimen_roi;
    std::vector<std::vector<std::uint8_t>> rois;
    for (const auto& s : ct.slices) rois.push_back(roi_mask(s, roi));
    PorosityOptions o;
    o.tone = PoreTone::dark;
    const auto r = measure_porosity(ct.slices, rois, o);
    ASSERT_TRUE(r.set_threshold);
    EXPECT_GT(r.set_threshold->level, 255u);  // a genuinely 16-bit threshold
    EXPECT_NEAR(100 * r.porosity, 100 * ct.true_porosity, 0.3);
    EXPECT_NEAR(100 * ct.true_porosity, 7.0, 0.5);  // the generator aimed at 7 %
  }
}

TEST(Porosity, FaceImagesRecoverTheTruth) {
  for (auto shape : {PoreShape::sphere, PoreShape::irregular}) {
    SyntheticFaceSpec spec;
    spec.width_px = spec.height_px = 160;
    spec.shape = shape;
    spec.seed = 5;
    const auto face = synthetic_face(spec);
    PorosityOptions o;
    o.tone = PoreTone::bright;
    o.otsu_per_image = true;
    const auto r = measure_porosity({face.image}, {{}}, o);
    EXPECT_NEAR(100 * r.porosity, 100 * face.true_porosity, 0.3);
  }
}

TEST(Porosity, WrongPolarityIsFlagged) {
  SyntheticFaceSpec spec;
  spec.width_px = spec.height_px = 96;
  const auto face = synthetic_face(spec);
  PorosityOptions o;
  o.tone = PoreTone::dark;  // plaster-filled pores are bright: this counts the matrix
  o.otsu_per_image = true;
  const auto r = measure_porosity({face.image}, {{}}, o);
  EXPECT_GT(r.porosity, 0.5);
  bool flagged = false;
  for (const auto& w : r.warnings) flagged = flagged || w.find("polarity") != std::string::npos;
  EXPECT_TRUE(flagged);
}

TEST(Synthetic, SameSeedSameBits) {
  SyntheticCtSpec spec;
  spec.specimen_px = 24;
  spec.slices = 3;
  spec.seed = 9;
  const auto a = synthetic_ct_stack(spec), b = synthetic_ct_stack(spec);
  for (std::size_t z = 0; z < a.slices.size(); ++z) EXPECT_EQ(a.slices[z].pixels, b.slices[z].pixels);
  EXPECT_EQ(a.true_porosity, b.true_porosity);
  spec.seed = 10;
  EXPECT_NE(synthetic_ct_stack(spec).slices[0].pixels, a.slices[0].pixels);
}
