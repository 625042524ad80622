// Issue 19, item 3: the calibration's targets are chosen in one place
// (CC_CALIBRATION_TARGETS, pipeline/concrete-cube/step-6-calibration.mk). On a copy of the source
// tree with the quick pipeline's rules (make QUICK=1 with this build's tools, as check-pipeline runs
// them), the calibration to the lab's own step-4 results - raw-compress.json, mw-compress on the
// synthetic load-frame records - meets those results within the calibration's tolerances on the
// trial mw-dem itself reported, says which file, entry and SHA-256 each target came from, and
// switching back to the default (the paper's static tests) gives the default calibration again.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "mesowave/prov/run_record.hpp"
#include "support/quick_tree.hpp"

using namespace mesowave;
using namespace mesowave::test;
namespace fs = std::filesystem;

namespace {

nlohmann::json json_file(const fs::path& path) { return nlohmann::json::parse(read_file(path)); }

// What a run decided: the calibrated parameters, the model's response and the targets with
// their origins; wall times (trials_wall_s) measure the machine, not the choice.
nlohmann::json decided(nlohmann::json c) {
  c.erase("trials_wall_s");
  return c;
}

}  // namespace

TEST(Pipeline, CalibratesToTheRawStepFourResultsWhenChosen) {
  const QuickTree quick;
  ASSERT_TRUE(quick.copied);
  const fs::path& tree = quick.root;
  const fs::path out = tree / "results-quick/concrete-cube", db = quick.db;
  const auto make = [&](std::vector<std::string> args) {
    args.insert(args.end(), {"results-quick/concrete-cube/calibration.json", "results-quick/concrete-cube/calibration-targets.csv"});
    const auto r = quick.make(args);
    EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
    return r;
  };
  const auto calibrate_runs = [&] {
    const auto r = run_tool("mw-prov", {"runs", "--json", "--db", db.string()});
    int n = 0;
    for (const auto& run : nlohmann::json::parse(r.out)) n += run["tool"] == "mw-calibrate";
    return n;
  };

  // The default: the paper's static tests, each target read from static-test.toml.
  make({});
  const fs::path static_test = tree / "lab-data/concrete-cube/static-test.toml";
  const auto by_default = json_file(out / "calibration.json");
  EXPECT_EQ(by_default["targets"]["E_st"]["file"], "lab-data/concrete-cube/static-test.toml");
  EXPECT_EQ(by_default["targets"]["E_st"]["entry"], "E_st_measured");
  EXPECT_EQ(by_default["targets"]["sigma_max"]["entry"], "sigma_max");
  // DOUBLE_EQ (4 ulp): mw-calibrate holds the targets in Pa and writes them in GPa and MPa again.
  EXPECT_DOUBLE_EQ(by_default["E_st_target_GPa"].get<double>(), quantity_entry(static_test, "E_st_measured"));
  EXPECT_DOUBLE_EQ(by_default["sigma_max_target_MPa"].get<double>(), quantity_entry(static_test, "sigma_max"));
  EXPECT_EQ(by_default["targets"]["E_st"]["sha256"], prov::describe_file(static_test).sha256);

  // The lab's own step 4: E_st and sigma_max from raw-compress.json, nu_st still static-test.toml's.
  // The shipped records are made from the paper's values, so a lab with another concrete is
  // simulated: its records made by mw-synth (as lab-data/concrete-cube/raw/generate.sh makes the
  // shipped ones) from E 25 GPa and 58 MPa, outside the static tests' 1 % and 2 % bands, so that
  // meeting them shows which targets the calibration took.
  const fs::path raw_dir = tree / "lab-data/concrete-cube/raw";
  const auto synth = run_tool(
      "mw-synth", {"compression", "--cyclic", (raw_dir / "cyclic-test.csv").string(), "--failure",
                   (raw_dir / "failure-test.csv").string(), "--truth", (raw_dir / "compression-truth.toml").string(),
                   "--E-GPa", "25", "--strength-MPa", "58", "--upper-stress-MPa", "16.7", "--lower-stress-MPa", "0.5",
                   "--cyclic-stress-rate-MPa-s", "0.3", "--failure-stress-rate-MPa-s", "0.6", "--hold-s", "20",
                   "--side-mm", "150", "--gauge-length-mm", "75", "--crosshead-multiplier", "0.2222222222222222",
                   "--seed", "3"});
  ASSERT_EQ(synth.exit_status, 0) << synth.err;
  make({"CC_CALIBRATION_TARGETS=raw-step-4"});
  const auto raw = json_file(out / "raw-compress.json");
  const double E_raw = raw["E_st_measured_GPa"], sigma_raw = raw["sigma_max_MPa"], nu_st = quantity_entry(static_test, "nu_st");
  // mw-compress recovers the records' truth (the shipped set: 27.4187 GPa and 65.965 MPa from 27.42
  // and 66.0, docs/tour/labraw.md); 1 % only checks that the records were made again.
  EXPECT_NEAR(E_raw / 25, 1, 0.01);
  EXPECT_NEAR(sigma_raw / 58, 1, 0.01);
  const auto c = json_file(out / "calibration.json");
  EXPECT_DOUBLE_EQ(c["E_st_target_GPa"].get<double>(), E_raw);
  EXPECT_DOUBLE_EQ(c["sigma_max_target_MPa"].get<double>(), sigma_raw);
  EXPECT_EQ(c["nu_st_target"].get<double>(), nu_st);
  for (const char* target : {"E_st", "sigma_max"}) {
    EXPECT_EQ(c["targets"][target]["file"], "results-quick/concrete-cube/raw-compress.json") << target;
    EXPECT_EQ(c["targets"][target]["sha256"], prov::describe_file(out / "raw-compress.json").sha256) << target;
  }
  EXPECT_EQ(c["targets"]["E_st"]["entry"], "E_st_measured_GPa");
  EXPECT_EQ(c["targets"]["nu_st"]["file"], "lab-data/concrete-cube/static-test.toml");
  // The calibrated model meets the raw targets within the calibration's tolerances (1 % on E, 0.01
  // on nu, 2 % on the strength: mw-calibrate's defaults, docs/calibration.md), read from the
  // summary mw-dem wrote for the calibrating trial - the model's own test, not the calibrator's copy.
  const auto test = json_file(tree / c["calibrated_by_trial"].get<std::string>())["test"];
  EXPECT_LE(std::abs(test["E_glob_GPa"].get<double>() / E_raw - 1), 0.01);
  EXPECT_LE(std::abs(test["nu_glob"].get<double>() - nu_st), 0.01);
  EXPECT_LE(std::abs(test["peak_stress_MPa"].get<double>() / sigma_raw - 1), 0.02);
  EXPECT_TRUE(test["peak_reached"].get<bool>());
  const std::string table = read_file(out / "calibration-targets.csv");
  EXPECT_NE(table.find("results-quick/concrete-cube/raw-compress.json"), std::string::npos) << table;

  // Back to the default: the calibration runs again and decides what it decided the first time.
  make({});
  EXPECT_EQ(decided(json_file(out / "calibration.json")), decided(by_default));
  EXPECT_EQ(calibrate_runs(), 3);  // every switch re-ran it
  make({});
  EXPECT_EQ(calibrate_runs(), 3);  // the same choice again: nothing runs
}
