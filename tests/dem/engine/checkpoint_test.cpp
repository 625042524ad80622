// Checkpoint and restart (dem/engine/checkpoint.hpp) against the run itself: a
// run stopped at step k with a checkpoint and continued in a new Simulation
// gives the same bits as the uninterrupted run - every sensor's samples, a
// test's curves, the broken-bond count and the energies - for the full law
// loaded to break bonds, the moment law, the linearised network and the chain.
// A checkpoint of another run, or with its contacts in another layout, is refused.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "mesowave/core/error.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/dem/contact/cohesive_frictional_contact.hpp"
#include "mesowave/dem/engine/simulation.hpp"
#include "dem/checkpoint_edits.hpp"
#include "dem/test_packings.hpp"
#include "support/input_error.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::dem;
using namespace mesowave::dem::testing;

namespace {

constexpr double kA = 2.0e-3;  // FCC cell of crushing_block (test_packings.hpp)

// A small-amplitude wave on an FCC block of `cells` cells of side `a`: a burst on x-, sensors on x+ and y-.
Scene wave_scene(int cells, double duration_s, double a = kA) {
  Scene s = bare_scene(concrete_material(), 5e-8, duration_s);
  s.material.damping = 0.01;
  const double side = cells * a + 0.5 * a, mid = 0.5 * side;
  s.actuators.push_back(force_burst("A", patch_target("x-", {0, mid, mid}, 3e-3), "inward", 1e-3, 300e3));
  s.sensors.push_back(motion_sensor("B", patch_target("x+", {side, mid, mid}, 3e-3), MotionQuantity::acceleration, "normal"));
  s.sensors.push_back(motion_sensor("D", patch_target("y-", {mid, 0, mid}, 3e-3), MotionQuantity::velocity, "normal"));
  return s;
}

const CheckpointIdentity kIdentity{"scene-sha", "packing-sha", "", {{"--model", "auto"}, {"--dt-ns", 0.0}}};

struct Stop {};

// Runs to step k, where it writes a checkpoint (every k steps) and stops.
void run_to(const Scene& scene, const Packing& packing, const std::string& model, std::int64_t k,
            const std::filesystem::path& file) {
  SimulationOptions o;
  o.model = model;
  o.checkpoint.file = file;
  o.checkpoint.every_steps = k;
  o.checkpoint.identity = kIdentity;
  o.on_progress = [&](std::int64_t done, std::int64_t) {
    if (done == k) throw Stop{};
  };
  Simulation sim(scene, packing, o);
  EXPECT_THROW(sim.run(), Stop);
  EXPECT_EQ(sim.steps_done(), k);
}

RunReport resume(const Scene& scene, const Packing& packing, const std::string& model, std::int64_t k,
                 const std::filesystem::path& file) {
  SimulationOptions o;
  o.model = model;
  Simulation sim(scene, packing, o);
  sim.restore(file, kIdentity);
  EXPECT_EQ(sim.steps_done(), k);
  return sim.run();
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

void expect_same_run(const RunReport& whole, const RunReport& resumed) {
  ASSERT_EQ(whole.signals.size(), resumed.signals.size());
  for (std::size_t i = 0; i < whole.signals.size(); ++i) {
    EXPECT_GT(whole.signals[i].size(), 2u);
    EXPECT_TRUE(same_bits(whole.signals[i].samples, resumed.signals[i].samples)) << whole.signals[i].name;
  }
  EXPECT_EQ(whole.steps, resumed.steps);
  EXPECT_EQ(whole.broken_bonds, resumed.broken_bonds);
  EXPECT_EQ(whole.stop_reason, resumed.stop_reason);
  const auto bits = [](double x) {
    std::uint64_t u;
    std::memcpy(&u, &x, sizeof u);
    return u;
  };
  EXPECT_EQ(bits(whole.energy.kinetic_J), bits(resumed.energy.kinetic_J));
  EXPECT_EQ(bits(whole.energy.elastic_J), bits(resumed.energy.elastic_J));
  EXPECT_EQ(bits(whole.energy.external_work_J), bits(resumed.energy.external_work_J));
  EXPECT_EQ(bits(whole.energy.damping_J), bits(resumed.energy.damping_J));
  EXPECT_EQ(bits(whole.energy.plastic_J), bits(resumed.energy.plastic_J));
  EXPECT_EQ(bits(whole.peak_force_ratio), bits(resumed.peak_force_ratio));
  EXPECT_EQ(bits(whole.peak_stored_J), bits(resumed.peak_stored_J));
}

void expect_refusal(const std::function<void()>& call, const std::string& words) {
  const std::string message = test::input_error_of(call);
  EXPECT_NE(message.find(words), std::string::npos) << message;
}

}  // namespace

TEST(Checkpoint, FullLawCompressionToFailureRestartsToTheSameBits) {
  const Scene scene = parse_scene(crushing_scene_toml("unused.h5"), "compression");
  const Packing packing = crushing_block(3);  // 108 spheres
  test::TempDir dir;
  SimulationOptions o;
  Simulation whole_sim(scene, packing, o);
  const RunReport whole = whole_sim.run();
  ASSERT_EQ(whole.choice.model, "full");
  const auto& law = dynamic_cast<const CohesiveFrictionalContact&>(dynamic_cast<const SphereSystem&>(whole_sim.model()).kernel());
  // Restart between the peak and the stop: the stop rule must remember the peak.
  ASSERT_TRUE(whole.test);
  const auto peak_step = std::int64_t(std::llround(whole.test->time_at_peak_s / scene.dt_s));
  const std::int64_t k = (peak_step + whole.steps) / 2;
  EXPECT_GT(k, peak_step + 5);
  std::printf("%lld steps (%s), %zu of %zu bonds broken, %zu contact detections, restart at %lld\n",
              (long long)whole.steps, whole.stop_reason.c_str(), whole.broken_bonds, whole.bonds,
              law.detection_passes(), (long long)k);
  EXPECT_GT(whole.broken_bonds, 0u);
  EXPECT_GT(law.detection_passes(), 1u);  // the contact list changed during the run

  run_to(scene, packing, "auto", k, dir / "c.h5");
  const RunReport resumed = resume(scene, packing, "auto", k, dir / "c.h5");
  expect_same_run(whole, resumed);
  ASSERT_TRUE(whole.test && resumed.test);
  EXPECT_TRUE(same_bits(whole.test->stress_Pa, resumed.test->stress_Pa));
  EXPECT_TRUE(same_bits(whole.test->axial_strain, resumed.test->axial_strain));
  EXPECT_TRUE(same_bits(whole.test->broken_bonds, resumed.test->broken_bonds));
  // Bonds broke before the checkpoint and after it.
  const std::vector<double>& broken = whole.test->broken_bonds;
  const std::size_t at_k = std::size_t(k / 5);  // one sample every 5 steps
  ASSERT_LT(at_k, broken.size());
  EXPECT_GT(broken[at_k], 0.0);
  EXPECT_GT(broken.back(), broken[at_k]);
  // Writing and reading closed every HDF5 object (no file left open).
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

TEST(Checkpoint, MomentLawRestartsToTheSameBits) {
  Scene scene = parse_scene(crushing_scene_toml("unused.h5"), "compression");
  scene.contact_law = "cohesive_moment";
  const Packing packing = crushing_block(3);
  test::TempDir dir;
  const RunReport whole = Simulation(scene, packing).run();
  EXPECT_GT(whole.broken_bonds, 0u);
  const std::int64_t k = whole.steps / 3;
  run_to(scene, packing, "auto", k, dir / "c.h5");
  expect_same_run(whole, resume(scene, packing, "auto", k, dir / "c.h5"));
}

TEST(Checkpoint, LinearNetworkWaveRestartsToTheSameBits) {
  const Scene scene = wave_scene(4, 20e-6);
  const Packing packing = crushing_block(4);  // 256 spheres
  test::TempDir dir;
  SimulationOptions o;
  o.model = "linear";
  const RunReport whole = Simulation(scene, packing, o).run();
  ASSERT_EQ(whole.choice.model, "linear");
  const std::int64_t k = 137;  // not a multiple of the energy check's 100 steps
  run_to(scene, packing, "linear", k, dir / "c.h5");
  expect_same_run(whole, resume(scene, packing, "linear", k, dir / "c.h5"));
}

TEST(Checkpoint, ChainRestartsToTheSameBits) {
  Scene scene = bare_scene(concrete_material(false), 5e-8, 40e-6);
  scene.actuators.push_back(force_burst("A", end_target(false), "line", 1.0, 100e3));
  scene.sensors.push_back(motion_sensor("S", end_target(true), MotionQuantity::acceleration, "line"));
  const Packing packing = line_packing(60, 1e-3, 1.9e-3, 2290);
  test::TempDir dir;
  const RunReport whole = Simulation(scene, packing).run();
  ASSERT_EQ(whole.choice.model, "chain");
  run_to(scene, packing, "auto", 333, dir / "c.h5");
  expect_same_run(whole, resume(scene, packing, "auto", 333, dir / "c.h5"));
}

TEST(Checkpoint, ARestartOnTwoThreadsGivesTheOneThreadBits) {
  // 8788 spheres: two partitions of the Morton order, the parallel path (models_test.cpp).
  const int cells = 13;
  const Packing packing = fcc_packing(cells, 2.5e-3, 0.8e-3, 1.0e-3, 0.03, 9, 2290);
  Scene scene = wave_scene(cells, 2e-6, 2.5e-3);
  test::TempDir dir;
  use_threads(1);
  SimulationOptions o;
  o.model = "full";
  const RunReport whole = Simulation(scene, packing, o).run();
  run_to(scene, packing, "full", 17, dir / "c.h5");
  use_threads(2);
  const RunReport resumed = resume(scene, packing, "full", 17, dir / "c.h5");
  EXPECT_EQ(resumed.threads, 2);
  expect_same_run(whole, resumed);
  use_threads(0);
}

TEST(Checkpoint, ACheckpointOfAnotherRunIsRefused) {
  const Scene scene = wave_scene(3, 5e-6);
  const Packing packing = crushing_block(3);
  test::TempDir dir;
  run_to(scene, packing, "full", 10, dir / "c.h5");
  Simulation sim(scene, packing, [] {
    SimulationOptions o;
    o.model = "full";
    return o;
  }());
  CheckpointIdentity other = kIdentity;
  other.scene_sha256 = "changed";
  expect_refusal([&] { sim.restore(dir / "c.h5", other); }, "is of another scene file");
  other = kIdentity;
  other.packing_sha256 = "changed";
  expect_refusal([&] { sim.restore(dir / "c.h5", other); }, "is of another packing file");
  other = kIdentity;
  other.options["--dt-ns"] = 20.0;
  expect_refusal([&] { sim.restore(dir / "c.h5", other); }, "is of a run with --dt-ns 0.0, this run has 20.0");
  // The same identity on another packing (hashes bypassed): its state does not fit.
  Simulation bigger(scene, crushing_block(4), [] {
    SimulationOptions o;
    o.model = "full";
    return o;
  }());
  expect_refusal([&] { bigger.restore(dir / "c.h5", kIdentity); }, "the checkpoint is not from this run");
  // Every contact and bond of this run, but two slots swapped (every per-slot array alike): not
  // the layout detection makes, whose order of terms the restart would not keep.
  {
    const hid_t f = H5Fopen((dir / "c.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    for (const char* name : {"first", "second", "bond", "cohesive", "normal_x", "normal_y", "normal_z", "shear_x_N",
                             "shear_y_N", "shear_z_N", "overlap0_m"}) {
      const hid_t d = H5Dopen2(f, (std::string("/model/law/") + name).c_str(), H5P_DEFAULT);
      ASSERT_GE(d, 0) << name;
      const hid_t type = H5Dget_type(d), space = H5Dget_space(d);
      std::vector<unsigned char> bytes(std::size_t(H5Sget_simple_extent_npoints(space)) * H5Tget_size(type));
      ASSERT_GE(H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()), 0);
      const std::size_t size = H5Tget_size(type);
      std::swap_ranges(bytes.begin(), bytes.begin() + std::ptrdiff_t(size), bytes.begin() + std::ptrdiff_t(size));
      ASSERT_GE(H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()), 0);
      H5Sclose(space), H5Tclose(type), H5Dclose(d);
    }
    H5Fclose(f);
  }
  expect_refusal([&] { sim.restore(dir / "c.h5", kIdentity); }, "its contact layout is not this packing's");
  // The first slot's bond index set to the last bonded slot's: that bond twice, the first slot's not at all.
  run_to(scene, packing, "full", 10, dir / "d.h5");
  ASSERT_NO_FATAL_FAILURE(test::give_the_first_slot_the_last_bond(dir / "d.h5"));
  expect_refusal([&] { sim.restore(dir / "d.h5", kIdentity); }, "its bonds are not this packing's");
  // Not a checkpoint at all.
  test::write_file(dir / "x.h5", "not hdf5");
  EXPECT_THROW(sim.restore(dir / "x.h5", kIdentity), InputError);
  EXPECT_EQ(sim.steps_done(), 0);
}
