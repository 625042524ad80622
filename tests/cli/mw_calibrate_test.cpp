// mw-calibrate end to end: it recovers the parameters that made its targets
// (a synthetic target from a forward mw-dem run), gives the rod its modulus,
// records every trial, and refuses targets no packing reaches.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "mesowave/io/csv.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using test::run_tool;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = MESOWAVE_SOURCE_DIR;
const std::string kCompression = (kSource / "pipeline/concrete-cube/scenes/cube-compression.toml").string();
const std::string kTension = (kSource / "pipeline/steel-rod/scenes/rod-tension.toml").string();

nlohmann::json json_of(const test::ToolResult& r) { return nlohmann::json::parse(r.out); }

// A 20 mm cube of the concrete paper's packing (2,392 spheres).
fs::path small_cube(const test::TempDir& dir) {
  const fs::path p = dir / "cube.h5";
  const auto r = run_tool("mw-pack", {"box", "--cube-side-mm", "20", "--porosity-pct", "7", "--d-min-mm", "1.6",
                                      "--d-max-mm", "2", "--density-kg-m3", "2129.56", "--packing", p.string(), "--quiet"});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  return p;
}

// `mw-dem --from calibration.json` applies all five calibrated values. The file
// is mw-calibrate's own, the five set apart from the scene's material (23.31 GPa,
// 0.32, 24.4 MPa, 24.4 MPa, 18 deg) so that each can be seen to reach the model;
// its other entries - results for the reader - are left by name, as the
// pipeline leaves them (pipeline/concrete-cube/study.mk, CC_CALIBRATION_UNTAKEN).
void expect_mw_dem_takes_the_five(const test::TempDir& dir, const fs::path& cube) {
  auto c = nlohmann::ordered_json::parse(test::read_file(dir / "calibration.json"));
  const std::vector<std::pair<std::string, double>> five = {
      {"E_dem_GPa", 31.5}, {"nu_dem", 0.21}, {"T_MPa", 12.5}, {"C_MPa", 14.5}, {"friction_angle_deg", 27.0}};
  for (const auto& [key, value] : five) {
    ASSERT_TRUE(c.contains(key)) << key << " is not in mw-calibrate's JSON";
    c[key] = value;
  }
  test::write_file(dir / "material.json", c.dump(2));
  const auto r = run_tool("mw-dem", {"--from", (dir / "material.json").string(), "--from-ignore",
                                     "E_glob_GPa,nu_glob,sigma_dem_MPa,E_st_target_GPa,nu_st_target,sigma_max_target_MPa,"
                                     "E_error_pct,nu_error,sigma_error_pct,calibrated_by_trial,trial_count,trials_wall_s",
                                     "info", kCompression, "--packing", cube.string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto m = json_of(r)["material"];
  EXPECT_NEAR(m["E_dem_Pa"].get<double>() / 31.5e9, 1.0, 1e-12);
  EXPECT_NEAR(m["nu_dem"].get<double>(), 0.21, 1e-12);
  EXPECT_NEAR(m["T_Pa"].get<double>() / 12.5e6, 1.0, 1e-12);
  EXPECT_NEAR(m["C_Pa"].get<double>() / 14.5e6, 1.0, 1e-12);
  EXPECT_NEAR(m["friction_angle_rad"].get<double>(), 27.0 * std::numbers::pi / 180, 1e-12);
}

}  // namespace

TEST(MwCalibrate, CubeRecoversTheParametersThatMadeItsTargets) {
  test::TempDir dir;
  const fs::path cube = small_cube(dir);
  const std::string db = (dir / "prov.sqlite").string();
  // The truth: a virtual test with known parameters gives the targets.
  const auto truth = run_tool("mw-dem", {"run", kCompression, "--packing", cube.string(), "--E-dem-GPa", "20",
                                         "--nu-dem", "0.25", "--T-MPa", "18", "--C-MPa", "18", "--signals",
                                         (dir / "truth.h5").string(), "--quiet"});
  ASSERT_EQ(truth.exit_status, 0) << truth.err;
  const auto t = json_of(truth)["test"];
  // From the issue's poor start, with E and nu held tighter than the defaults
  // so that the parameters, not only the outputs, can be compared: 0.5 % on E
  // is just above the scatter of a failure run's modulus (its levels follow
  // its own peak: 19.54-19.69 GPa over seven runs near the target, measured).
  const auto r = run_tool(
      "mw-calibrate",
      {"cube", "--scene", kCompression, "--packing", cube.string(), "--E-st-measured-GPa",
       std::to_string(t["E_glob_GPa"].get<double>()), "--nu-st", std::to_string(t["nu_glob"].get<double>()),
       "--sigma-max-MPa", std::to_string(t["peak_stress_MPa"].get<double>()), "--start-E-dem-GPa", "10",
       "--start-nu-dem", "0.1", "--start-T-MPa", "10", "--tolerance-E-pct", "0.5", "--tolerance-nu", "0.002",
       "--work-dir", (dir / "trials").string(), "--out", (dir / "calibration.json").string(), "--trials",
       (dir / "trials.csv").string(), "--db", db});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto c = json_of(r);
  EXPECT_NEAR(c["E_dem_GPa"].get<double>() / 20.0, 1.0, 0.01);
  EXPECT_NEAR(c["nu_dem"].get<double>(), 0.25, 0.01);
  // The peak of a 2,400-sphere cube is a jagged function of T: T = 23.6, 24.0,
  // 24.4, 24.8, 25.2 MPa give 43.4, 43.6, 45.9, 46.4, 46.1 MPa (measured; the
  // failure path changes with every change of the run), so a 2 % match of the
  // strength pins T down only to about 10 % (the synthetic-response unit test,
  // tests/dem/calibration/calibration_test.cpp, recovers T to 1e-4 where the response is smooth).
  EXPECT_NEAR(c["T_MPa"].get<double>() / 18.0, 1.0, 0.10);
  EXPECT_EQ(c["C_MPa"], c["T_MPa"]);
  EXPECT_LE(std::abs(c["sigma_error_pct"].get<double>()), 2.0);
  const int trials = c["trial_count"];
  EXPECT_LE(trials, 8);
  // The failure trials raise T from the start's 10 MPa, so a later one starts from an earlier one's
  // intact checkpoint (the same bits: tests/cli/mw_dem_checkpoint_test.cpp), and the log says so.
  EXPECT_NE(r.err.find(" steps from trial "), std::string::npos) << r.err;
  // Every trial is a run of its own in the provenance database, and the log lists them.
  const auto runs = run_tool("mw-prov", {"runs", "--json", "--db", db});
  ASSERT_EQ(runs.exit_status, 0) << runs.err;
  const auto listed = nlohmann::json::parse(runs.out);
  int dem_runs = 0, calibrate_runs = 0;
  for (const auto& run : listed) {
    dem_runs += run["tool"] == "mw-dem";
    calibrate_runs += run["tool"] == "mw-calibrate";
  }
  EXPECT_EQ(dem_runs, trials);
  EXPECT_EQ(calibrate_runs, 1);
  EXPECT_EQ(io::read_csv(dir / "trials.csv").rows.size(), std::size_t(trials));
  expect_mw_dem_takes_the_five(dir, cube);
}

TEST(MwCalibrate, RodGetsTheContactModulusOfItsYoungModulus) {
  test::TempDir dir;
  const fs::path rod = dir / "rod.h5";
  ASSERT_EQ(run_tool("mw-pack", {"line", "--sphere-radius-mm", "5.1", "--spacing-R", "1.05", "--length-mm", "200",
                                 "--density-kg-m3", "7850.66", "--packing", rod.string(), "--quiet"})
                .exit_status,
            0);
  const auto r = run_tool("mw-calibrate", {"rod", "--scene", kTension, "--packing", rod.string(), "--E-GPa", "208.72",
                                           "--work-dir", (dir / "trials").string(), "--out", (dir / "rod.json").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = json_of(r);
  EXPECT_NEAR(j["E_DEM_GPa"].get<double>() / 208.72, 1.0, 0.005);
  // E_DEM = E_dem R d / (pi R^2) (K_n = E_dem R): E_dem = E pi R / d.
  EXPECT_NEAR(j["E_dem_GPa"].get<double>() / (208.72 * std::numbers::pi / 1.05), 1.0, 0.005);
  EXPECT_NEAR(j["Kn_N_m"].get<double>(), j["E_dem_GPa"].get<double>() * 1e9 * 5.1e-3, 1e-3);
  // The first trial ran the scene's E_dem (the rod paper's 660 GPa for 1.03 R): its E_DEM is 660 d / (pi R).
  EXPECT_NEAR(j["E_DEM_at_start_GPa"].get<double>() / (660.0 * 1.05 / std::numbers::pi), 1.0, 1e-4);
}

TEST(MwCalibrate, RefusesTargetsNoPackingReaches) {
  test::TempDir dir;
  const fs::path cube = small_cube(dir);
  auto calibrate = [&](const std::string& E, const std::string& nu, const std::string& sigma, const std::string& scene) {
    return run_tool("mw-calibrate", {"cube", "--scene", scene, "--packing", cube.string(), "--E-st-measured-GPa", E,
                                     "--nu-st", nu, "--sigma-max-MPa", sigma, "--work-dir", (dir / "w").string(),
                                     "--out", (dir / "out.json").string()});
  };
  const std::vector<std::tuple<std::string, std::string, std::string, std::string, std::string>> bad = {
      {"27.42", "0.5", "66", kCompression, "must lie in (0, 0.5)"},
      {"27.42", "0.55", "66", kCompression, "must lie in (0, 0.5)"},
      {"-27.42", "0.16", "66", kCompression, "must be positive"},
      {"27.42", "0.16", "5000", kCompression, "peak strain"},
      {"27.42", "0.16", "66", (kSource / "pipeline/concrete-cube/scenes/cube-wave.toml").string(), "no [test] table"},
      {"27.42", "0.16", "66", kTension, "needs a compression test"},
  };
  for (const auto& [E, nu, sigma, scene, message] : bad) {
    const auto r = calibrate(E, nu, sigma, scene);
    EXPECT_EQ(r.exit_status, 1) << nu << " " << sigma;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.json"));
  }
}

// The dynamic calibration (CC_CALIBRATION_TARGETS=dynamic): --E-d-GPa and --nu-d take the place of
// E_st and nu_st, so a bad one is refused by its own name before any trial runs, even beside good
// static targets (which they replace; the strength stays --sigma-max-MPa's).
TEST(MwCalibrate, DynamicTargetsReplaceTheStaticOnesAndAreCheckedByTheirName) {
  test::TempDir dir;
  const fs::path cube = small_cube(dir);
  auto calibrate = [&](const std::vector<std::string>& dynamic) {
    std::vector<std::string> args = {"cube", "--scene", kCompression, "--packing", cube.string(), "--E-st-measured-GPa",
                                     "27.42", "--nu-st", "0.16", "--sigma-max-MPa", "66", "--work-dir",
                                     (dir / "w").string(), "--out", (dir / "out.json").string()};
    args.insert(args.end(), dynamic.begin(), dynamic.end());
    return run_tool("mw-calibrate", args);
  };
  const auto bad_E = calibrate({"--E-d-GPa", "-36.67", "--nu-d", "0.16"});
  EXPECT_EQ(bad_E.exit_status, 1);
  EXPECT_NE(bad_E.err.find("--E-d-GPa (-36.67 GPa) must be positive"), std::string::npos) << bad_E.err;
  const auto bad_nu = calibrate({"--E-d-GPa", "36.67", "--nu-d", "0.55"});
  EXPECT_EQ(bad_nu.exit_status, 1);
  EXPECT_NE(bad_nu.err.find("must lie in (0, 0.5)"), std::string::npos) << bad_nu.err;
  EXPECT_FALSE(fs::exists(dir / "out.json"));
  EXPECT_FALSE(fs::exists(dir / "w" / "trial-01.json"));
}
