// mw-dem end to end: info and run on small scenes, outputs only on success.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "mesowave/dem/packing/packing_file.hpp"
#include "mesowave/dem/packing/packing_generator.hpp"
#include "mesowave/signal/signal_file.hpp"
#include "support/rod_scene.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using test::run_tool;

namespace {

dem::Packing rod(std::size_t n, double r, double d) {
  dem::Packing p;
  for (std::size_t i = 0; i < n; ++i) {
    p.centres_m.push_back({r + double(i) * d, 0, 0});
    p.radii_m.push_back(r);
    p.ids.push_back(std::int64_t(i));
  }
  p.container.shape = "line";
  p.particle_density_kg_m3 = 6044.37;
  return p;
}

void replace_once(std::string& text, const std::string& key, const std::string& by) {
  const auto at = text.find(key);
  ASSERT_NE(at, std::string::npos) << key;
  text.replace(at, key.size(), by);
}

std::string rod_scene(const std::filesystem::path& packing) { return mesowave::test::rod_chain_scene_toml(packing); }

// The shipped rod scene, its packing and its experiment file given as absolute paths.
std::string shipped_rod_scene(const std::filesystem::path& packing) {
  const std::filesystem::path source = MESOWAVE_SOURCE_DIR;
  std::string text = test::read_file(source / "pipeline/steel-rod/scenes/rod-wave.toml");
  replace_once(text, "file = \"results/steel-rod/packing-1.03R.h5\"", "file = \"" + packing.string() + "\"");
  replace_once(text, "file = \"../../../lab-data/steel-rod/experiment.toml\"",
          "file = \"" + (source / "lab-data/steel-rod/experiment.toml").string() + "\"");
  return text;
}

}  // namespace

