// Lineage and staleness on a small hand-made history:
//   lab.toml -> run A -> mid.json -> run B -> out.csv
#include <gtest/gtest.h>

#include "mesowave/io/sha256.hpp"
#include "mesowave/prov/queries.hpp"
#include "mesowave/prov/report.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

namespace {

std::int64_t record(const prov::Database& db, const std::string& tool, std::vector<fs::path> in, std::vector<fs::path> out) {
  prov::RunRecord r;
  r.tool = tool;
  r.version = "v";
  r.binary_sha256 = r.cwd = r.host = r.started_at = r.ended_at = "-";
  for (auto& p : in) r.inputs.push_back(prov::describe_file(p));
  for (auto& p : out) r.outputs.push_back(prov::describe_file(p));
  return prov::record_run(db, r);
}

struct History : ::testing::Test {
  test::TempDir dir;
  prov::Database db = prov::Database::open(dir / "p.sqlite");
  std::int64_t a = 0, b = 0;
  void SetUp() override {
    test::write_file(dir / "lab.toml", "[x]\nvalue = 1\n");
    test::write_file(dir / "mid.json", "{\"x\": 1}");
    a = record(db, "mw-a", {dir / "lab.toml"}, {dir / "mid.json"});
    test::write_file(dir / "out.csv", "x\n1\n");
    b = record(db, "mw-b", {dir / "mid.json"}, {dir / "out.csv"});
  }
};

}  // namespace

TEST_F(History, LineageReachesTheLabDataWithHashes) {
  const auto root = prov::lineage(db, (dir / "out.csv").string());
  ASSERT_TRUE(root.producer);
  EXPECT_EQ(root.producer->id, b);
  ASSERT_EQ(root.inputs.size(), 1u);
  const auto& mid = root.inputs[0];
  ASSERT_TRUE(mid.producer);
  EXPECT_EQ(mid.producer->id, a);
  ASSERT_EQ(mid.inputs.size(), 1u);
  EXPECT_FALSE(mid.inputs[0].producer);  // a source file
  EXPECT_EQ(mid.inputs[0].sha256, io::sha256_hex("[x]\nvalue = 1\n"));
  const auto text = prov::lineage_text(root, dir.path());
  EXPECT_NE(text.find("lab.toml"), std::string::npos);
  EXPECT_NE(text.find("<- run " + std::to_string(a) + " mw-a"), std::string::npos);
  const auto dot = prov::lineage_dot(root, dir.path());
  EXPECT_EQ(dot.rfind("digraph lineage {", 0), 0u);
  EXPECT_NE(dot.find("\"r_" + std::to_string(b) + "\""), std::string::npos);
}

TEST_F(History, NothingIsStaleUntilAnInputChanges) {
  EXPECT_TRUE(prov::stale_inputs(db).empty());
  test::write_file(dir / "lab.toml", "[x]\nvalue = 2\n");
  const auto stale = prov::stale_inputs(db);
  ASSERT_EQ(stale.size(), 1u);
  EXPECT_EQ(stale[0].run.id, a);
  EXPECT_EQ(fs::path(stale[0].input_path).filename(), "lab.toml");
  EXPECT_FALSE(stale[0].current_sha256.empty());
  // Removing an input is stale too, reported as missing.
  fs::remove(dir / "mid.json");
  bool missing = false;
  for (const auto& s : prov::stale_inputs(db)) missing |= s.current_sha256.empty() && s.run.id == b;
  EXPECT_TRUE(missing);
}

TEST_F(History, LineageFlagsAFileChangedSinceItWasMade) {
  test::write_file(dir / "mid.json", "{\"x\": 3}");
  const auto root = prov::lineage(db, (dir / "out.csv").string());
  ASSERT_EQ(root.inputs.size(), 1u);
  EXPECT_NE(root.inputs[0].current_sha256, root.inputs[0].sha256);
  EXPECT_NE(prov::lineage_text(root, dir.path()).find("CHANGED since"), std::string::npos);
}

TEST_F(History, ANewerRunOfTheSameOutputIsTheLiveOne) {
  test::write_file(dir / "lab2.toml", "[x]\nvalue = 5\n");
  const auto c = record(db, "mw-a", {dir / "lab2.toml"}, {dir / "mid.json"});
  test::write_file(dir / "lab.toml", "changed");  // only run a read it; a is no longer live
  for (const auto& s : prov::stale_inputs(db)) EXPECT_NE(s.run.id, a);
  EXPECT_EQ(prov::lineage(db, (dir / "mid.json").string()).producer->id, c);
}
