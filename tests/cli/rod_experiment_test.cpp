// The steel rod's experiment (lab-data/steel-rod/experiment.toml) as the rod tools take it
// (--experiment): the same bits as the rod paper's values typed as options (Section 4.1), so
// that the pipeline's one copy of them moves no result. The quick tree's shorter rod is
// --length-mm; the FEM's concentrated force (Section 4.3.1) is --patch-radius-mm 0.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "mesowave/signal/signal_file.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using mesowave::test::read_file;
using mesowave::test::run_tool;
using mesowave::test::TempDir;

namespace {
const std::string kRod = std::string(MESOWAVE_SOURCE_DIR) + "/lab-data/steel-rod/experiment.toml";
const std::vector<std::string> kSteel = {"--E-GPa", "208.72", "--nu", "0.3", "--density-kg-m3", "7850.66"};
std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}
// Every signal the same, sample for sample, bit for bit.
void expect_same_signals(const std::filesystem::path& a, const std::filesystem::path& b) {
  const auto x = signal::read_signal_file(a), y = signal::read_signal_file(b);
  ASSERT_EQ(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_EQ(x[i].name, y[i].name);
    EXPECT_EQ(x[i].dt_s, y[i].dt_s);
    EXPECT_EQ(x[i].samples, y[i].samples) << x[i].name;
  }
}
nlohmann::json json_without_wall_time(const std::string& text) {
  auto j = nlohmann::json::parse(text);
  j.erase("wall_time_s");
  j.erase("wall_s");
  j.erase("steps_per_s");
  j.erase("element_updates_per_s");
  j.erase("peak_rss_MiB");
  j.erase("signals");
  // the machine's state at the start, not the run's result (core/threads: the other runnable threads)
  j.erase("threads");
  j.erase("threads_reason");
  return j;
}
}  // namespace

TEST(RodExperiment, MwFemRodGivesTheSignalsOfTheTypedValues) {
  TempDir dir;
  const std::vector<std::string> run = {"--mesh-mm", "1.7", "--frequency-kHz", "100", "--alpha-damping", "2000",
                                        "--duration-ms", "0.08", "--quiet"};
  // The quick tree's rule: the experiment's rod, shortened; a point force as the paper's FEM.
  const auto typed = run_tool("mw-fem", with(with(with({"rod"}, kSteel), {"--radius-mm", "5.1", "--length-mm", "200"}),
                                             with(run, {"--signals", (dir / "typed.h5").string()})));
  ASSERT_EQ(typed.exit_status, 0) << typed.err;
  const auto lab = run_tool("mw-fem", with({"rod", "--experiment", kRod, "--length-mm", "200", "--patch-radius-mm", "0"},
                                           with(run, {"--signals", (dir / "lab.h5").string()})));
  ASSERT_EQ(lab.exit_status, 0) << lab.err;
  expect_same_signals(dir / "typed.h5", dir / "lab.h5");
  EXPECT_EQ(json_without_wall_time(typed.out), json_without_wall_time(lab.out));
  // The full tree's rule: the experiment's own 1000 mm rod (a short record: the first packet only).
  const auto typed_full = run_tool("mw-fem", with(with(with({"rod"}, kSteel), {"--radius-mm", "5.1", "--length-mm", "1000"}),
                                                  with(run, {"--signals", (dir / "typed-full.h5").string()})));
  ASSERT_EQ(typed_full.exit_status, 0) << typed_full.err;
  const auto lab_full = run_tool("mw-fem", with({"rod", "--experiment", kRod, "--patch-radius-mm", "0"},
                                                with(run, {"--signals", (dir / "lab-full.h5").string()})));
  ASSERT_EQ(lab_full.exit_status, 0) << lab_full.err;
  expect_same_signals(dir / "typed-full.h5", dir / "lab-full.h5");
  // Without --patch-radius-mm 0 the actuator is the experiment's 2 x 2 mm plate: another load, other signals.
  const auto plate = run_tool("mw-fem", with({"rod", "--experiment", kRod, "--length-mm", "200"},
                                             with(run, {"--signals", (dir / "plate.h5").string()})));
  ASSERT_EQ(plate.exit_status, 0) << plate.err;
  EXPECT_NE(signal::read_signal_file(dir / "plate.h5")[0].samples, signal::read_signal_file(dir / "lab.h5")[0].samples);
}

