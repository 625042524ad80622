// Merging provenance databases (prov/merge.hpp): the same runs recorded into one database
// directly and recorded into one database per job then merged give the same database, run
// for run; merging again adds nothing; a bad source or a conflicting record changes nothing.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "mesowave/core/error.hpp"
#include "mesowave/prov/database.hpp"
#include "mesowave/prov/merge.hpp"
#include "mesowave/prov/queries.hpp"
#include "mesowave/prov/run_record.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

namespace {

std::int64_t rows(const prov::Database& db, const std::string& table) {
  auto count = db.prepare("SELECT count(*) FROM " + table);
  count.step();
  return count.integer(0);
}

// A run that read `inputs` and wrote `outputs` (files that exist in `dir`), ending at second `end_s`.
prov::RunRecord job_run(const std::string& tool, const test::TempDir& dir, const std::vector<std::string>& inputs,
                        const std::vector<std::string>& outputs, int end_s) {
  prov::RunRecord r;
  r.tool = tool;
  r.version = "v-test";
  r.binary_sha256 = std::string(64, 'a');
  r.argv = {tool, "--end", std::to_string(end_s)};
  r.params = {{"end", end_s}, {"frequency-kHz", 100.0 + end_s}};
  r.cwd = dir.path().string();
  r.host = "node" + std::to_string(end_s % 3);
  r.started_at = "2026-01-01T00:00:" + std::string(end_s < 10 ? "0" : "") + std::to_string(end_s) + ".000Z";
  r.ended_at = "2026-01-01T00:00:" + std::string(end_s < 10 ? "0" : "") + std::to_string(end_s) + ".500Z";
  r.wall_s = 0.5 + 1e-9 * end_s;
  r.cpu_s = 0.25;
  r.peak_rss_kib = 1000 + end_s;
  for (const auto& f : inputs) r.inputs.push_back(prov::describe_file(dir / f));
  for (const auto& f : outputs) r.outputs.push_back(prov::describe_file(dir / f));
  r.metrics = {{"E_d", 36.0 + end_s, "GPa"}, {"steps_per_s", 1e4 / end_s, ""}};
  if (end_s == 5) {
    r.exit_status = 1;  // a failed run is provenance too
    r.error = "t_s (30 us) is shorter than t_p";
    r.outputs.clear();
  }
  return r;
}

void expect_same_run(const prov::RunRecord& a, const prov::RunRecord& b, std::int64_t id) {
  SCOPED_TRACE("run " + std::to_string(id));
  EXPECT_EQ(a.tool, b.tool);
  EXPECT_EQ(a.argv, b.argv);
  EXPECT_EQ(a.params, b.params);
  EXPECT_EQ(a.host, b.host);
  EXPECT_EQ(a.started_at, b.started_at);
  EXPECT_EQ(a.ended_at, b.ended_at);
  EXPECT_EQ(a.exit_status, b.exit_status);
  EXPECT_EQ(a.error, b.error);
  EXPECT_EQ(a.wall_s, b.wall_s);  // the same double, not a near one
  EXPECT_EQ(a.peak_rss_kib, b.peak_rss_kib);
  ASSERT_EQ(a.inputs.size(), b.inputs.size());
  for (std::size_t i = 0; i < a.inputs.size(); ++i) {
    EXPECT_EQ(a.inputs[i].path, b.inputs[i].path);
    EXPECT_EQ(a.inputs[i].sha256, b.inputs[i].sha256);
  }
  ASSERT_EQ(a.outputs.size(), b.outputs.size());
  for (std::size_t i = 0; i < a.outputs.size(); ++i) EXPECT_EQ(a.outputs[i].sha256, b.outputs[i].sha256);
  ASSERT_EQ(a.metrics.size(), b.metrics.size());
  for (std::size_t i = 0; i < a.metrics.size(); ++i) {
    EXPECT_EQ(a.metrics[i].name, b.metrics[i].name);
    EXPECT_EQ(a.metrics[i].value, b.metrics[i].value);
  }
}

// A pipeline of six runs in three jobs, as the Slurm launcher leaves it: each job's
// database holds the runs merged before it started (its seed) and its own runs.
struct Jobs {
  test::TempDir dir;
  std::vector<prov::RunRecord> runs;  // in the order they ended
  std::vector<fs::path> job_dbs;
  fs::path direct;  // the same runs recorded into one database as they ended

