// mw-prov merge on databases made by real tool runs (one database per run, as a Slurm step
// leaves them): every run, input, output and metric of the sources is in the target once;
// merging again adds nothing; a bad source is one line, exit 1, and no target.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <nlohmann/json.hpp>

#include "support/run_tool.hpp"

using namespace mesowave::test;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

std::int64_t count(const fs::path& db, const std::string& sql) {
  sqlite3* raw = nullptr;
  sqlite3_open_v2(db.c_str(), &raw, SQLITE_OPEN_READONLY, nullptr);
  sqlite3_stmt* stmt = nullptr;
  sqlite3_prepare_v2(raw, sql.c_str(), -1, &stmt, nullptr);
  std::int64_t n = -1;
  if (sqlite3_step(stmt) == SQLITE_ROW) n = sqlite3_column_int64(stmt, 0);
  sqlite3_finalize(stmt);
  sqlite3_close(raw);
  return n;
}

const char* const kTables[] = {"runs", "files WHERE role = 'input'", "files WHERE role = 'output'", "metrics"};

}  // namespace

TEST(ProvenanceMergeCli, StepDatabasesOfRealRunsMergeWithNothingLostOrDoubled) {
  TempDir dir;
  write_file(dir / "upv.toml", "[path]\nvalue = 150\nunit = \"mm\"\nsource = \"assumed\"\ncite = \"a test fixture\"\n");
  std::vector<fs::path> steps;
  for (int i = 0; i < 4; ++i) {  // four steps: mw-upv runs reading a lab-data file, one of them failing
    steps.push_back(dir / ("step-" + std::to_string(i) + ".sqlite"));
    const std::string t_s = i == 3 ? "30" : std::to_string(55 + i);
    const auto r = run_tool("mw-upv", {"--from", (dir / "upv.toml").string(), "--t-p-us", "35", "--t-s-us", t_s,
                                       "--density-kg-m3", "2129.56", "--out", (dir / ("upv-" + std::to_string(i) + ".json")).string(),
                                       "--db", steps.back().string()});
    ASSERT_EQ(r.exit_status, i == 3 ? 1 : 0) << r.err;
  }
  std::vector<std::int64_t> sums(std::size(kTables), 0);
  for (const auto& s : steps)
    for (std::size_t t = 0; t < std::size(kTables); ++t) sums[t] += count(s, std::string("SELECT count(*) FROM ") + kTables[t]);
  EXPECT_EQ(sums[0], 4);
  EXPECT_EQ(sums[1], 4);  // each read its --from file (the failed one too)
  EXPECT_EQ(sums[2], 3);  // the failed run wrote nothing

  const auto into = dir / "main.sqlite";
  std::vector<std::string> args = {"merge", "--into", into.string(), "--json"};
  for (const auto& s : steps) args.push_back(s.string());
  const auto first = run_tool("mw-prov", args);
  ASSERT_EQ(first.exit_status, 0) << first.err;
  const auto answer = json::parse(first.out);
  EXPECT_EQ(answer["runs"]["after"], 4);
  for (std::size_t t = 0; t < std::size(kTables); ++t)
    EXPECT_EQ(count(into, std::string("SELECT count(*) FROM ") + kTables[t]), sums[t]) << kTables[t];
  EXPECT_EQ(count(into, "SELECT count(*) FROM runs WHERE exit_status = 1"), 1);

  const auto again = run_tool("mw-prov", args);
  ASSERT_EQ(again.exit_status, 0) << again.err;
  const auto second = json::parse(again.out);
  for (const auto& s : second["sources"]) EXPECT_EQ(s["runs_added"], 0) << s["path"];
  for (std::size_t t = 0; t < std::size(kTables); ++t)
    EXPECT_EQ(count(into, std::string("SELECT count(*) FROM ") + kTables[t]), sums[t]) << kTables[t];
  // The merged database answers as one: each output's run, found by its hash.
  const auto verify = run_tool("mw-prov", {"--db", into.string(), "verify", "--json"});
  ASSERT_EQ(verify.exit_status, 0) << verify.err;
  EXPECT_EQ(json::parse(verify.out).size(), 3u);
}

TEST(ProvenanceMergeCli, ABadSourceIsOneLineAndNoTarget) {
  TempDir dir;
  write_file(dir / "junk.sqlite", std::string(4096, 'x'));
  const auto r = run_tool("mw-prov", {"merge", "--into", (dir / "main.sqlite").string(), (dir / "junk.sqlite").string()});
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("junk.sqlite"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_FALSE(fs::exists(dir / "main.sqlite"));
}
