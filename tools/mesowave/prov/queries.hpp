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

/// Current SHA-256 of a file, or "" if it does not exist; memoised per path.
class HashCache {
public:
  const std::string& operator()(const std::string& path);

private:
  std::map<std::string, std::string> hashes_;
};

}  // namespace mesowave::prov
