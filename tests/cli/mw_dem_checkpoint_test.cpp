// mw-dem run --checkpoint / --restart end to end: a run continued from a
// checkpoint writes the same files, byte for byte, as the run that never
// stopped (the full law crushed to failure; the chain stopped by SIGTERM), and
// a restart of another scene or with other options is refused; a run with
// stronger bonds started from the intact checkpoint of a weaker one (the elastic
// prefix a calibration's failure trials share, engine/checkpoint.hpp) writes the
// same files as that run from step 0, and weaker bonds or a broken one are refused.
#include <gtest/gtest.h>

#include <csignal>

#include <nlohmann/json.hpp>

#include "dem/test_packings.hpp"
#include "mesowave/dem/packing/packing_file.hpp"
#include "mesowave/signal/signal_file.hpp"
#include "support/rod_scene.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using test::run_tool;

namespace {

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

std::string rod_scene(const std::filesystem::path& packing) { return mesowave::test::rod_chain_scene_toml(packing); }

}  // namespace

// The full law to failure: checkpoints every 1000 steps; the run stops by its
// [test] rule at 3206 steps, so the last checkpoint holds step 3000 and the
// restart runs the last 206 steps, breaking more bonds on the way.
TEST(MwDemCheckpoint, ARestartedCompressionToFailureWritesTheSameFiles) {
  test::TempDir dir;
  dem::write_packing_file(dir / "block.h5", dem::testing::crushing_block(3));
  test::write_file(dir / "crush.toml", dem::testing::crushing_scene_toml((dir / "block.h5").string()));
  const std::vector<std::string> base = {"run", (dir / "crush.toml").string(), "--quiet"};
  const auto whole = run_tool("mw-dem", with(base, {"--signals", (dir / "whole.h5").string(), "--curves",
                                                    (dir / "whole.csv").string(), "--summary", (dir / "whole.json").string()}));
  ASSERT_EQ(whole.exit_status, 0) << whole.err;
  const auto first = run_tool("mw-dem", with(base, {"--signals", (dir / "first.h5").string(), "--checkpoint",
                                                    (dir / "c.h5").string(), "--checkpoint-every-steps", "1000"}));
  ASSERT_EQ(first.exit_status, 0) << first.err;
  const auto again = run_tool("mw-dem", with(base, {"--signals", (dir / "again.h5").string(), "--curves",
                                                    (dir / "again.csv").string(), "--summary",
                                                    (dir / "again.json").string(), "--restart", (dir / "c.h5").string()}));
  ASSERT_EQ(again.exit_status, 0) << again.err;
  EXPECT_EQ(test::read_file(dir / "whole.h5"), test::read_file(dir / "again.h5"));  // cmp: the same bytes
  EXPECT_EQ(test::read_file(dir / "whole.csv"), test::read_file(dir / "again.csv"));
  const auto a = nlohmann::json::parse(test::read_file(dir / "whole.json"));
  const auto b = nlohmann::json::parse(test::read_file(dir / "again.json"));
  EXPECT_EQ(a["steps"], 3206);
  EXPECT_EQ(b["steps"], 3206);
  EXPECT_EQ(a["broken_bonds"], b["broken_bonds"]);
  EXPECT_GT(a["broken_bonds"].get<int>(), 0);
  // Bonds were broken at the checkpoint (step 3000, sample 600 of the counter: one every 5 steps) and after it.
  for (const auto& s : signal::read_signal_file(dir / "whole.h5"))
    if (s.name == "broken") {
      ASSERT_GT(s.size(), 600u);
      EXPECT_GT(s.samples[600], 0.0);
      EXPECT_GT(s.samples.back(), s.samples[600]);
    }
}

