// make concrete-cube-150 end to end on small models: the quick tree's sizes of cube-150.mk (the
// lab's cube at 37.5 mm, the 1/3-scale test on 30 mm), on a copy of the source tree with this
// build's tools (make QUICK=1 BUILD=..., as scripts/check-pipeline runs the quick pipeline, so
// that a test never rebuilds the tools the other tests run), with the upstream the chain needs
// (step 5's packing, both calibrations, the continuum references, the static calibration's Table 3).
// The full make takes over an hour and no other test runs its rules; its first end-to-end run
// met two bugs only in its last table, after 65 minutes (a row name with a comma; E_glob showing
// the picks' E_d). Here, in about a minute:
//  1. every rule of the chain ran: each output was made by a recorded, successful run of its tool;
//  2. the report is whole (scripts/check-report: the spec's tables and figures, none broken);
//  3. the tables hold their sources' numbers: in upv150.csv a DEM row's E_glob_GPa and nu_glob are
//     its calibration's (not its picks' E_d, nu_d), its times its picks', the measured row's
//     times upv.toml's, its E_d, nu_d upv.json's and its E_glob, nu_glob the compression tests'
//     E_st, nu_st (static-test.toml); table3-calibrations.csv's columns each calibration's table3.csv;
//  4. every tool run is in the quick provenance database, none failed, every output as recorded.
// Measured on the 2-core development machine (2026-12-06, five runs beside another engineer's
// benchmarks, load 2.4-4.5): 37-74 s wall, 63-74 s of CPU (user + system; the tree's copy, 6 s, and
// the report's rendering included). Of the tools' 46 s, the chain's own runs (both cubes' packings, the dynamic
// calibration, the wave runs, the picks, the tables, the report) take 28 s, the upstream quick
// pipeline they need 18 s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "mesowave/io/csv.hpp"
#include "support/quick_tree.hpp"

using namespace mesowave;
using namespace mesowave::test;
namespace fs = std::filesystem;

