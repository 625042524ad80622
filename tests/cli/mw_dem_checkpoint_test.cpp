// mw-dem run --checkpoint / --restart end to end: a run continued from a
// checkpoint writes the same files, byte for byte, as the run that never
// stopped (the full law crushed to failure; the chain stopped by SIGTERM), and
// a restart of another scene or with other options is refused.
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
