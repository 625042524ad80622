// mw-compress on the shipped synthetic records (truth beside them), its hard
// cases (a missing cycle, a dropped extensometer, non-monotonic time), and a
// real MTS 793 export read as it is.
#include <gtest/gtest.h>

#include "cli/labraw_support.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::test;

TEST(MwCompress, ShippedRecordsRecoverTheTruth) {
  TempDir dir;
  const auto r = run_tool("mw-compress", {"--cyclic", (raw_dir() / "cyclic-test.csv").string(), "--failure",
                                          (raw_dir() / "failure-test.csv").string(), "--from",
                                          (raw_dir() / "compression-truth.toml").string(), "--cycles-csv",
                                          (dir / "cycles.csv").string(), "--failure-curve",
                                          (dir / "fail.csv").string(), "--out", (dir / "c.json").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = parse_json(r.out);
  const double E = truth("compression-truth.toml", "true_E_st"), s = truth("compression-truth.toml", "true_sigma_max"),
               m = truth("compression-truth.toml", "true_crosshead_multiplier");
  EXPECT_NEAR(j["E_st_GPa"].get<double>() / E, 1.0, 0.01);
  EXPECT_NEAR(j["sigma_max_MPa"].get<double>() / s, 1.0, 0.005);
  EXPECT_NEAR(j["crosshead_multiplier"].get<double>() / m, 1.0, 0.02);
  EXPECT_EQ(j["cycles_found"], 3);
  EXPECT_EQ(j["E_st_measured_GPa"], j["E_st_GPa"]);  // for mw-estatic --from
  EXPECT_TRUE(j["warnings"].empty()) << j["warnings"].dump();
  const auto cycles = read_file(dir / "cycles.csv");
  EXPECT_EQ(std::count(cycles.begin(), cycles.end(), '\n'), 4);
}

TEST(MwCompress, MissingCycleAndDroppedChannel) {
  TempDir dir;
  auto synth = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = {"compression", "--cyclic", (dir / "c.csv").string(), "--failure",
                                  (dir / "f.csv").string(), "--truth", (dir / "t.toml").string()};
    a.insert(a.end(), extra.begin(), extra.end());
    ASSERT_EQ(run_tool("mw-synth", a).exit_status, 0);
  };
  const std::vector<std::string> setup = {"--side-mm", "150", "--gauge-length-mm", "75"};
  auto compress = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = {"--cyclic", (dir / "c.csv").string()};
    a.insert(a.end(), setup.begin(), setup.end());
    a.insert(a.end(), extra.begin(), extra.end());
    return run_tool("mw-compress", a);
  };
  synth({"--skip-cycle", "2"});
  auto r = compress({});
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_NE(r.err.find("found 2 load cycles"), std::string::npos) << r.err;

  synth({"--dropout-channel", "2", "--dropout-time-s", "100"});
  r = compress({});
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_NE(r.err.find("only 1 usable extensometer"), std::string::npos) << r.err;
  r = compress({"--min-extensometers", "1"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: extensometer 'ext2_mm' not used"), std::string::npos) << r.err;
  EXPECT_EQ(parse_json(r.out)["extensometers_used"].size(), 1u);
}

TEST(MwCompress, NonMonotonicTimeColumn) {
  TempDir dir;
  write_file(dir / "t.csv", "t_s,force_kN,ext1_mm,ext2_mm\n0,1,0,0\n0.2,2,0.001,0.001\n0.1,3,0.002,0.002\n");
  const auto r = run_tool("mw-compress", {"--cyclic", (dir / "t.csv").string(), "--side-mm", "150",
                                          "--gauge-length-mm", "75"});
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_NE(r.err.find("strictly increasing"), std::string::npos) << r.err;
}

TEST(MwCompress, RealMtsExportAsItIs) {
  const auto file = std::filesystem::path(MESOWAVE_SHARED_DIR) /
                    "realdata/lebedigital-concrete-compression/druckfestigkeit/Wolf_8.2_Probe_2.dat";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "real data not present";
  const auto r = run_tool("mw-compress", {"--format", "mts793", "--failure", file.string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = parse_json(r.out);
  // Peak force 354.08 kN (the file's summary block says 354.12 kN at its own
  // sampling) on the header's 100 mm diameter.
  EXPECT_NEAR(j["F_max_kN"].get<double>(), 354.08, 0.05);
  EXPECT_NEAR(j["sigma_max_MPa"].get<double>(), 354.08e3 / (M_PI / 4 * 100 * 100), 0.01);
  EXPECT_TRUE(j["failure_detected"].get<bool>());
}
