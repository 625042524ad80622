#pragma once
// Merging provenance databases: the runs of several databases (one per Slurm job, say,
// each written on the node that ran the job) added to one, so that the provenance of a
// pipeline run across hosts is one database again without SQLite ever being shared
// between hosts (its locking is not safe on storage shared between hosts; docs/slurm.md).
//
// A run has no name but its record, so a run of a source is "already there" when the
// target holds a run with every column but `id` equal (tool, version, binary hash, argv,
// parameters, cwd, host, start and end to the millisecond, exit status, error, wall and
// CPU seconds as the same doubles, peak memory); its files and metrics must then be
// equal too, or the merge is refused (two different records claiming one run). So
// merging a database twice, or two databases holding copies of the same runs, adds each
// run once, and nothing a source holds is left out.
//
// The new runs get new ids in the order they ended (then started, then source order,
// then their id in the source): the order in which they would have recorded themselves
// into one database (a tool records its run as it ends), which is what the queries take
// id order to mean (the producer of a file a run read has a smaller id). Their files and
// metrics follow them in their source order (rowid), re-keyed to the new ids.
//
// Whole or nothing: every source is opened and read before the target is touched (a
// missing, corrupt or foreign source changes nothing, and no target is created), and
// all additions are one transaction. The sources are read only; an empty file (a database
// no run was recorded in) is a source without runs.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace mesowave::prov {

/// What one source brought.
struct MergeSourceCount {
  std::string path;
  std::int64_t runs = 0;           ///< runs in the source
  std::int64_t runs_added = 0;     ///< new to the target (added, with their files and metrics)
  std::int64_t runs_present = 0;   ///< already in the target (or in an earlier source), left as they are
  std::int64_t files_added = 0;    ///< rows of `files` added
  std::int64_t metrics_added = 0;  ///< rows of `metrics` added
};

struct MergeResult {
  std::vector<MergeSourceCount> sources;
  std::int64_t runs_before = 0, runs_after = 0;  ///< rows of `runs` in the target
  std::int64_t files_before = 0, files_after = 0;
  std::int64_t metrics_before = 0, metrics_after = 0;
};

/// Adds to the database `into` (created if absent) every run of `sources` it does not hold
/// yet. InputError for a source that is missing, not a mesowave database, of another schema
/// version, the target itself, or that holds a run whose record matches one already there
/// but whose files or metrics differ; nothing is changed then.
MergeResult merge_databases(const std::filesystem::path& into, const std::vector<std::filesystem::path>& sources);

}  // namespace mesowave::prov
