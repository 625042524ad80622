// mw-dem end to end: info and run on small scenes, outputs only on success.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "mesowave/dem/packing_file.hpp"
#include "mesowave/io/signal_file.hpp"
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

// The shipped rod scene, pointed at a packing written here.
std::string rod_scene(const std::filesystem::path& packing) {
  std::string text = test::read_file(std::filesystem::path(MESOWAVE_SOURCE_DIR) / "pipeline/steel-rod/scenes/rod-wave.toml");
  const std::string key = "file = \"results/steel-rod/packing-1.03R.h5\"";
  const auto at = text.find(key);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, key.size(), "file = \"" + packing.string() + "\"");
  return text;
}

}  // namespace

TEST(MwDem, InfoOnTheShippedRodSceneChoosesTheChain) {
  test::TempDir dir;
  dem::write_packing_file(dir / "rod.h5", rod(191, 5.1e-3, 1.03 * 5.1e-3));
  test::write_file(dir / "rod.toml", rod_scene(dir / "rod.h5"));
  const auto r = run_tool("mw-dem", {"info", (dir / "rod.toml").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model"], "chain");
  EXPECT_EQ(j["spheres"], 191);
  EXPECT_EQ(j["bonds"], 190);
  EXPECT_EQ(j["steps"], 30000);
  EXPECT_GT(j["dt_limit_s"].get<double>(), 5e-8);
  EXPECT_EQ(test::count_files(dir.path()), 2u);  // info writes nothing
}

TEST(MwDem, RunWritesSignalsAndSummary) {
  test::TempDir dir;
  dem::write_packing_file(dir / "rod.h5", rod(191, 5.1e-3, 1.03 * 5.1e-3));
  test::write_file(dir / "rod.toml", rod_scene(dir / "rod.h5"));
  const auto r = run_tool("mw-dem", {"run", (dir / "rod.toml").string(), "--frequency-kHz", "80", "--duration-ms", "0.5",
                                     "--signals", (dir / "s.h5").string(), "--summary", (dir / "s.json").string(), "--quiet"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto signals = io::read_signal_file(dir / "s.h5");
  ASSERT_EQ(signals.size(), 1u);
  EXPECT_EQ(signals[0].name, "S");
  EXPECT_EQ(signals[0].quantity, "acceleration");
  EXPECT_EQ(signals[0].size(), 10000u);
  EXPECT_DOUBLE_EQ(signals[0].dt_s, 5e-8);
  const auto j = nlohmann::json::parse(test::read_file(dir / "s.json"));
  EXPECT_EQ(j["model"], "chain");
  EXPECT_GT(j["steps_per_s"].get<double>(), 0.0);
  EXPECT_EQ(j["energy"]["external_work_J"].get<double>() > 0, true);
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
