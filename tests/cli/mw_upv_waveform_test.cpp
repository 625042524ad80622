// mw-upv: the original options and JSON keys unchanged, and times of flight
// picked on the shipped synthetic waveforms (truth beside them).
#include <gtest/gtest.h>

#include <sstream>

#include "cli/labraw_support.hpp"
#include "mesowave/core/format.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::test;

TEST(MwUpv, GivenTimesOfFlightAsBefore) {
  const auto r = run_tool("mw-upv", {"--path-mm", "150", "--t-p-us", "35", "--t-s-us", "55.1", "--density-kg-m3",
                                     "2129.56"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = parse_json(r.out);
  // Concrete paper Section 3.2: E_d = 36.68 GPa, nu_d = 0.16 from these inputs.
  EXPECT_NEAR(j["E_d_GPa"].get<double>(), 36.67, 0.01);
  EXPECT_NEAR(j["nu_d"].get<double>(), 0.1618, 1e-3);
  for (const char* key : {"path_mm", "t_p_us", "t_s_us", "density_kg_m3", "v_p_m_s", "v_s_m_s", "nu_d", "nu_d_source",
                          "E_d_GPa", "G_d_GPa", "method"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_FALSE(j.contains("warnings"));
}

TEST(MwUpv, PicksTheShippedWaveformsWithinHalfAMicrosecond) {
  TempDir dir;
  const auto r = run_tool("mw-upv", {"--from", (raw_dir() / "upv-truth.toml").string(), "--p-wave",
                                     (raw_dir() / "upv-p.csv").string(), "--s-wave", (raw_dir() / "upv-s.csv").string(),
                                     "--lowpass-kHz", "216", "--s-lowpass-kHz", "160", "--density-kg-m3", "2129.56",
                                     "--plot", (dir / "fig7.png").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = parse_json(r.out);
  EXPECT_NEAR(j["t_p_us"].get<double>(), truth("upv-truth.toml", "true_t_p"), 0.5);
  EXPECT_NEAR(j["t_s_us"].get<double>(), truth("upv-truth.toml", "true_t_s"), 0.5);
  EXPECT_DOUBLE_EQ(j["t_p_delay_us"].get<double>(), truth("upv-truth.toml", "delay"));  // --from filled --delay-us
  EXPECT_TRUE(std::filesystem::exists(dir / "fig7.png"));
}

TEST(MwUpv, OnsetInsideThePretrigger) {
  TempDir dir;
  // A record whose trigger came late: the pulse starts 5 us before t = 0.
  ASSERT_EQ(run_tool("mw-synth", {"upv", "--p-wave", (dir / "p.csv").string(), "--truth", (dir / "t.toml").string(),
                                  "--t-p-us", "40", "--pretrigger-us", "50"})
                .exit_status,
            0);
  std::string text = read_file(dir / "p.csv"), shifted = "t_us,amplitude_V\n";
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line) && (line.empty() || line[0] == '#')) {
  }  // the label, then the header line just read
  while (std::getline(in, line)) {
    const auto comma = line.find(',');
    shifted += format_fixed(std::stod(line.substr(0, comma)) - 45.0, 2) + line.substr(comma) + "\n";
  }
  write_file(dir / "late.csv", shifted);
  const auto r = run_tool("mw-upv", {"--path-mm", "150", "--p-wave", (dir / "late.csv").string()});
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_NE(r.err.find("pre-trigger"), std::string::npos) << r.err;
}