  Jobs() {
    test::write_file(dir / "lab.toml", "t_p = 35\n");
    test::write_file(dir / "a.json", "{\"E_d_GPa\": 36.7}\n");
    test::write_file(dir / "b.h5", "signals");
    test::write_file(dir / "c.csv", "pcc\n0.98\n");
    test::write_file(dir / "d.csv", "summary\n");
    runs = {job_run("mw-upv", dir, {"lab.toml"}, {"a.json"}, 1), job_run("mw-dem", dir, {"a.json"}, {"b.h5"}, 2),
            job_run("mw-fem", dir, {"lab.toml"}, {}, 3),          job_run("mw-pcc", dir, {"b.h5"}, {"c.csv"}, 4),
            job_run("mw-upv", dir, {"lab.toml"}, {}, 5),          job_run("mw-table", dir, {"c.csv", "a.json"}, {"d.csv"}, 6)};
    direct = dir / "direct.sqlite";
    auto one = prov::Database::open(direct);
    for (const auto& r : runs) prov::record_run(one, r);
    // Job 1: runs 1 and 3 (no seed); job 2: run 2 seeded with job 1's; job 3: runs 4-6 seeded with 1-3.
    const std::vector<std::vector<int>> own = {{0, 2}, {1}, {3, 4, 5}};
    const std::vector<std::vector<int>> seed = {{}, {0, 2}, {0, 2, 1}};
    for (std::size_t j = 0; j < own.size(); ++j) {
      job_dbs.push_back(dir / ("job-" + std::to_string(j + 1) + ".sqlite"));
      auto db = prov::Database::open(job_dbs.back());
      for (int i : seed[j]) prov::record_run(db, runs[std::size_t(i)]);
      for (int i : own[j]) prov::record_run(db, runs[std::size_t(i)]);
    }
  }
};

}  // namespace

TEST(ProvenanceMerge, JobDatabasesMergeIntoTheDatabaseOneWouldHaveRecorded) {
  Jobs jobs;
  const auto merged_path = jobs.dir / "merged.sqlite";
  // Sources in an order other than the runs' (a shell glob's, say): the ids follow the ends.
  const auto result = prov::merge_databases(merged_path, {jobs.job_dbs[2], jobs.job_dbs[0], jobs.job_dbs[1]});
  ASSERT_EQ(result.sources.size(), 3u);
  EXPECT_EQ(result.sources[0].runs, 6);  // job 3: three seeded, three its own
  EXPECT_EQ(result.sources[0].runs_added, 6);
  EXPECT_EQ(result.sources[1].runs, 2);          // job 1
  EXPECT_EQ(result.sources[1].runs_present, 2);  // the same records as job 3's seed
  EXPECT_EQ(result.sources[2].runs, 3);          // job 2: two seeded, one its own
  EXPECT_EQ(result.sources[2].runs_present, 3);
  EXPECT_EQ(result.runs_before, 0);
  EXPECT_EQ(result.runs_after, 6);

  const auto direct = prov::Database::open(jobs.direct, prov::Database::Mode::ReadOnly);
  const auto merged = prov::Database::open(merged_path, prov::Database::Mode::ReadOnly);
  for (const char* table : {"runs", "files", "metrics"}) EXPECT_EQ(rows(merged, table), rows(direct, table)) << table;
  // Sums over the records made: 7 input and 4 output rows, 12 metrics.
  EXPECT_EQ(rows(merged, "files WHERE role = 'input'"), 7);
  EXPECT_EQ(rows(merged, "files WHERE role = 'output'"), 4);
  EXPECT_EQ(rows(merged, "metrics"), 12);
  for (std::int64_t id = 1; id <= 6; ++id) expect_same_run(prov::load_run(merged, id), prov::load_run(direct, id), id);
  // Foreign keys hold: every file and metric row belongs to a run.
  EXPECT_EQ(rows(merged, "files WHERE run_id NOT IN (SELECT id FROM runs)"), 0);
  EXPECT_EQ(rows(merged, "metrics WHERE run_id NOT IN (SELECT id FROM runs)"), 0);
  // The lineage of the last output crosses the three jobs as in the direct database.
  const auto tree = prov::lineage(merged, (jobs.dir / "d.csv").string());
  ASSERT_TRUE(tree.producer);
  EXPECT_EQ(tree.producer->id, 6);
  ASSERT_EQ(tree.inputs.size(), 2u);
  ASSERT_TRUE(tree.inputs[0].producer);
  EXPECT_EQ(tree.inputs[0].producer->tool, "mw-pcc");
  ASSERT_EQ(tree.inputs[0].inputs.size(), 1u);
  ASSERT_TRUE(tree.inputs[0].inputs[0].producer);
  EXPECT_EQ(tree.inputs[0].inputs[0].producer->tool, "mw-dem");
}