// A restart must be of the same scene, packing and options: one line naming what differs, nothing written.
TEST(MwDemCheckpoint, ARestartOfAnotherSceneOrWithOtherOptionsIsRefused) {
  test::TempDir dir;
  dem::write_packing_file(dir / "block.h5", dem::testing::crushing_block(3));
  std::string scene = dem::testing::crushing_scene_toml((dir / "block.h5").string());
  test::write_file(dir / "crush.toml", scene);
  const auto first = run_tool("mw-dem", {"run", (dir / "crush.toml").string(), "--quiet", "--duration-ms", "0.02",
                                         "--signals", (dir / "first.h5").string(), "--checkpoint",
                                         (dir / "c.h5").string(), "--checkpoint-every-steps", "100"});
  ASSERT_EQ(first.exit_status, 0) << first.err;
  const auto restart = [&](const std::vector<std::string>& more) {
    return run_tool("mw-dem", with({"run", (dir / "crush.toml").string(), "--quiet", "--signals",
                                    (dir / "again.h5").string(), "--restart", (dir / "c.h5").string()},
                                   more));
  };
  // Another --duration-ms (here: none, the scene's).
  const auto options = restart({});
  EXPECT_EQ(options.exit_status, 1);
  EXPECT_NE(options.err.find("is of a run with --duration-ms 0.02, this run has 0.0"), std::string::npos) << options.err;
  // The scene file changed (its velocity).
  scene.replace(scene.find("velocity_mm_s = 500.0"), 21, "velocity_mm_s = 400.0");
  test::write_file(dir / "crush.toml", scene);
  const auto changed = restart({"--duration-ms", "0.02"});
  EXPECT_EQ(changed.exit_status, 1);
  EXPECT_NE(changed.err.find("is of another scene file"), std::string::npos) << changed.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "again.h5"));
}

// The failure trials of a calibration differ in T and C alone. The block at T = C = 20 MPa
// keeps an intact checkpoint every 100 steps; its bonds first break between steps 1000 and 1100
// (of 3206), so the last one holds an elastic prefix (its broken-bond counter still 0) that a run at
// T = C = 24.4 MPa (the scene's) shares: started from it, that run writes the same signal
// and curve files, byte for byte, as the same run from step 0, and breaks its bonds later.
TEST(MwDemCheckpoint, ARunWithStrongerBondsStartedFromAWeakerRunsIntactCheckpointWritesTheSameFiles) {
  test::TempDir dir;
  dem::write_packing_file(dir / "block.h5", dem::testing::crushing_block(3));
  test::write_file(dir / "crush.toml", dem::testing::crushing_scene_toml((dir / "block.h5").string()));
  const std::vector<std::string> base = {"run", (dir / "crush.toml").string(), "--quiet"};
  const auto out = [&](const std::string& name) {
    return std::vector<std::string>{"--signals", (dir / (name + ".h5")).string(), "--curves",
                                    (dir / (name + ".csv")).string(), "--summary", (dir / (name + ".json")).string()};
  };
  const auto weak = run_tool("mw-dem", with(with(base, out("weak")), {"--T-MPa", "20", "--C-MPa", "20", "--intact-checkpoint",
                                                                     (dir / "intact.h5").string(),
                                                                     "--intact-checkpoint-every-steps", "100"}));
  ASSERT_EQ(weak.exit_status, 0) << weak.err;
  const auto whole = run_tool("mw-dem", with(base, out("whole")));
  ASSERT_EQ(whole.exit_status, 0) << whole.err;
  const auto strong = run_tool("mw-dem", with(with(base, out("strong")), {"--restart-stronger", (dir / "intact.h5").string()}));
  ASSERT_EQ(strong.exit_status, 0) << strong.err;
  EXPECT_EQ(test::read_file(dir / "whole.h5"), test::read_file(dir / "strong.h5"));  // cmp: the same bytes
  EXPECT_EQ(test::read_file(dir / "whole.csv"), test::read_file(dir / "strong.csv"));
  const auto w = nlohmann::json::parse(test::read_file(dir / "weak.json"));
  const auto a = nlohmann::json::parse(test::read_file(dir / "whole.json"));
  const auto b = nlohmann::json::parse(test::read_file(dir / "strong.json"));
  const std::int64_t at = b["restarted_stronger_at_step"].get<std::int64_t>();
  EXPECT_GE(at, 1000);  // a prefix worth sharing
  EXPECT_EQ(a["steps"], b["steps"]);
  EXPECT_EQ(a["broken_bonds"], b["broken_bonds"]);
  EXPECT_GT(a["test"]["peak_stress_MPa"].get<double>(), w["test"]["peak_stress_MPa"].get<double>());  // stronger bonds
  // The checkpoint was the last intact one: the weak run's counter is 0 before its step and not after the
  // next check, 100 steps later (one sample every 5 steps, sample m after step 5 m + 1).
  for (const auto& s : signal::read_signal_file(dir / "weak.h5"))
    if (s.name == "broken") {
      ASSERT_GT(s.size(), std::size_t(at / 5 + 20));
      EXPECT_EQ(s.samples[at / 5 - 1], 0.0);
      EXPECT_GT(s.samples[at / 5 + 20], 0.0);
    }
}