// On the pipeline's packing: mw-pack line of the experiment's rod at 1.03 R.
TEST(MwDem, InfoOnTheShippedRodSceneChoosesTheChain) {
  test::TempDir dir;
  const auto pack = run_tool("mw-pack", {"line", "--experiment",
                                         std::string(MESOWAVE_SOURCE_DIR) + "/lab-data/steel-rod/experiment.toml",
                                         "--spacing-R", "1.03", "--packing", (dir / "rod.h5").string()});
  ASSERT_EQ(pack.exit_status, 0) << pack.err;
  test::write_file(dir / "rod.toml", shipped_rod_scene(dir / "rod.h5"));
  const auto r = run_tool("mw-dem", {"info", (dir / "rod.toml").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model"], "chain");
  EXPECT_EQ(j["spheres"], 191);
  EXPECT_EQ(j["bonds"], 190);
  EXPECT_EQ(j["steps"], 30000);
  EXPECT_GT(j["dt_limit_s"].get<double>(), 5e-8);
  // Memory: positions, velocities, forces of 191 spheres and 190 bonds, and one sensor's 30,001 samples.
  EXPECT_GT(j["memory_estimate_MiB"].get<double>(), 30001 * 8 / 1048576.0);
  EXPECT_LT(j["memory_estimate_MiB"].get<double>(), 1.0);
  EXPECT_EQ(test::count_files(dir.path()), 2u);  // info writes nothing
}

TEST(MwDem, RunWritesSignalsAndSummary) {
  test::TempDir dir;
  dem::write_packing_file(dir / "rod.h5", rod(191, 5.1e-3, 1.03 * 5.1e-3));
  test::write_file(dir / "rod.toml", rod_scene(dir / "rod.h5"));
  const auto r = run_tool("mw-dem", {"run", (dir / "rod.toml").string(), "--frequency-kHz", "80", "--duration-ms", "0.5",
                                     "--signals", (dir / "s.h5").string(), "--summary", (dir / "s.json").string(), "--quiet"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto signals = signal::read_signal_file(dir / "s.h5");
  ASSERT_EQ(signals.size(), 1u);
  EXPECT_EQ(signals[0].name, "S");
  EXPECT_EQ(signals[0].quantity, "acceleration");
  EXPECT_EQ(signals[0].size(), 10000u);
  EXPECT_DOUBLE_EQ(signals[0].dt_s, 5e-8);
  const auto j = nlohmann::json::parse(test::read_file(dir / "s.json"));
  EXPECT_EQ(j["model"], "chain");
  EXPECT_GT(j["steps_per_s"].get<double>(), 0.0);
  EXPECT_EQ(j["energy"]["external_work_J"].get<double>() > 0, true);
  // The chain's critical step is the closed form 2 / omega_max, omega_max = 2 sqrt(K_n / m)
  // (no damping), and the paper's estimate R sqrt(rho / E) sits below it.
  const double R = 5.1e-3, kn = 660e9 * R, m = 6044.37 * 4.0 / 3.0 * 3.14159265358979 * R * R * R;
  EXPECT_NEAR(j["dt_cr_eigenvalue_s"].get<double>() / (1.0 / std::sqrt(kn / m)), 1.0, 1e-3);
  EXPECT_NEAR(j["dt_cr_paper_estimate_s"].get<double>(), R * std::sqrt(6044.37 / 660e9), 1e-12);
  EXPECT_LE(j["dt_limit_s"].get<double>(), j["dt_cr_eigenvalue_s"].get<double>());
  // Undamped: what the force put in is in the rod, to round-off.
  EXPECT_LT(std::abs(j["energy"]["residual_relative"].get<double>()), 1e-9);
  // Peak bond force / strength: the rod scene gives no strengths, so nothing can break (0).
  EXPECT_EQ(j["peak_force_ratio"].get<double>(), 0.0);
  EXPECT_EQ(j["validity_bound"], nullptr);
}

// One run, every frequency (--frequencies-kHz): the undamped chain is linear, so each file equals
// the direct run at its frequency to round-off, and the record says how it was made.
TEST(MwDem, FrequenciesFromOneRunMatchTheDirectRuns) {
  test::TempDir dir;
  dem::write_packing_file(dir / "rod.h5", rod(191, 5.1e-3, 1.03 * 5.1e-3));
  test::write_file(dir / "rod.toml", rod_scene(dir / "rod.h5"));
  const auto r = run_tool("mw-dem", {"run", (dir / "rod.toml").string(), "--duration-ms", "0.5", "--frequencies-kHz",
                                     "80,120", "--check-kHz", "120", "--signals-pattern", (dir / "s-{f}kHz.h5").string(),
                                     "--summary-pattern", (dir / "s-{f}kHz.json").string(), "--summary",
                                     (dir / "all.json").string(), "--quiet"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  for (const char* f : {"80", "120"}) {
    const auto d = run_tool("mw-dem", {"run", (dir / "rod.toml").string(), "--duration-ms", "0.5", "--frequency-kHz", f,
                                       "--signals", (dir / "d.h5").string(), "--quiet"});
    ASSERT_EQ(d.exit_status, 0) << d.err;
    const auto direct = signal::read_signal_file(dir / "d.h5");
    const auto superposed = signal::read_signal_file(dir / ("s-" + std::string(f) + "kHz.h5"));
    ASSERT_EQ(superposed.size(), 1u);
    EXPECT_EQ(superposed[0].name, direct[0].name);
    EXPECT_EQ(superposed[0].t0_s, direct[0].t0_s);
    EXPECT_EQ(superposed[0].dt_s, direct[0].dt_s);
    ASSERT_EQ(superposed[0].size(), direct[0].size());
    double peak = 0, diff = 0;
    for (std::size_t i = 0; i < direct[0].size(); ++i) {
      peak = std::max(peak, std::abs(direct[0].samples[i]));
      diff = std::max(diff, std::abs(superposed[0].samples[i] - direct[0].samples[i]));
    }
    EXPECT_LT(diff, 1e-10 * peak) << f;
    const auto j = nlohmann::json::parse(test::read_file(dir / ("s-" + std::string(f) + "kHz.json")));
    EXPECT_EQ(j["method"], "superposition");
    EXPECT_EQ(j["model"], "chain");
    EXPECT_EQ(j["superposition"]["exact"], true);
    EXPECT_EQ(j["actuator_loads"][0]["frequency_hz"].get<double>(), std::stod(f) * 1e3);
    EXPECT_EQ(j["superposition"]["check"] == nullptr, std::string(f) == "80");
  }
  const auto all = nlohmann::json::parse(test::read_file(dir / "all.json"));
  ASSERT_EQ(all["superposition"]["checks"].size(), 1u);
  EXPECT_GT(all["superposition"]["checks"][0]["min_pcc"].get<double>(), 1 - 1e-12);
  EXPECT_LT(all["superposition"]["checks"][0]["max_diff_over_peak"].get<double>(), 1e-10);
  EXPECT_EQ(all["frequencies"].size(), 2u);
}

TEST(MwDem, FrequenciesNeedAPatternWithTheFrequencyAndWriteNothingOtherwise) {
  test::TempDir dir;
  dem::write_packing_file(dir / "rod.h5", rod(50, 5.1e-3, 1.03 * 5.1e-3));
  test::write_file(dir / "rod.toml", rod_scene(dir / "rod.h5"));
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--signals-pattern", (dir / "s.h5").string()}, "needs {f}"},
      {{"--signals-pattern", (dir / "s-{f}.h5").string(), "--signals", (dir / "s.h5").string()}, "for one direct run"},
      {{"--signals-pattern", (dir / "s-{f}.h5").string(), "--check-kHz", "90"}, "must be one of --frequencies-kHz"},
      {{"--signals-pattern", (dir / "s-{f}.h5").string(), "--model", "full"}, "needs a linear model"},
  };
  for (const auto& [extra, why] : cases) {
    std::vector<std::string> args = {"run", (dir / "rod.toml").string(), "--duration-ms", "0.01", "--frequencies-kHz",
                                     "80,120", "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = run_tool("mw-dem", args);
    EXPECT_EQ(r.exit_status, 1) << why;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    EXPECT_EQ(test::count_files(dir.path()), 2u) << why;
  }
}

TEST(MwDem, RecordsItsRunWithInputsOutputsAndMetrics) {
  test::TempDir dir;
  dem::write_packing_file(dir / "rod.h5", rod(50, 5.1e-3, 1.03 * 5.1e-3));
  test::write_file(dir / "rod.toml", rod_scene(dir / "rod.h5"));
  const std::string db = (dir / "prov.sqlite").string();
  const auto r = run_tool("mw-dem", {"run", (dir / "rod.toml").string(), "--duration-ms", "0.05", "--signals",
                                     (dir / "s.h5").string(), "--summary", (dir / "s.json").string(), "--quiet",
                                     "--db", db});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto show = run_tool("mw-prov", {"show", "1", "--json", "--db", db});
  ASSERT_EQ(show.exit_status, 0) << show.err;
  const auto j = nlohmann::json::parse(show.out);
  EXPECT_EQ(j["tool"], "mw-dem");
  EXPECT_EQ(j["exit_status"], 0);
  std::vector<std::string> inputs, outputs, metrics;
  for (const auto& f : j["inputs"]) inputs.push_back(std::filesystem::path(f["path"].get<std::string>()).filename());
  for (const auto& f : j["outputs"]) outputs.push_back(std::filesystem::path(f["path"].get<std::string>()).filename());
  for (const auto& m : j["metrics"]) metrics.push_back(m["name"]);
  EXPECT_EQ(inputs, (std::vector<std::string>{"rod.toml", "rod.h5"}));
  EXPECT_EQ(outputs, (std::vector<std::string>{"s.h5", "s.json"}));
  for (const char* name : {"steps_per_s", "wall", "dt_limit", "peak_force_ratio"})
    EXPECT_NE(std::find(metrics.begin(), metrics.end(), name), metrics.end()) << name;
}

TEST(MwDem, ATooLargeTimeStepIsRefusedAndNothingIsWritten) {
  test::TempDir dir;
  dem::write_packing_file(dir / "rod.h5", rod(50, 5.1e-3, 1.03 * 5.1e-3));
  test::write_file(dir / "rod.toml", rod_scene(dir / "rod.h5"));
  const auto r = run_tool("mw-dem", {"run", (dir / "rod.toml").string(), "--dt-ns", "5000", "--signals",
                                     (dir / "s.h5").string(), "--quiet"});
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_NE(r.err.find("exceeds the stable limit"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "s.h5"));
}

TEST(MwDem, UnknownSceneKeyIsNamed) {
  test::TempDir dir;
  dem::write_packing_file(dir / "rod.h5", rod(10, 5.1e-3, 1.03 * 5.1e-3));
  std::string text = rod_scene(dir / "rod.h5");
  text.replace(text.find("damping = 0.0"), 13, "dampnig = 0.0");
  test::write_file(dir / "rod.toml", text);
  const auto r = run_tool("mw-dem", {"info", (dir / "rod.toml").string()});
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_NE(r.err.find("unknown key \"dampnig\""), std::string::npos) << r.err;
}

TEST(MwDem, SnapshotsAreVtkPolyDataWithATimeSeries) {
  test::TempDir dir;
  dem::write_packing_file(dir / "rod.h5", rod(30, 5.1e-3, 1.03 * 5.1e-3));
  test::write_file(dir / "rod.toml", rod_scene(dir / "rod.h5"));
  const auto r = run_tool("mw-dem", {"run", (dir / "rod.toml").string(), "--duration-ms", "0.01", "--signals",
                                     (dir / "s.h5").string(), "--snapshots", (dir / "snap").string(),
                                     "--snapshot-interval-us", "5", "--quiet"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  // t = 0, 5 and 10 us.
  for (int k = 0; k < 3; ++k) {
    const std::string vtp = test::read_file(dir / "snap" / ("snapshot-" + std::to_string(k) + ".vtp"));
    EXPECT_NE(vtp.find("<VTKFile type=\"PolyData\""), std::string::npos);
    EXPECT_NE(vtp.find("NumberOfPoints=\"30\""), std::string::npos);
    for (const char* name : {"radius", "displacement", "velocity"})
      EXPECT_NE(vtp.find(std::string("Name=\"") + name + "\""), std::string::npos) << name;
    EXPECT_NE(vtp.find("</VTKFile>"), std::string::npos);
  }
  const std::string pvd = test::read_file(dir / "snap" / "snapshots.pvd");
  EXPECT_NE(pvd.find("timestep=\"1e-05\" part=\"0\" file=\"snapshot-2.vtp\""), std::string::npos) << pvd;
}

// SIGTERM while the run steps (app/interrupt.hpp): the run stops at its next progress
// report, writes nothing, exits with 128 + 15 by itself (not killed by the signal) and is in
// the provenance database as interrupted, with the step it reached.
TEST(MwDem, ASigtermStopsTheRunWritesNothingAndRecordsItAsInterrupted) {
  test::TempDir dir, db_dir;
  dem::write_packing_file(dir / "rod.h5", rod(191, 5.1e-3, 1.03 * 5.1e-3));
  test::write_file(dir / "rod.toml", rod_scene(dir / "rod.h5"));
  const std::string db = (db_dir / "p.sqlite").string();
  const std::int64_t steps = 4'000'000;  // 200 ms at 50 ns: seconds of stepping, stopped after its first 10 %
  const auto r = test::run_tool_and_signal(
      "mw-dem", {"run", (dir / "rod.toml").string(), "--frequency-kHz", "80", "--duration-ms", "200", "--signals",
                 (dir / "s.h5").string(), "--summary", (dir / "s.json").string(), "--db", db},
      " 10% ", SIGTERM);  // the progress line at 10 % (lines at 0, 10, 20, ... % off a terminal)
  ASSERT_TRUE(r.signal_sent) << "the run ended before its first progress line: " << r.err;
  EXPECT_FALSE(r.killed_by_signal);
  EXPECT_EQ(r.exit_status, 143) << r.err;
  EXPECT_NE(r.err.find("error: interrupted by SIGTERM after "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("; no output was written"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("; kept "), std::string::npos) << r.err;  // no checkpoint asked for
  EXPECT_EQ(test::count_files(dir.path()), 2u);  // rod.h5 and rod.toml: no signals, summary or staged temporary

  const auto runs = nlohmann::json::parse(run_tool("mw-prov", {"--db", db, "runs", "--json"}).out);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0]["tool"], "mw-dem");
  EXPECT_EQ(runs[0]["exit_status"], 143);
  EXPECT_EQ(runs[0]["status"], "interrupted");
  const auto show = nlohmann::json::parse(run_tool("mw-prov", {"--db", db, "show", "1", "--json"}).out);
  const auto& where = show["params"]["interrupted"];
  EXPECT_EQ(where["signal"], "SIGTERM");
  EXPECT_EQ(where["unit"], "steps");
  EXPECT_EQ(where["total"].get<std::int64_t>(), steps);
  const auto done = where["done"].get<std::int64_t>();
  EXPECT_GE(done, steps / 10);  // the signal came after the 10 % line
  EXPECT_LT(done, steps);
  EXPECT_TRUE(show["outputs"].empty());
  const std::string reached = "after " + std::to_string(done) + " of " + std::to_string(steps) + " steps (mw-dem rod-wave)";
  EXPECT_NE(runs[0]["error"].get<std::string>().find(reached), std::string::npos) << runs[0]["error"];

  const auto text = run_tool("mw-prov", {"--db", db, "runs"});
  EXPECT_NE(text.out.find("interrupted"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find(reached), std::string::npos) << text.out;
}

TEST(MwDem, StaticCompressionGivesTheSteppedElasticTrialsModulus) {
  // mw-calibrate's elastic trial of the shipped compression scene on a 16 mm
  // cube, stepped and solved (--static): the same E_glob and nu_glob (a 12 mm
  // cube's nu_glob differs by 1.3e-4: the smaller the cube, the more of its
  // extensometer pads are surface spheres; docs/calibration.md); the static
  // summary keeps the keys mw-calibrate reads (model, wall_s, test).
  test::TempDir dir;
  dem::PackingOptions po;
  po.porosity = 0.07;
  po.sizes = dem::SizeDistribution::uniform(1.6e-3, 2.0e-3);
  dem::Packing p = dem::generate_packing(dem::box_container({0, 0, 0}, {16e-3, 16e-3, 16e-3}), po);
  p.particle_density_kg_m3 = 2129.56;
  dem::write_packing_file(dir / "cube.h5", p);
  const std::string scene = std::string(MESOWAVE_SOURCE_DIR) + "/pipeline/concrete-cube/scenes/cube-compression.toml";
  const std::vector<std::string> trial = {"run", scene, "--packing", (dir / "cube.h5").string(), "--unbreakable-bonds",
                                          "--model", "linear", "--modulus-levels-MPa", "5,16.666666666666668",
                                          "--stop-at-MPa", "17", "--quiet"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = trial;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  const auto dynamic = run_tool("mw-dem", with({"--signals", (dir / "d.h5").string()}));
  ASSERT_EQ(dynamic.exit_status, 0) << dynamic.err;
  const auto statics = run_tool("mw-dem", with({"--static", "--signals", (dir / "s.h5").string(), "--curves",
                                                (dir / "s.csv").string(), "--summary", (dir / "s.json").string()}));
  ASSERT_EQ(statics.exit_status, 0) << statics.err;
  const auto d = nlohmann::json::parse(dynamic.out), s = nlohmann::json::parse(statics.out);
  EXPECT_EQ(s["method"], "static");
  EXPECT_EQ(s["model"], "linear");
  EXPECT_TRUE(s.contains("wall_s"));
  EXPECT_NEAR(s["test"]["E_glob_GPa"].get<double>() / d["test"]["E_glob_GPa"].get<double>(), 1.0, 1e-4);
  EXPECT_NEAR(s["test"]["nu_glob"].get<double>(), d["test"]["nu_glob"].get<double>(), 1e-4);
  EXPECT_TRUE(std::filesystem::exists(dir / "s.h5"));
  EXPECT_TRUE(std::filesystem::exists(dir / "s.csv"));
  // hypre's multigrid as the preconditioner (a build with hypre; a plain run: MPI is started for it):
  // the Jacobi solve's values to what the solves' residual 1e-10 leaves (static_elastic_test.cpp).
  const auto amg = run_tool("mw-dem", with({"--static", "--static-preconditioner", "amg", "--signals",
                                            (dir / "a.h5").string()}));
  if (amg.exit_status == 0) {
    const auto a = nlohmann::json::parse(amg.out);
    EXPECT_EQ(a["solver"], "BiCGSTAB (BoomerAMG)");
    EXPECT_NEAR(a["test"]["E_glob_GPa"].get<double>() / s["test"]["E_glob_GPa"].get<double>(), 1.0, 1e-8);
    EXPECT_NEAR(a["test"]["nu_glob"].get<double>(), s["test"]["nu_glob"].get<double>(), 1e-8);
  } else {
    EXPECT_NE(amg.err.find("needs hypre"), std::string::npos) << amg.err;
  }
  // Levels as fractions of a peak mean nothing for a linear response: refused, nothing written.
  const auto pct = run_tool("mw-dem", {"run", scene, "--packing", (dir / "cube.h5").string(), "--static",
                                       "--unbreakable-bonds", "--signals", (dir / "x.h5").string(), "--quiet"});
  EXPECT_EQ(pct.exit_status, 1);
  EXPECT_NE(pct.err.find("modulus levels as stresses"), std::string::npos) << pct.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.h5"));
}