TEST(RodExperiment, MwFemRodRefusesWhatTheExperimentAlreadyGives) {
  TempDir dir;
  const auto sig = (dir / "s.h5").string();
  const auto radius = run_tool("mw-fem", {"rod", "--experiment", kRod, "--radius-mm", "5", "--signals", sig});
  EXPECT_EQ(radius.exit_status, 1);
  EXPECT_NE(radius.err.find("--experiment gives the rod's radius: no --radius-mm"), std::string::npos) << radius.err;
  const auto cube = run_tool("mw-fem", with({"rod", "--experiment", std::string(MESOWAVE_SOURCE_DIR) +
                                                                        "/lab-data/concrete-cube/experiment.toml"},
                                            with(kSteel, {"--signals", sig})));
  EXPECT_EQ(cube.exit_status, 1);
  EXPECT_NE(cube.err.find("a rod is a cylinder specimen, this one is a 50 x 50 x 50 mm box"), std::string::npos) << cube.err;
  const auto bare = run_tool("mw-fem", {"rod", "--radius-mm", "5.1", "--length-mm", "100", "--signals", sig});
  EXPECT_EQ(bare.exit_status, 1);
  EXPECT_NE(bare.err.find("give --E-GPa"), std::string::npos) << bare.err;
  EXPECT_EQ(mesowave::test::count_files(dir.path()), 0u);
}

TEST(RodExperiment, MwPackLineGivesTheChainOfTheTypedValues) {
  TempDir dir;
  const auto typed = run_tool("mw-pack", {"line", "--sphere-radius-mm", "5.1", "--spacing-R", "1.03", "--length-mm", "500",
                                          "--density-kg-m3", "7850.66", "--packing", (dir / "typed.h5").string()});
  ASSERT_EQ(typed.exit_status, 0) << typed.err;
  const auto lab = run_tool("mw-pack", {"line", "--experiment", kRod, "--spacing-R", "1.03", "--length-mm", "500",
                                        "--packing", (dir / "lab.h5").string()});
  ASSERT_EQ(lab.exit_status, 0) << lab.err;
  auto a = json_without_wall_time(typed.out), b = json_without_wall_time(lab.out);
  a.erase("packing_file");
  b.erase("packing_file");
  EXPECT_EQ(a, b);
  EXPECT_EQ(b["spheres"], 96);  // ceil(500 / 5.253)
  EXPECT_EQ(b["sphere_radius_mm"], 5.1);
  // The full rod: rod Table 1's 191 spheres of 1.03R (rod paper Section 4.3.2, n = ceil(L / d)).
  const auto full = run_tool("mw-pack", {"line", "--experiment", kRod, "--spacing-R", "1.03", "--packing", (dir / "f.h5").string()});
  ASSERT_EQ(full.exit_status, 0) << full.err;
  EXPECT_EQ(nlohmann::json::parse(full.out)["spheres"], 191);
  const auto box = run_tool("mw-pack", {"box", "--experiment", kRod, "--cube-side-mm", "10", "--packing", (dir / "b.h5").string()});
  EXPECT_EQ(box.exit_status, 1);
  EXPECT_NE(box.err.find("--experiment gives a line its rod"), std::string::npos) << box.err;
}

TEST(RodExperiment, MwDispersionTakesTheRodAndTheEchoRoundTrip) {
  TempDir dir;
  const std::vector<std::string> theory = {"theory", "--f-max-kHz", "200", "--df-kHz", "10", "--modes", "1"};
  const auto typed = run_tool("mw-dispersion", with(with(theory, kSteel), {"--radius-mm", "5.1", "--csv", (dir / "t.csv").string()}));
  ASSERT_EQ(typed.exit_status, 0) << typed.err;
  const auto lab = run_tool("mw-dispersion", with(theory, {"--experiment", kRod, "--csv", (dir / "l.csv").string()}));
  ASSERT_EQ(lab.exit_status, 0) << lab.err;
  EXPECT_EQ(read_file(dir / "t.csv"), read_file(dir / "l.csv"));
  EXPECT_EQ(typed.out, lab.out);
  // The echo at the far end of the 1000 mm rod: the round trip 2 L = 2000 mm unless --distance-mm says otherwise.
  const auto fem = run_tool("mw-fem", {"rod", "--experiment", kRod, "--patch-radius-mm", "0", "--mesh-mm", "1.7",
                                       "--frequency-kHz", "100", "--duration-ms", "0.7", "--sample-dt-us", "0.2", "--quiet",
                                       "--signals", (dir / "f.h5").string()});
  ASSERT_EQ(fem.exit_status, 0) << fem.err;
  const auto m_typed = run_tool("mw-dispersion", with(with({"measure", "--run", (dir / "f.h5").string(), "--method", "echo",
                                                            "--distance-mm", "2000", "--radius-mm", "5.1"},
                                                           kSteel),
                                                      {"--csv", (dir / "mt.csv").string()}));
  ASSERT_EQ(m_typed.exit_status, 0) << m_typed.err;
  const auto m_lab = run_tool("mw-dispersion", {"measure", "--run", (dir / "f.h5").string(), "--method", "echo",
                                                "--experiment", kRod, "--csv", (dir / "ml.csv").string()});
  ASSERT_EQ(m_lab.exit_status, 0) << m_lab.err;
  EXPECT_EQ(read_file(dir / "mt.csv"), read_file(dir / "ml.csv"));
  EXPECT_NE(read_file(dir / "ml.csv").find(",2000,"), std::string::npos);
}