// Weaker bonds than the checkpoint's, a checkpoint with broken bonds, or another option: refused, nothing written.
TEST(MwDemCheckpoint, ARestartWithWeakerBondsOrFromABrokenStateIsRefused) {
  test::TempDir dir;
  dem::write_packing_file(dir / "block.h5", dem::testing::crushing_block(3));
  test::write_file(dir / "crush.toml", dem::testing::crushing_scene_toml((dir / "block.h5").string()));
  const std::vector<std::string> base = {"run", (dir / "crush.toml").string(), "--quiet"};
  const auto intact = run_tool("mw-dem", with(base, {"--duration-ms", "0.02", "--signals", (dir / "first.h5").string(),
                                                     "--intact-checkpoint", (dir / "intact.h5").string(),
                                                     "--intact-checkpoint-every-steps", "100"}));
  ASSERT_EQ(intact.exit_status, 0) << intact.err;
  const auto broken = run_tool("mw-dem", with(base, {"--signals", (dir / "first.h5").string(), "--checkpoint",
                                                     (dir / "broken.h5").string(), "--checkpoint-every-steps", "3000"}));
  ASSERT_EQ(broken.exit_status, 0) << broken.err;
  const auto restart = [&](const std::string& checkpoint, const std::vector<std::string>& more) {
    return run_tool("mw-dem", with(with(base, {"--signals", (dir / "again.h5").string(), "--restart-stronger",
                                               (dir / checkpoint).string()}),
                                   more));
  };
  const auto weaker = restart("intact.h5", {"--duration-ms", "0.02", "--T-MPa", "24", "--C-MPa", "30"});
  EXPECT_EQ(weaker.exit_status, 1);
  EXPECT_NE(weaker.err.find("is of a run with T 24.4 MPa, C 24.4 MPa; this run has T 24 MPa, C 30 MPa"), std::string::npos)
      << weaker.err;
  const auto other = restart("intact.h5", {"--T-MPa", "30", "--C-MPa", "30"});  // the scene's duration
  EXPECT_EQ(other.exit_status, 1);
  EXPECT_NE(other.err.find("--duration-ms 0.02, this run has 0.0: a restart with stronger bonds differs"), std::string::npos)
      << other.err;
  const auto cracked = restart("broken.h5", {"--T-MPa", "30", "--C-MPa", "30"});
  EXPECT_EQ(cracked.exit_status, 1);
  EXPECT_NE(cracked.err.find("broken bonds at step 3000: only an intact one"), std::string::npos) << cracked.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "again.h5"));
}

// SIGTERM while the chain steps: the run writes its checkpoint, says so, and exits 143 with
// no other output; --restart from it writes the signal file of the run that never stopped.
TEST(MwDemCheckpoint, AfterSigtermTheRestartWritesTheUninterruptedSignals) {
  test::TempDir dir;
  dem::write_packing_file(dir / "rod.h5", dem::testing::line_packing(191, 5.1e-3, 1.03 * 5.1e-3, 6044.37));
  test::write_file(dir / "rod.toml", rod_scene(dir / "rod.h5"));
  const std::vector<std::string> base = {"run", (dir / "rod.toml").string(), "--duration-ms", "100"};  // 2e6 steps
  const auto whole = run_tool("mw-dem", with(base, {"--quiet", "--signals", (dir / "whole.h5").string()}));
  ASSERT_EQ(whole.exit_status, 0) << whole.err;
  const auto stopped = test::run_tool_and_signal(
      "mw-dem", with(base, {"--signals", (dir / "s.h5").string(), "--checkpoint", (dir / "c.h5").string()}), " 10% ",
      SIGTERM);
  ASSERT_TRUE(stopped.signal_sent) << "the run ended before its 10 % progress line: " << stopped.err;
  EXPECT_EQ(stopped.exit_status, 143) << stopped.err;
  EXPECT_NE(stopped.err.find("c.h5 holds step "), std::string::npos) << stopped.err;
  // The interrupted run's error line (and its record) names the file it kept, not "nothing written".
  EXPECT_NE(stopped.err.find("; no output was written; kept " + (dir / "c.h5").string() + " (a checkpoint at step "),
            std::string::npos) << stopped.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "s.h5"));
  ASSERT_TRUE(std::filesystem::exists(dir / "c.h5"));
  const auto again = run_tool("mw-dem", with(base, {"--signals", (dir / "s.h5").string(), "--restart",
                                                    (dir / "c.h5").string()}));
  ASSERT_EQ(again.exit_status, 0) << again.err;
  EXPECT_EQ(test::read_file(dir / "whole.h5"), test::read_file(dir / "s.h5"));  // cmp: the same bytes
  // The progress of the restart begins at the checkpoint's step, not at 0.
  EXPECT_EQ(again.err.find(" 0% "), std::string::npos) << again.err;
}
