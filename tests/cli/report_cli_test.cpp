// mw-report: a small report made from recorded runs, rendered in headless
// Chromium by scripts/check-report (every table there, every figure decoded).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>

#include "support/run_tool.hpp"

using namespace mesowave::test;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = MESOWAVE_SOURCE_DIR;

struct SmallReport : ::testing::Test {
  TempDir dir;
  std::string db = (dir / "p.sqlite").string();
  double runs_elapsed_s = 0;  // measured here around the two recorded runs
  void SetUp() override {
    const auto t0 = std::chrono::steady_clock::now();
    ASSERT_EQ(run_tool("mw-upv", {"--path-mm", "150", "--t-p-us", "35", "--t-s-us", "55.1", "--density-kg-m3", "2129.56",
                                  "--out", (dir / "upv.json").string(), "--db", db})
                  .exit_status,
              0);
    ASSERT_EQ(run_tool("mw-compare", {"--ours", (dir / "upv.json").string(), "--paper",
                                      (kSource / "lab-data/concrete-cube/paper/printed-results.toml").string(), "--csv",
                                      (dir / "upv-vs-paper.csv").string(), "--db", db})
                  .exit_status,
              0);
    runs_elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    write_file(dir / "sketch.svg",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"120\" height=\"40\"><rect width=\"120\" height=\"40\" "
               "fill=\"#8ab\"/></svg>\n");
    fs::copy_file(kSource / "docs/figures/signal-burst.png", dir / "burst.png");
    write_file(dir / "spec.toml",
               "title = \"test report\"\n[[section]]\ntitle = \"Moduli\"\ntext = \"From `mw-upv`.\"\n"
               "[[section.item]]\ntable = \"upv-vs-paper.csv\"\ncaption = \"E_d vs the paper\"\n"
               "[[section.item]]\nfigure = \"sketch.svg\"\ncaption = \"an SVG\"\n"
               "[[section.item]]\nfigure = \"burst.png\"\ncaption = \"a PNG\"\n");
  }
  ToolResult report() {
    return run_tool("mw-report", {"--spec", (dir / "spec.toml").string(), "--base", dir.path().string(), "--out-dir",
                                  (dir / "report").string(), "--db", db});
  }
  ToolResult check(const std::vector<std::string>& counts) {
    std::vector<std::string> args = {(dir / "report/index.html").string()};
    args.insert(args.end(), counts.begin(), counts.end());
    return run_command(kSource / "scripts/check-report", args);
  }
};

}  // namespace

TEST_F(SmallReport, RendersEveryTableAndFigureWithProvenance) {
  const auto r = report();
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.out.find("1 tables, 2 figures"), std::string::npos) << r.out;
  const auto html = read_file(dir / "report/index.html");
  EXPECT_NE(html.find("run 2 <code>mw-compare</code>"), std::string::npos);
  EXPECT_NE(html.find("&lt;- run 1 mw-upv"), std::string::npos);  // lineage reaches the mw-upv run
  EXPECT_NE(html.find("<code>mw-upv</code>"), std::string::npos);   // backticks become code
  EXPECT_TRUE(fs::exists(dir / "report/figures/sketch.svg"));
  const auto c = check({"1", "2"});
  EXPECT_EQ(c.exit_status, 0) << c.out << c.err;
  EXPECT_EQ(c.out.rfind("report OK: 1 tables", 0), 0u) << c.out;
}

TEST_F(SmallReport, StatesThePipelinesWallTime) {
  ASSERT_EQ(report().exit_status, 0);
  const auto html = read_file(dir / "report/index.html");
  const std::string key = "<th>wall time of the pipeline</th><td>";
  const auto at = html.find(key);
  ASSERT_NE(at, std::string::npos);
  const double span = std::strtod(html.c_str() + at + key.size(), nullptr);
  // From the first run's start to the last run's end: at least the two runs' own wall times
  // (they ran one after the other), at most what this test measured around them (the
  // recorded times have millisecond resolution).
  // Runs 1 and 2 made the report's files; run 3 is mw-report itself.
  const auto runs = nlohmann::json::parse(run_tool("mw-prov", {"--db", db, "runs", "--json"}).out);
  ASSERT_EQ(runs.size(), 3u);
  ASSERT_EQ(runs[2]["tool"], "mw-report");
  const double walls = runs[0]["wall_s"].get<double>() + runs[1]["wall_s"].get<double>();
  EXPECT_GE(span, walls - 0.0025);
  EXPECT_LE(span, runs_elapsed_s + 0.0025);
}

TEST_F(SmallReport, ChromiumCatchesAFigureThatDoesNotDecode) {
  ASSERT_EQ(report().exit_status, 0);
  write_file(dir / "report/figures/burst.png", "not a png");
  const auto c = check({"1", "2"});
  EXPECT_EQ(c.exit_status, 1) << c.out;
  EXPECT_NE(c.out.find("1 images failed to load"), std::string::npos) << c.out;
  EXPECT_EQ(check({"2", "2"}).exit_status, 1);  // and a missing table
}

TEST_F(SmallReport, AMissingItemIsNamedAndNothingIsWritten) {
  fs::remove(dir / "sketch.svg");
  const auto r = report();
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_NE(r.err.find("sketch.svg"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "report"));
}

// Table 3's per-sensor tables are wider than a laptop's window: the report keeps them in a
// box of their own that scrolls, and the page itself fits 1280 px (scripts/check-report
// measures document.documentElement.scrollWidth in Chromium at that width). The same page
// without the box has the horizontal scrollbar the check exists for.
TEST_F(SmallReport, AWideTableScrollsInItsOwnBoxAndThePageFits1280Px) {
  std::string csv = "f_kHz";
  for (const char* s : {"B", "C", "D", "E", "F", "G"})
    for (const char* q : {"pcc_signal", "pcc_envelope", "samples", "from_us"}) csv += std::string(",") + s + " " + q;
  csv += "\n";
  for (int f = 100; f <= 500; f += 50) {
    csv += std::to_string(f);
    for (int i = 0; i < 24; ++i) csv += ",0.123456789012";
    csv += "\n";
  }
  write_file(dir / "wide.csv", csv);
  write_file(dir / "spec.toml", read_file(dir / "spec.toml") +
                                    "[[section.item]]\ntable = \"wide.csv\"\ncaption = \"per-sensor PCC, 9 frequencies\"\n");
  ASSERT_EQ(report().exit_status, 0);
  const auto c = check({"2", "2"});
  EXPECT_EQ(c.exit_status, 0) << c.out << c.err;
  const auto at = c.out.find(" px wide in a 1280 px window");
  ASSERT_NE(at, std::string::npos) << c.out;
  const auto from = c.out.rfind(", ", at) + 2;
  EXPECT_LE(std::stoi(c.out.substr(from, at - from)), 1280) << c.out;

  // Unboxed, the same table pushes the page past the window.
  auto html = read_file(dir / "report/index.html");
  ASSERT_NE(html.find("<div class=\"table-box\">"), std::string::npos);
  for (auto p = html.find("<div class=\"table-box\">"); p != std::string::npos; p = html.find("<div class=\"table-box\">"))
    html.replace(p, std::string("<div class=\"table-box\">").size(), "<div>");
  write_file(dir / "report/unboxed.html", html);
  const auto u = run_command(kSource / "scripts/check-report", {(dir / "report/unboxed.html").string(), "2", "2"});
  EXPECT_EQ(u.exit_status, 1) << u.out;
  EXPECT_NE(u.out.find("a horizontal scrollbar"), std::string::npos) << u.out;
}