namespace {

nlohmann::json json_file(const fs::path& path) { return nlohmann::json::parse(read_file(path)); }

// A value as mw-table gather --significant-digits 4 prints it (cube-150.mk's upv150.csv), read back.
double printed(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.4g", x);
  return std::stod(text);
}

std::string label(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

// The number in row `key` (first column) and column `column`; a failure naming both if absent.
double cell(const io::CsvTable& t, const std::string& key, const std::string& column) {
  const auto c = t.find_column(column);
  if (!c) {
    ADD_FAILURE() << t.origin << ": no column " << column;
    return NAN;
  }
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    if (t.rows[r][0] == key) return t.number(r, *c);
  ADD_FAILURE() << t.origin << ": no row '" << key << "'";
  return NAN;
}

}  // namespace

TEST(Pipeline, Cube150ChainOnSmallModelsMakesEveryTableFromItsSources) {
  const QuickTree quick;
  ASSERT_TRUE(quick.copied);
  const fs::path &source = quick.source, &build = quick.build, &tree = quick.root, &db = quick.db;
  const std::string R = "results-quick/concrete-cube/", C = R + "cube-150/";
  const auto r = quick.make({"-j2", "--output-sync=target", "concrete-cube-150"});
  ASSERT_EQ(r.exit_status, 0) << "make concrete-cube-150 QUICK=1 failed:\n"
                              << r.out.substr(r.out.size() > 4000 ? r.out.size() - 4000 : 0) << r.err;

  // 4 (first, so that 1 can use it). make prints each tool's command line; mw-calibrate runs one
  // mw-dem per trial and says so on stderr.
  const auto runs = nlohmann::json::parse(run_tool("mw-prov", {"runs", "--json", "--db", db.string()}).out);
  std::size_t printed_runs = 0;
  for (std::size_t at = 0; (at = r.out.find(build.string() + "/bin/mw-", at)) != std::string::npos; ++at) ++printed_runs;
  std::istringstream err(r.err);
  const std::regex trial("^mw-calibrate: trial [0-9]+ .*");
  for (std::string line; std::getline(err, line);) printed_runs += std::regex_match(line, trial);
  EXPECT_EQ(runs.size(), printed_runs) << "recorded runs against the tool runs make printed";
  std::map<int, nlohmann::json> run_by_id;
  for (const auto& run : runs) {
    run_by_id[run["id"].get<int>()] = run;
    EXPECT_EQ(run["exit_status"], 0) << "run " << run["id"] << " (" << run["tool"] << ") failed: " << run["error"];
  }
  const auto verify = run_tool("mw-prov", {"verify", "--json", "--db", db.string()});
  EXPECT_EQ(verify.exit_status, 0) << verify.out << verify.err;
  std::map<std::string, nlohmann::json> made_by;  // output path (relative to the tree) -> its verify entry
  for (const auto& e : nlohmann::json::parse(verify.out)) {
    const std::string path = fs::path(e["path"].get<std::string>()).lexically_relative(tree).string();
    EXPECT_EQ(e["state"], "unchanged") << path;
    made_by[path] = e;
  }

  // 1. Every rule of the chain: its outputs, each by a successful run of its tool.
  const std::vector<std::string> choices = {"static-test", "dynamic"}, sizes = {"150", "50"};
  const auto table3 = io::read_csv(tree / R / "table3.csv");
  std::vector<std::string> freqs;
  for (const auto& row : table3.rows) freqs.push_back(row[0]);
  ASSERT_FALSE(freqs.empty()) << "no frequency in " << R << "table3.csv";
  std::vector<std::pair<std::string, std::string>> outputs = {
      {C + "packing.h5", "mw-pack"},          {C + "packing-50.h5", "mw-pack"},
      {R + "packing.h5", "mw-pack"},          {R + "calibration.json", "mw-calibrate"},
      {C + "calibration-dynamic.json", "mw-calibrate"},
      {R + "table3.csv", "mw-table"},         {C + "waves-dynamic/table3.csv", "mw-table"},
      {C + "packing150.csv", "mw-table"},     {C + "upv150.csv", "mw-table"},
      {C + "upv150-cost.csv", "mw-table"},    {C + "table3-calibrations.csv", "mw-table"},
      {C + "table3-calibrations.png", "mw-table"}, {"report-quick/concrete-cube-150/index.html", "mw-report"}};
  for (const auto& f : freqs)
    for (const auto& [name, tool] : std::vector<std::pair<std::string, std::string>>{
             {R + "fem-" + f + "kHz.h5", "mw-fem"}, {R + "fem-early-" + f + "kHz.h5", "mw-fem"},
             {R + "dem-" + f + "kHz.h5", "mw-dem"}, {C + "waves-dynamic/dem-" + f + "kHz.h5", "mw-dem"},
             {C + "waves-dynamic/pcc-" + f + "kHz.csv", "mw-pcc"}, {C + "waves-dynamic/pcc-early-" + f + "kHz.csv", "mw-pcc"}})
      outputs.emplace_back(name, tool);
  for (const auto& c : choices)
    for (const auto& z : sizes) {
      for (const std::string k : {"p", "s"}) {
        for (const std::string ext : {".h5", ".csv", ".json"}) outputs.emplace_back(C + "upv" + z + "-" + k + "-" + c + ext, "mw-dem");
        for (const std::string noisy : {"", "-noisy"}) outputs.emplace_back(C + "upv" + z + "-" + k + noisy + "-" + c + ".png", "mw-upv");
      }
      for (const std::string noisy : {"", "-noisy"})
        for (const std::string pick : {"tp", "picks"}) outputs.emplace_back(C + "upv" + z + "-" + pick + noisy + "-" + c + ".json", "mw-upv");
    }
  for (const auto& [path, tool] : outputs) {
    const auto m = made_by.find(path);
    if (m == made_by.end()) {
      ADD_FAILURE() << path << ": not a recorded run's output (its rule did not run)";
      continue;
    }
    const auto& run = run_by_id[m->second["run"].get<int>()];
    EXPECT_EQ(run["tool"], tool) << path << " was made by run " << m->second["run"];
    EXPECT_EQ(run["exit_status"], 0) << path << " was made by a failed run " << m->second["run"];
  }

  // 2. The report: the tables and figures its spec lists, every figure decoded.
  const std::string spec = read_file(tree / "pipeline/concrete-cube/report-150.toml");
  const auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = 0; (at = spec.find("\n" + what + " = \"", at)) != std::string::npos; ++at) ++n;
    return n;
  };
  const std::size_t tables = count("table"), figures = count("figure");
  EXPECT_GT(tables, 0u);
  EXPECT_GT(figures, 0u);
  const auto report = run_command(source / "scripts/check-report",
                                  {(tree / "report-quick/concrete-cube-150/index.html").string(), std::to_string(tables),
                                   std::to_string(figures)});
  EXPECT_EQ(report.exit_status, 0) << report.out << report.err;
  EXPECT_EQ(report.out.rfind("report OK: " + std::to_string(tables) + " tables", 0), 0u) << report.out;
  EXPECT_NE(report.out.find(", 0 broken"), std::string::npos) << report.out;

  // 3. upv150.csv against its sources, each file read here, not through the rule's row list.
  const auto upv = io::read_csv(tree / C / "upv150.csv");
  const fs::path upv_toml = tree / "lab-data/concrete-cube/upv.toml", static_toml = tree / "lab-data/concrete-cube/static-test.toml";
  const std::string measured = "measured (upv.toml; static-test.toml)";
  EXPECT_EQ(cell(upv, measured, "t_p_us"), printed(quantity_entry(upv_toml, "t_p"))) << measured;
  EXPECT_EQ(cell(upv, measured, "t_s_us"), printed(quantity_entry(upv_toml, "t_s"))) << measured;
  EXPECT_EQ(cell(upv, measured, "path_mm"), printed(quantity_entry(upv_toml, "path"))) << measured;
  // Its dynamic moduli from the UPV test, its static ones from the compression tests: not the same.
  const auto lab_upv = json_file(tree / R / "upv.json");
  EXPECT_EQ(cell(upv, measured, "E_d_GPa"), printed(lab_upv["E_d_GPa"].get<double>())) << measured;
  EXPECT_EQ(cell(upv, measured, "nu_d"), printed(lab_upv["nu_d"].get<double>())) << measured;
  EXPECT_EQ(cell(upv, measured, "E_glob_GPa"), printed(quantity_entry(static_toml, "E_st_measured"))) << measured;
  EXPECT_EQ(cell(upv, measured, "nu_glob"), printed(quantity_entry(static_toml, "nu_st"))) << measured;
  EXPECT_NE(cell(upv, measured, "E_glob_GPa"), cell(upv, measured, "E_d_GPa")) << measured;
  EXPECT_EQ(upv.rows.size(), 1 + choices.size() * sizes.size() * 2) << "upv150.csv: the measured row and each DEM row";
  const std::map<std::string, fs::path> material = {{"static-test", tree / R / "calibration.json"},
                                                    {"dynamic", tree / C / "calibration-dynamic.json"}};
  for (const auto& c : choices) {
    const auto m = json_file(material.at(c));
    for (const auto& z : sizes)
      for (const std::string noisy : {"", "-noisy"}) {
        const auto picks = json_file(tree / C / ("upv" + z + "-picks" + noisy + "-" + c + ".json"));
        const std::string row = "DEM " + label(picks["path_mm"].get<double>()) + " mm; calibrated to " + c +
                                (noisy.empty() ? "" : "; + 40 dB noise; AIC");
        SCOPED_TRACE(row);
        // The picks' E_d, nu_d differ from the calibration's E_glob, nu_glob in the printed digits,
        // so that the columns show which file they came from.
        EXPECT_NE(printed(m["E_glob_GPa"].get<double>()), printed(picks["E_d_GPa"].get<double>()));
        EXPECT_NE(printed(m["nu_glob"].get<double>()), printed(picks["nu_d"].get<double>()));
        EXPECT_EQ(cell(upv, row, "E_glob_GPa"), printed(m["E_glob_GPa"].get<double>())) << "E_glob_GPa is not " << material.at(c);
        EXPECT_EQ(cell(upv, row, "nu_glob"), printed(m["nu_glob"].get<double>())) << "nu_glob is not " << material.at(c);
        EXPECT_EQ(cell(upv, row, "E_d_GPa"), printed(picks["E_d_GPa"].get<double>()));
        EXPECT_EQ(cell(upv, row, "nu_d"), printed(picks["nu_d"].get<double>()));
        EXPECT_EQ(cell(upv, row, "t_p_us"), printed(picks["t_p_us"].get<double>()));
        EXPECT_EQ(cell(upv, row, "t_s_us"), printed(picks["t_s_us"].get<double>()));
        EXPECT_EQ(cell(upv, row, "path_mm"), printed(picks["path_mm"].get<double>()));
      }
  }

  // table3-calibrations.csv: each calibration's four PCC columns, its own Table 3's.
  const auto both = io::read_csv(tree / C / "table3-calibrations.csv");
  const std::map<std::string, io::CsvTable> own = {{"static-test", table3},
                                                   {"dynamic", io::read_csv(tree / C / "waves-dynamic/table3.csv")}};
  EXPECT_EQ(both.rows.size(), freqs.size());
  for (const auto& f : freqs)
    for (const auto& c : choices)
      for (const std::string k : {"first_50us_pcc_signals", "first_50us_pcc_envelopes", "pcc_signals", "pcc_envelopes"})
        EXPECT_EQ(cell(both, f, c + "_" + k), cell(own.at(c), f, "dem_vs_fem_" + k)) << f << " kHz, " << c << "_" << k;
}
