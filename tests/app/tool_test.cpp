// app/tool, called directly (tests/cli runs the built tools): the exit codes, whole-or-nothing
// outputs, the --from contract on the reader's side (an entry no option takes is an error) and
// on the producer's (declare_products).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/prov/database.hpp"
#include "mesowave/prov/queries.hpp"
#include "mesowave/prov/report.hpp"
#include "mesowave/prov/run_record.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using mesowave::test::TempDir;
using mesowave::test::write_file;
namespace fs = std::filesystem;

namespace {

// Runs a tool with one option --t-p-us whose body writes `out` and then throws `failure` (if any).
int run_tool_body(std::vector<std::string> args, const fs::path& out, double* seen, const char* failure = nullptr) {
  app::Tool tool("mw-probe", "A probe of app::Tool.");
  double t_p_us = 0;
  tool.cli().add_option("--t-p-us", t_p_us, "t_p [us]");
  args.insert(args.begin(), "mw-probe");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return tool.run(int(argv.size()), argv.data(), [&](app::Run& run) {
    *seen = t_p_us;
    run.write_text(out, "result\n");
    if (failure) throw InputError(failure);
  });
}

TEST(Tool, ExitZeroWritesTheOutputAnInputErrorExitsOneAndWritesNothing) {
  TempDir dir;
  double seen = 0;
  EXPECT_EQ(run_tool_body({"--t-p-us", "35"}, dir / "a.txt", &seen), 0);
  EXPECT_EQ(seen, 35.0);
  EXPECT_TRUE(fs::exists(dir / "a.txt"));
  EXPECT_EQ(run_tool_body({"--t-p-us", "35"}, dir / "b.txt", &seen, "t_p (35 us) is wrong"), 1);
  EXPECT_FALSE(fs::exists(dir / "b.txt"));  // staged, never renamed into place
  EXPECT_EQ(run_tool_body({"--no-such-option"}, dir / "c.txt", &seen), 1);
}

TEST(Tool, FromFillsOptionsAndAnEntryNoOptionTakesIsAnError) {
  TempDir dir;
  write_file(dir / "upv.toml", "[t_p]\nvalue = 35.0\nunit = \"us\"\nsource = \"paper\"\ncite = \"Section 3.2\"\n");
  double seen = 0;
  EXPECT_EQ(run_tool_body({"--from", (dir / "upv.toml").string()}, dir / "a.txt", &seen), 0);
  EXPECT_EQ(seen, 35.0);
  EXPECT_EQ(run_tool_body({"--from", (dir / "upv.toml").string(), "--t-p-us", "36"}, dir / "b.txt", &seen), 0);
  EXPECT_EQ(seen, 36.0);  // the command line beats the file
  write_file(dir / "renamed.json", R"({"t_p_ms": 0.035})");
  EXPECT_EQ(run_tool_body({"--from", (dir / "renamed.json").string()}, dir / "c.txt", &seen), 1);
  EXPECT_FALSE(fs::exists(dir / "c.txt"));
  write_file(dir / "declared.json", R"({"t_p_us": 35, "v_p_m_s": 4285.7, "foreign_keys": ["v_p_m_s"]})");
  EXPECT_EQ(run_tool_body({"--from", (dir / "declared.json").string()}, dir / "d.txt", &seen), 0);
}

// Run::origin agrees with the value the option got: the command line beats the files, the last
// --from file named wins, and the record names the file, the entry and the file's SHA-256.
TEST(Tool, OriginSaysWhichFileOrTheCommandLineGaveAnOption) {
  TempDir dir;
  const std::string paper = (dir / "paper.toml").string(), lab = (dir / "lab.json").string();
  write_file(paper, "[t_p]\nvalue = 35.0\nunit = \"us\"\nsource = \"paper\"\ncite = \"Section 3.2\"\n");
  write_file(lab, R"({"t_p_us": 34.5})");
  const auto origin_of = [&](std::vector<std::string> args, double* seen) {
    app::Tool tool("mw-probe", "A probe of app::Tool.");
    double t_p_us = 0, t_s_us = 55.1;
    tool.cli().add_option("--t-p-us", t_p_us, "t_p [us]");
    tool.cli().add_option("--t-s-us", t_s_us, "t_s [us]");
    args.insert(args.begin(), "mw-probe");
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    nlohmann::ordered_json o;
    EXPECT_EQ(tool.run(int(argv.size()), argv.data(), [&](app::Run& run) {
      *seen = t_p_us;
      o = {{"t_p", run.origin("--t-p-us")}, {"t_s", run.origin("--t-s-us")}};
    }), 0);
    return o;
  };
  double seen = 0;
  auto o = origin_of({"--from", paper, "--from", lab}, &seen);
  EXPECT_EQ(seen, 34.5);
  EXPECT_EQ(o["t_p"]["file"], lab);
  EXPECT_EQ(o["t_p"]["entry"], "t_p_us");
  EXPECT_EQ(o["t_p"]["source"], "output");
  EXPECT_EQ(o["t_p"]["sha256"], prov::describe_file(lab).sha256);
  EXPECT_FALSE(o["t_p"].contains("cite"));  // a tool's JSON has none but its own name
  EXPECT_EQ(o["t_s"]["given"], "default");
  o = origin_of({"--from", lab, "--from", paper}, &seen);
  EXPECT_EQ(seen, 35.0);
  EXPECT_EQ(o["t_p"]["file"], paper);
  EXPECT_EQ(o["t_p"]["entry"], "t_p");
  EXPECT_EQ(o["t_p"]["cite"], "Section 3.2");
  o = origin_of({"--from", paper, "--t-p-us=36", "--t-s-us", "55.2"}, &seen);
  EXPECT_EQ(seen, 36.0);
  EXPECT_EQ(o["t_p"]["given"], "command line");
  EXPECT_FALSE(o["t_p"].contains("file"));
  EXPECT_EQ(o["t_s"]["given"], "command line");
}

TEST(Tool, DeclareProductsMakesEveryOtherEntryForeign) {
  nlohmann::ordered_json j = {{"path_mm", 150.0}, {"E_d_GPa", 36.67}, {"method", "Eq. (9)"}};
  app::declare_products(j, {"E_d_GPa"});
  EXPECT_EQ(j["foreign_keys"], nlohmann::ordered_json::array({"path_mm", "method"}));
  app::declare_products(j, {"E_d_GPa", "method"});  // declared again: the list is replaced, not grown
  EXPECT_EQ(j["foreign_keys"], nlohmann::ordered_json::array({"path_mm"}));
  EXPECT_THROW(app::declare_products(j, {"E_st_GPa"}), std::logic_error);
}

}  // namespace

// A wall time means little without the threads that earned it: a run whose body chose its threads
// (core/threads: use_threads) records the count as the metric `threads`, and mw-prov show prints it
// on the cost line.
TEST(Tool, ARunThatChoseItsThreadsRecordsTheCount) {
  TempDir dir;
  const std::string db_path = (dir / "p.sqlite").string();
  app::Tool tool("mw-probe", "A probe of app::Tool.");
  std::vector<std::string> args = {"mw-probe", "--db", db_path};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  EXPECT_EQ(tool.run(int(argv.size()), argv.data(), [](app::Run&) { EXPECT_EQ(use_threads(2).count, 2); }), 0);
  const auto db = prov::Database::open(db_path);
  const auto runs = prov::list_runs(db);
  ASSERT_EQ(runs.size(), 1u);
  const prov::RunRecord r = prov::load_run(db, runs[0].id);
  const auto m = std::find_if(r.metrics.begin(), r.metrics.end(), [](const auto& x) { return x.name == "threads"; });
  ASSERT_NE(m, r.metrics.end());
  EXPECT_EQ(m->value, 2.0);
  EXPECT_NE(prov::run_text(runs[0].id, r, dir.path()).find("MiB, 2 threads\n"), std::string::npos);
}