TEST(ProvenanceMerge, MergingAgainAddsNothing) {
  Jobs jobs;
  const auto merged_path = jobs.dir / "merged.sqlite";
  prov::merge_databases(merged_path, jobs.job_dbs);
  const auto again = prov::merge_databases(merged_path, jobs.job_dbs);
  EXPECT_EQ(again.runs_before, 6);
  EXPECT_EQ(again.runs_after, 6);
  EXPECT_EQ(again.files_after, again.files_before);
  EXPECT_EQ(again.metrics_after, again.metrics_before);
  for (const auto& s : again.sources) {
    EXPECT_EQ(s.runs_added, 0) << s.path;
    EXPECT_EQ(s.runs_present, s.runs) << s.path;
  }
  // Into a database that already holds some of them (the direct one): nothing doubled either.
  const auto into_direct = prov::merge_databases(jobs.direct, jobs.job_dbs);
  EXPECT_EQ(into_direct.runs_after, 6);
  EXPECT_EQ(into_direct.files_after, into_direct.files_before);
}

TEST(ProvenanceMerge, NewRunsFollowTheOnesAlreadyThere) {
  Jobs jobs;
  const auto merged_path = jobs.dir / "merged.sqlite";
  prov::merge_databases(merged_path, {jobs.job_dbs[0]});  // runs 1 and 3
  const auto result = prov::merge_databases(merged_path, {jobs.job_dbs[2]});
  EXPECT_EQ(result.sources[0].runs_added, 4);
  EXPECT_EQ(result.sources[0].runs_present, 2);
  EXPECT_EQ(result.sources[0].files_added, 8);  // runs 2, 4, 5, 6: 1+1, 1+1, 1+0, 2+1
  EXPECT_EQ(result.sources[0].metrics_added, 8);
  const auto merged = prov::Database::open(merged_path, prov::Database::Mode::ReadOnly);
  const std::vector<std::string> order = {"mw-upv", "mw-fem", "mw-dem", "mw-pcc", "mw-upv", "mw-table"};
  for (std::int64_t id = 1; id <= 6; ++id) EXPECT_EQ(prov::load_run(merged, id).tool, order[std::size_t(id - 1)]);
}

