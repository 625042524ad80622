// mw-synth's products (lab/synthetic_report): what each kind makes, its truth
// consistent with the data (the block's porosity is the mean of its slices',
// the set's the mean of its faces'), the same seed the same bits, and the
// requests it refuses.
#include "mesowave/lab/synthetic_report.hpp"

#include <gtest/gtest.h>

#include <map>

#include "mesowave/core/error.hpp"
#include "mesowave/io/csv.hpp"

using namespace mesowave;
using namespace mesowave::lab;

namespace {

std::map<std::string, double> values(const SynthesisProducts& p) {
  std::map<std::string, double> v;
  for (const auto& e : p.entries) v[e.name] = e.value;
  return v;
}

TEST(SyntheticReport, CtStackTruthIsTheMeanOfItsSlices) {
  SynthesisRequest q;
  q.kind = "ct";
  q.stack = "out/ct.tif";
  q.size_px = 32;
  q.slices = 4;
  q.seed = 3;
  const auto p = synthesize(q);
  ASSERT_TRUE(p.stack);
  EXPECT_EQ(p.stack->first, "out/ct.tif");
  ASSERT_EQ(p.stack->second.size(), 4u);
  EXPECT_EQ(p.stack->second[0].width, 32 + 2 * 6);  // the specimen and its air margin
  auto v = values(p);
  double mean = 0;
  for (int z = 1; z <= 4; ++z) mean += v.at("true_porosity_slice_" + std::to_string(z)) / 4;
  EXPECT_NEAR(v.at("true_porosity"), mean, 1e-9);  // equal ROIs: the block is the mean of its slices
  EXPECT_EQ(v.at("target_porosity"), 7.0);
  EXPECT_EQ(v.at("roi_x0"), 6.0);
  EXPECT_EQ(v.at("roi_width"), 32.0);
  EXPECT_EQ(p.summary["roi"], "6,6,32,32");
  EXPECT_NE(p.title.find("ct.tif: 4 slices of 44 px"), std::string::npos);
  EXPECT_TRUE(p.images.empty() && p.texts.empty());
  // Same seed, same bits; another seed, other pores.
  EXPECT_EQ(synthesize(q).stack->second[2].pixels, p.stack->second[2].pixels);
  q.seed = 4;
  EXPECT_NE(synthesize(q).stack->second[2].pixels, p.stack->second[2].pixels);
}

TEST(SyntheticReport, FacesTruthIsTheMeanOfItsFaces) {
  SynthesisRequest q;
  q.kind = "faces";
  q.prefix = "raw/face";
  q.count = 2;
  q.size_px = 64;
  q.pore_shape = "irregular";
  const auto p = synthesize(q);
  ASSERT_EQ(p.images.size(), 2u);
  EXPECT_EQ(p.images[1].first, "raw/face-2.png");
  const auto v = values(p);
  EXPECT_NEAR(v.at("true_porosity"), (v.at("true_porosity_face_1") + v.at("true_porosity_face_2")) / 2, 1e-12);
  EXPECT_EQ(v.at("pixel_size"), 10.0);  // the generator's default
  EXPECT_NE(p.images[0].second.pixels, p.images[1].second.pixels);  // each face its own seed
}

TEST(SyntheticReport, CompressionAndUpvRecordsAreLabelledCsv) {
  SynthesisRequest q;
  q.kind = "compression";
  q.cyclic = "c.csv";
  q.failure = "f.csv";
  auto p = synthesize(q);
  ASSERT_EQ(p.texts.size(), 2u);
  EXPECT_EQ(p.texts[0].first, "c.csv");
  EXPECT_EQ(p.texts[1].first, "f.csv");
  EXPECT_EQ(p.texts[0].second.rfind(synthetic_record_label(), 0), 0u);
  EXPECT_EQ(values(p).at("true_E_st"), 27.42);
  EXPECT_EQ(values(p).at("true_crosshead_multiplier"), 1.0 / 4.5);
  EXPECT_EQ(p.summary["true_sigma_max_MPa"], 66.0);

  q = {};
  q.kind = "upv";
  q.s_wave = "s.csv";
  q.pretrigger_us = 20;
  q.duration_us = 100;
  q.dt_us = 0.5;
  p = synthesize(q);
  ASSERT_EQ(p.texts.size(), 1u);
  const auto table = io::parse_csv(p.texts[0].second, "s.csv");
  EXPECT_EQ(table.header, (std::vector<std::string>{"t_us", "amplitude_V"}));
  EXPECT_NEAR(table.number(0, 0), -20.0, 1e-9);  // the pre-trigger before t = 0
  EXPECT_NEAR(table.number(1, 0) - table.number(0, 0), 0.5, 1e-9);
  EXPECT_EQ(values(p).at("true_t_s"), 55.1);
}

TEST(SyntheticReport, RefusesMissingOutputsAndImpossibleTargets) {
  SynthesisRequest q;
  q.kind = "ct";
  EXPECT_THROW(synthesize(q), InputError);  // no --stack
  q.kind = "faces";
  q.prefix = "f";
  q.count = 0;
  EXPECT_THROW(synthesize(q), InputError);
  q.kind = "upv";
  EXPECT_THROW(synthesize(q), InputError);  // neither wave
  q.kind = "compression";
  EXPECT_THROW(synthesize(q), InputError);
  q.kind = "upv";
  q.p_wave = "p.csv";
  q.porosity_pct = 80;
  EXPECT_THROW(synthesize(q), InputError);
  q.porosity_pct = 7;
  q.kind = "xray";
  EXPECT_THROW(synthesize(q), InputError);
}

}  // namespace
