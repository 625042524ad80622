// The three models against each other, the model choice and its validity
// check, and thread-count independence.
#include <gtest/gtest.h>

#include <cstring>

#include "mesowave/core/error.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/dem/engine/simulation.hpp"
#include "mesowave/signal/correlation.hpp"
#include "dem/test_packings.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::dem;
using namespace mesowave::dem::testing;

namespace {

constexpr double kA = 2.5e-3;  // FCC cell

// A cube-like wave scene on an FCC block: burst at the centre of x-, six
// sensors on the other faces (pairs on opposite faces, as in the paper).
Scene cube_scene(int cells, double amplitude_N, double frequency_hz, double duration) {
  Scene s = bare_scene(concrete_material(), 5e-8, duration);
  s.material.damping = 0.01;
  const double side = cells * kA + 0.5 * kA, mid = 0.5 * side, q = 0.3 * side;
  s.actuators.push_back(force_burst("A", patch_target("x-", {0, mid, mid}, 3e-3), "inward", amplitude_N, frequency_hz));
  const struct {
    const char* name;
    const char* face;
    std::array<double, 3> at;
  } sensors[] = {{"B", "x+", {side, mid, mid}}, {"C", "x+", {side, q, q}}, {"D", "y-", {mid, 0, mid}},
                 {"F", "y+", {mid, side, mid}}, {"E", "z-", {q, mid, 0}},  {"G", "z+", {q, mid, side}}};
  for (const auto& x : sensors)
    s.sensors.push_back(motion_sensor(x.name, patch_target(x.face, x.at, 3e-3), MotionQuantity::acceleration, "normal"));
  return s;
}

RunReport run(const Scene& s, const Packing& p, const std::string& model) {
  SimulationOptions o;
  o.model = model;
  return Simulation(s, p, o).run();
}

}  // namespace

TEST(Models, LinearAndFullAgreeOnASmallAmplitudeCubeWave) {
  const Packing p = fcc_packing(6, kA, 0.8e-3, 1.0e-3, 0.03, 21, 2290);  // 864 spheres
  const Scene s = cube_scene(6, 1e-3, 300e3, 60e-6);
  const RunReport linear = run(s, p, "linear"), full = run(s, p, "full");
  ASSERT_EQ(linear.signals.size(), 6u);
  for (std::size_t i = 0; i < linear.signals.size(); ++i) {
    const double pcc = signal::pearson(linear.signals[i].samples, full.signals[i].samples);
    std::printf("sensor %s: PCC linear vs full %.9f\n", linear.signals[i].name.c_str(), pcc);
    EXPECT_GT(pcc, 0.9999) << linear.signals[i].name;
  }
  EXPECT_LT(linear.peak_force_ratio, 1e-3);
  EXPECT_NEAR(linear.peak_force_ratio / full.peak_force_ratio, 1.0, 1e-3);
}

TEST(Models, ChoiceFollowsTheAmplitudeAndTheLinearCheckNamesTheBound) {
  const Packing p = fcc_packing(4, kA, 0.8e-3, 1.0e-3, 0.03, 5, 2290);
  {
    Simulation small(cube_scene(4, 1e-3, 300e3, 2e-6), p);
    EXPECT_EQ(small.choice().model, "linear") << small.choice().reason;
  }
  {
    Simulation large(cube_scene(4, 50.0, 300e3, 2e-6), p);
    EXPECT_EQ(large.choice().model, "full") << large.choice().reason;
  }
  // Forced to linear at an amplitude that loads the bonds to a few % of their strength:
  // the result is refused, naming the measured ratio and the bound.
  const std::string error = mesowave::test::input_error_of([&] { run(cube_scene(4, 1.0, 300e3, 20e-6), p, "linear"); });
  EXPECT_NE(error.find("above the validity bound 0.001"), std::string::npos) << error;
}

TEST(Models, ChainLinearAndFullGiveTheSameRodSignal) {
  // A line loaded along it: the 3-D models keep transverse motion at zero and
  // reproduce the chain.
  const double R = 5.1e-3, rho = 6044.37;
  CohesiveFrictionalMaterial m;
  m.E_dem_Pa = 6.6e11;
  m.stiffness_ratio = 0.3;
  m.density_kg_m3 = rho;
  m.bond_factor = 1.0;
  Scene s = bare_scene(m, 5e-8, 100e-6);
  s.actuators.push_back(force_burst("A", end_target(false), "x", 1000.0, 100e3));
  s.sensors.push_back(motion_sensor("S", end_target(true), MotionQuantity::acceleration, "x"));
  s.sensors.push_back(motion_sensor("T", end_target(true), MotionQuantity::displacement, "y"));
  const Packing p = line_packing(60, R, 1.03 * R, rho);
  const RunReport chain = run(s, p, "auto"), linear = run(s, p, "linear"), full = run(s, p, "full");
  EXPECT_EQ(chain.choice.model, "chain");
  double peak = 0, d_linear = 0, d_full = 0;
  for (std::size_t i = 0; i < chain.signals[0].size(); ++i) {
    peak = std::max(peak, std::abs(chain.signals[0].samples[i]));
    d_linear = std::max(d_linear, std::abs(linear.signals[0].samples[i] - chain.signals[0].samples[i]));
    d_full = std::max(d_full, std::abs(full.signals[0].samples[i] - chain.signals[0].samples[i]));
  }
  EXPECT_LT(d_linear / peak, 1e-12);
  EXPECT_LT(d_full / peak, 1e-6);  // positions in metres carry ~1e-18 m round-off against ~1e-10 m waves
  for (double y : full.signals[1].samples) EXPECT_EQ(y, 0.0);
}

TEST(Models, OneAndTwoThreadsGiveBitIdenticalSignals) {
  // 8788 spheres, ~50,000 bonds: two partitions of the Morton order, so the
  // parallel path (in-place sums inside partitions, gathered records across) runs.
  const Packing p = fcc_packing(13, kA, 0.8e-3, 1.0e-3, 0.03, 9, 2290);
  const Scene s = cube_scene(13, 1e-3, 300e3, 2e-6);
  for (const char* model : {"linear", "full"}) {
    use_threads(1);
    const RunReport one = run(s, p, model);
    use_threads(2);
    const RunReport two = run(s, p, model);
    EXPECT_EQ(one.threads, 1);
    EXPECT_EQ(two.threads, 2);
    for (std::size_t i = 0; i < one.signals.size(); ++i) {
      ASSERT_EQ(one.signals[i].size(), two.signals[i].size());
      EXPECT_EQ(std::memcmp(one.signals[i].samples.data(), two.signals[i].samples.data(),
                            one.signals[i].size() * sizeof(double)), 0)
          << model << " sensor " << one.signals[i].name;
    }
    EXPECT_EQ(one.energy.elastic_J, two.energy.elastic_J);
    EXPECT_EQ(one.energy.damping_J, two.energy.damping_J);
  }
}
