// One FEM run per mesh for every burst frequency (fem/superposition.hpp): the
// explicit step is linear and time-invariant in the load, so the burst convolved
// with the unit-impulse response must equal a direct run of the same mesh to
// round-off - the direct run (run_fem_case) is the independent reference, for each
// recorded quantity, with and without Rayleigh damping, with the sampling interval
// several steps long; and the same bits on one and two threads.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "mesowave/fem/case.hpp"
#include "mesowave/fem/superposition.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::fem;

namespace {

// A concrete box (the cube paper's E_d, nu_d, rho), a 2 mm traction patch at the centre of
// face z-, sensors on three other faces; samples every 0.3 us (several steps at 1 mm).
FemCase small_box(const std::array<double, 3>& size_m, MotionQuantity quantity, double alpha_per_s) {
  FemCase c;
  c.body = FemCase::Body::box;
  c.material = {36.67e9, 0.162, 2129.56};
  c.mesh_m = 1e-3;
  c.size_m = size_m;
  c.source_m = {size_m[0] / 2, size_m[1] / 2, 0};
  c.patch_radius_m = 2e-3;
  c.force_N = 1;
  c.alpha_damping_per_s = alpha_per_s;
  c.duration_s = 40e-6;
  c.sample_dt_s = 0.3e-6;
  c.quantity = quantity;
  c.probe_points = {{"B", {size_m[0] / 2, size_m[1] / 2, size_m[2]}, ""},
                    {"C", {0, size_m[1] / 2, size_m[2] / 2}, ""},
                    {"D", {size_m[0] * 0.75, size_m[1], size_m[2] * 0.25}, ""}};
  return c;
}

}  // namespace

TEST(FemSuperposition, EqualsTheDirectRunsAtEveryFrequencyToRoundOff) {
  struct Variant {
    MotionQuantity quantity;
    double alpha_per_s;
  };
  // alpha = 2e4 1/s: the amplitude falls by e^-0.4 over the 40 us, far more than the rod paper's 2000.
  for (const Variant& variant : {Variant{MotionQuantity::acceleration, 0}, Variant{MotionQuantity::velocity, 2e4},
                                 Variant{MotionQuantity::displacement, 0}}) {
    SCOPED_TRACE(to_string(variant.quantity));
    const FemSetup setup = assemble_fem_case(small_box({12e-3, 10e-3, 8e-3}, variant.quantity, variant.alpha_per_s));
    ASSERT_GE(setup.stepping.stride, 2);  // the outputs are every few steps, the response every step
    const FemSuperposedSet set = run_fem_superposed(setup, {100, 300});
    ASSERT_EQ(set.frequencies.size(), 2u);
    for (const auto& f : set.frequencies) {
      const FemRun direct = run_fem_case(f.setup);
      const auto& d = direct.result.signals;
      const auto& s = f.run.result.signals;
      ASSERT_EQ(d.size(), 4u);  // B, C, D, then the excitation
      ASSERT_EQ(s.size(), d.size());
      for (std::size_t i = 0; i < d.size(); ++i) {
        EXPECT_EQ(s[i].name, d[i].name);
        EXPECT_EQ(s[i].quantity, d[i].quantity);
        EXPECT_EQ(s[i].unit, d[i].unit);
        EXPECT_EQ(s[i].component, d[i].component);
        EXPECT_EQ(s[i].position_m, d[i].position_m);
        EXPECT_EQ(s[i].dt_s, d[i].dt_s);
        EXPECT_EQ(s[i].t0_s, d[i].t0_s);
        ASSERT_EQ(s[i].size(), d[i].size());
      }
      EXPECT_EQ(s.back().samples, d.back().samples);  // the excitation is the same burst, sampled alike
      const signal::SuperpositionError e = signal::superposition_error(d, s);
      for (std::size_t i = 0; i + 1 < d.size(); ++i) {
        EXPECT_LT(e.max_diff_over_peak[i], 1e-10) << e.sensors[i] << " at " << f.setup.spec.frequency_hz;
        EXPECT_GT(e.pcc[i], 1 - 1e-12) << e.sensors[i];
      }
      // The record's provenance is a direct run's but for the method.
      auto attributes = f.run.attributes;
      EXPECT_EQ(attributes.at("method"), "superposition");
      attributes.erase("method");
      EXPECT_EQ(attributes, direct.attributes);
    }
  }
}

TEST(FemSuperposition, GivesTheSameBitsOnOneAndTwoThreads) {
  // 20 x 20 x 20 elements: two threads' worth (4000 elements each).
  FemCase c = small_box({20e-3, 20e-3, 20e-3}, MotionQuantity::acceleration, 0);
  c.duration_s = 8e-6;  // the P wave reaches B, 20 mm away, after 4.7 us
  std::vector<FemSuperposedSet> runs;
  for (int threads : {1, 2}) {
    c.threads = threads;
    runs.push_back(run_fem_superposed(assemble_fem_case(c), {150, 250}));
    EXPECT_EQ(runs.back().impulse.result.threads, threads);
  }
  double peak_B = 0;
  for (double x : runs[0].frequencies[0].run.result.signals[0].samples) peak_B = std::max(peak_B, std::abs(x));
  EXPECT_GT(peak_B, 0);
  for (std::size_t f = 0; f < 2; ++f)
    for (std::size_t i = 0; i < runs[0].frequencies[f].run.result.signals.size(); ++i) {
      const auto& a = runs[0].frequencies[f].run.result.signals[i].samples;
      const auto& b = runs[1].frequencies[f].run.result.signals[i].samples;
      ASSERT_EQ(a.size(), b.size());
      EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0) << "signal " << i << ", frequency " << f;
    }
}

TEST(FemSuperposition, RefusesRepeatedFrequenciesAStrayCheckAndTheSpaceTimeRecord) {
  const FemSetup setup = assemble_fem_case(small_box({6e-3, 6e-3, 6e-3}, MotionQuantity::acceleration, 0));
  EXPECT_EQ(test::input_error_of([&] { run_fem_superposed(setup, {100, 100}); }),
            "--frequencies-kHz names 100 kHz twice");
  EXPECT_EQ(test::input_error_of([&] { run_fem_superposed(setup, {100, 200}, {300}); }),
            "--check-kHz (300 kHz) must be one of --frequencies-kHz");
  FemCase rod;
  rod.material = {208.72e9, 0.3, 7850.66};
  rod.radius_m = 2e-3;
  rod.length_m = 10e-3;
  rod.duration_s = 5e-6;
  rod.spacetime_step_m = 1e-3;
  EXPECT_NE(test::input_error_of([&] { run_fem_superposed(assemble_fem_case(rod), {100}); }).find("no --spacetime"),
            std::string::npos);
}

TEST(FemSuperposition, ChecksAgainstADirectRunAtTheChosenFrequency) {
  const FemSetup setup = assemble_fem_case(small_box({8e-3, 8e-3, 6e-3}, MotionQuantity::acceleration, 0));
  const FemSuperposedSet set = run_fem_superposed(setup, {100, 200}, {200});
  ASSERT_EQ(set.checks.size(), 1u);
  EXPECT_EQ(set.checks[0].frequency_hz, 200e3);
  EXPECT_LT(set.checks[0].error.max_diff_over_peak_all, 1e-10);
  const auto j = superposition_json(set, set.frequencies[1]);
  EXPECT_EQ(j["exact"], true);
  EXPECT_EQ(j["check"]["frequency_kHz"], 200.0);
  EXPECT_TRUE(superposition_json(set, set.frequencies[0])["check"].is_null());
}