TEST(ProvenanceMerge, AConflictingRecordChangesNothing) {
  Jobs jobs;
  const auto merged_path = jobs.dir / "merged.sqlite";
  prov::merge_databases(merged_path, {jobs.job_dbs[0]});
  // A source claiming run 1's record with another metric value.
  auto forged = jobs.runs[0];
  forged.metrics[0].value += 1;
  const auto bad = jobs.dir / "forged.sqlite";
  {
    auto db = prov::Database::open(bad);
    prov::record_run(db, jobs.runs[1]);
    prov::record_run(db, forged);
  }
  EXPECT_THROW(prov::merge_databases(merged_path, {jobs.job_dbs[1], bad}), InputError);
  const auto merged = prov::Database::open(merged_path, prov::Database::Mode::ReadOnly);
  EXPECT_EQ(rows(merged, "runs"), 2);  // job 2's run was not added either: whole or nothing
  EXPECT_EQ(rows(merged, "metrics"), 4);
}

TEST(ProvenanceMerge, ABadSourceLeavesNoTarget) {
  Jobs jobs;
  const auto target = jobs.dir / "new.sqlite";
  test::write_file(jobs.dir / "junk.sqlite", std::string(4096, 'x'));
  EXPECT_THROW(prov::merge_databases(target, {jobs.job_dbs[0], jobs.dir / "junk.sqlite"}), InputError);
  EXPECT_THROW(prov::merge_databases(target, {jobs.job_dbs[0], jobs.dir / "absent.sqlite"}), InputError);
  EXPECT_FALSE(fs::exists(target));
  EXPECT_THROW(prov::merge_databases(jobs.job_dbs[0], {jobs.job_dbs[1], jobs.job_dbs[0]}), InputError);
  const auto job1 = prov::Database::open(jobs.job_dbs[0], prov::Database::Mode::ReadOnly);
  EXPECT_EQ(rows(job1, "runs"), 2);
}

TEST(ProvenanceMerge, AnEmptyFileIsASourceWithoutRuns) {
  Jobs jobs;
  test::write_file(jobs.dir / "empty.sqlite", "");  // a job whose tools recorded nothing
  const auto result = prov::merge_databases(jobs.dir / "merged.sqlite", {jobs.dir / "empty.sqlite", jobs.job_dbs[0]});
  EXPECT_EQ(result.sources[0].runs, 0);
  EXPECT_EQ(result.runs_after, 2);
}

TEST(ProvenanceMerge, ASourceBeingWrittenIsReadAsOneSnapshot) {
  // make -j: one step's database is merged into the main one while another merge seeds a step
  // from it. Each merge reads its source in one transaction, so it sees a run with all of its
  // files or not at all (read statement by statement, a run committed between the reading of
  // runs and of files had files without a run: the merge refused). At the end every run is
  // there once.
  Jobs jobs;
  const auto live = jobs.dir / "live.sqlite";
  { auto create = prov::Database::open(live); }
  constexpr int kRuns = 2000;
  std::atomic<bool> done = false;
  std::thread writer([&] {
    auto db = prov::Database::open(live);
    for (int i = 0; i < kRuns; ++i) {
      auto run = jobs.runs[std::size_t(i % 6)];
      run.argv.push_back(std::to_string(i));  // a run of its own
      prov::record_run(db, run);
    }
    done = true;
  });
  int merges = 0;
  std::string failure;
  for (; !done && failure.empty(); ++merges) {
    try {
      prov::merge_databases(jobs.dir / ("seed-" + std::to_string(merges % 4) + ".sqlite"), {live});
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  writer.join();
  EXPECT_EQ(failure, "") << "after " << merges << " merges";
  const auto last = prov::merge_databases(jobs.dir / "seed-0.sqlite", {live});
  EXPECT_EQ(last.runs_after, kRuns);
  const auto seed = prov::Database::open(jobs.dir / "seed-0.sqlite", prov::Database::Mode::ReadOnly);
  const auto source = prov::Database::open(live, prov::Database::Mode::ReadOnly);
  for (const char* table : {"files", "metrics"}) EXPECT_EQ(rows(seed, table), rows(source, table)) << table;
}
