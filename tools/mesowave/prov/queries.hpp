#pragma once
// Questions asked of the provenance database: which runs happened, what one
// run did, where a file came from (lineage), and which results were made from
// inputs that have changed since (stale).
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/prov/database.hpp"
#include "mesowave/prov/run_record.hpp"

namespace mesowave::prov {

struct RunSummary {
  std::int64_t id = 0;
  std::string tool;
  std::string version;
  std::string started_at;
  int exit_status = 0;
  double wall_s = 0;
  std::string error;
};

struct RunFilter {
  std::optional<std::string> tool;
  std::size_t limit = 0;  ///< newest `limit` runs; 0 for all
};

std::vector<RunSummary> list_runs(const Database& db, const RunFilter& filter = {});

/// The whole record of one run; InputError if there is no such run.
RunRecord load_run(const Database& db, std::int64_t id);

/// One file in a lineage: the version a run used (or, at the root, the file as
/// it is now), the run that produced that version, and that run's inputs.
struct LineageNode {
  std::string path;
  std::string sha256;          ///< content this node stands for
  std::string current_sha256;  ///< content on disk now; empty if missing
  std::optional<RunSummary> producer;
  bool producer_matches = true;  ///< producer wrote exactly `sha256`
  bool expanded_elsewhere = false;  ///< producer already shown higher up
  std::vector<LineageNode> inputs;
};

/// Traces `path` back through the runs that made it to files no run made
/// (lab-data and other sources). The root's producer is the newest successful
/// run that wrote the file's current content (or, failing that, its path).
LineageNode lineage(const Database& db, const std::string& path);

/// A recorded input whose content differs from the file on disk now, for the
/// newest run of each output path (the run whose results are the live ones).
struct StaleInput {
  RunSummary run;
  std::string input_path;
  std::string recorded_sha256;
  std::string current_sha256;  ///< empty if the file is gone
  std::vector<std::string> outputs;
};

std::vector<StaleInput> stale_inputs(const Database& db);

/// What differs between two runs: parameters (flattened to dotted keys),
/// input and output files (by path: content changed, only in A, only in B),
/// and metrics.
struct RunDiff {
  struct Value {
    std::string key;
    std::string a, b;  ///< "" where absent
  };
  std::vector<Value> params, inputs, outputs, metrics;
  bool empty() const { return params.empty() && inputs.empty() && outputs.empty() && metrics.empty(); }
};

RunDiff diff_runs(const Database& db, std::int64_t a, std::int64_t b);

/// Every output path's live version (newest successful run that wrote it)
/// against the file on disk now.
struct OutputCheck {
  std::string path;
  std::int64_t run_id = 0;
  std::string recorded_sha256;
  std::string current_sha256;  ///< empty if missing
  bool ok() const { return recorded_sha256 == current_sha256; }
};

std::vector<OutputCheck> verify_outputs(const Database& db);

/// One named metric across runs, oldest first, with an optional parameter
/// alongside (e.g. the centre frequency of each run).
struct MetricRow {
  RunSummary run;
  double value = 0;
  std::string unit;
  std::string by_value;  ///< the requested parameter, "" if absent
};

std::vector<MetricRow> metric_history(const Database& db, const std::string& name,
                                      const std::optional<std::string>& tool = std::nullopt,
                                      const std::string& by_param = "");

/// Why make would re-run FILE: every file in its lineage whose content now
/// differs from what the run downstream of it read, nearest first.
struct ChangedUpstream {
  std::string path;
  std::string recorded_sha256;
  std::string current_sha256;  ///< empty if missing
  RunSummary read_by;          ///< the run that read the recorded version
  std::size_t depth = 0;       ///< 1 = a direct input of the file's own run
};

std::vector<ChangedUpstream> why_changed(const Database& db, const std::string& path);

/// Current SHA-256 of a file, or "" if it does not exist; memoised per path.
class HashCache {
public:
  const std::string& operator()(const std::string& path);

private:
  std::map<std::string, std::string> hashes_;
};

}  // namespace mesowave::prov
