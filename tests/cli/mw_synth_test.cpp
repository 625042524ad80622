// mw-synth: deterministic by seed, truth labelled synthetic beside the data.
#include <gtest/gtest.h>

#include "mesowave/io/quantity_file.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::test;

TEST(MwSynth, SameSeedSameBytesAndTruthLabelled) {
  TempDir dir;
  for (const char* name : {"a", "b"}) {
    const std::string d = (dir / name).string();
    ASSERT_EQ(run_tool("mw-synth", {"ct", "--stack", d + "-ct.tif", "--truth", d + "-ct.toml", "--size-px", "32",
                                    "--slices", "4", "--seed", "3"})
                  .exit_status,
              0);
    ASSERT_EQ(run_tool("mw-synth", {"upv", "--p-wave", d + "-p.csv", "--s-wave", d + "-s.csv", "--truth",
                                    d + "-upv.toml", "--seed", "3"})
                  .exit_status,
              0);
  }
  EXPECT_EQ(read_file(dir / "a-ct.tif"), read_file(dir / "b-ct.tif"));
  EXPECT_EQ(read_file(dir / "a-p.csv"), read_file(dir / "b-p.csv"));
  for (const auto& q : io::read_quantity_file(dir / "a-ct.toml")) EXPECT_EQ(q.source, "synthetic") << q.name;
  EXPECT_NE(read_file(dir / "a-ct.toml").find("mw-synth ct --stack"), std::string::npos);  // how to regenerate
}

TEST(MwSynth, RefusesImpossibleSpecifications) {
  TempDir dir;
  const auto r = run_tool("mw-synth", {"compression", "--cyclic", (dir / "c.csv").string(), "--failure",
                                       (dir / "f.csv").string(), "--truth", (dir / "t.toml").string(),
                                       "--upper-stress-MPa", "70", "--strength-MPa", "66"});
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_NE(r.err.find("below the strength"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "c.csv"));
}
