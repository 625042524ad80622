// The provenance database: recording, reading back, and refusing files it must not touch.
#include <gtest/gtest.h>

#include "mesowave/core/error.hpp"
#include "mesowave/prov/database.hpp"
#include "mesowave/prov/queries.hpp"
#include "mesowave/prov/run_record.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

namespace {

prov::RunRecord sample_run(const std::string& tool) {
  prov::RunRecord r;
  r.tool = tool;
  r.version = "v-test";
  r.binary_sha256 = "00";
  r.argv = {tool, "--x", "it's; DROP TABLE runs; --"};  // bound, never pasted into SQL
  r.params = {{"x", 1.5}};
  r.cwd = "/tmp";
  r.host = "h";
  r.started_at = r.ended_at = "2026-01-01T00:00:00.000Z";
  r.wall_s = 0.5;
  r.cpu_s = 0.25;
  r.peak_rss_kib = 1024;
  r.metrics = {{"E_d", 36.67, "GPa"}};
  return r;
}

}  // namespace

TEST(ProvenanceDatabase, RecordsAndReadsBackARun) {
  test::TempDir dir;
  test::write_file(dir / "in.txt", "abc");
  auto db = prov::Database::open(dir / "p.sqlite");
  auto run = sample_run("mw-upv");
  run.inputs = {prov::describe_file(dir / "in.txt")};
  const auto id = prov::record_run(db, run);
  const auto back = prov::load_run(db, id);
  EXPECT_EQ(back.argv, run.argv);
  EXPECT_EQ(back.params, run.params);
  ASSERT_EQ(back.inputs.size(), 1u);
  EXPECT_EQ(back.inputs[0].sha256, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(back.inputs[0].size_bytes, 3);
  ASSERT_EQ(back.metrics.size(), 1u);
  EXPECT_DOUBLE_EQ(back.metrics[0].value, 36.67);
  EXPECT_EQ(prov::list_runs(db).size(), 1u);
  EXPECT_THROW(prov::load_run(db, id + 1), InputError);
}

TEST(ProvenanceDatabase, UsesWalMode) {
  test::TempDir dir;
  auto db = prov::Database::open(dir / "p.sqlite");
  auto mode = db.prepare("PRAGMA journal_mode");
  ASSERT_TRUE(mode.step());
  EXPECT_EQ(mode.text(0), "wal");
}

TEST(ProvenanceDatabase, RefusesMissingDirectory) {
  test::TempDir dir;
  EXPECT_THROW(prov::Database::open(dir / "nowhere/p.sqlite"), InputError);
  EXPECT_FALSE(fs::exists(dir / "nowhere"));
}

TEST(ProvenanceDatabase, RefusesACorruptFileAndLeavesItAlone) {
  test::TempDir dir;
  const std::string junk(4096, 'x');
  test::write_file(dir / "p.sqlite", junk);
  EXPECT_THROW(prov::Database::open(dir / "p.sqlite"), InputError);
  EXPECT_EQ(test::read_file(dir / "p.sqlite"), junk);
}

TEST(ProvenanceDatabase, RefusesAnotherSqliteDatabase) {
  test::TempDir dir;
  {
    sqlite3* raw = nullptr;
    sqlite3_open((dir / "other.sqlite").c_str(), &raw);
    sqlite3_exec(raw, "CREATE TABLE t(x)", nullptr, nullptr, nullptr);
    sqlite3_close(raw);
  }
  EXPECT_THROW(prov::Database::open(dir / "other.sqlite"), InputError);
}

TEST(ProvenanceDatabase, ReadOnlyModeNeverCreates) {
  test::TempDir dir;
  EXPECT_THROW(prov::Database::open(dir / "p.sqlite", prov::Database::Mode::ReadOnly), InputError);
  EXPECT_FALSE(fs::exists(dir / "p.sqlite"));
}
