#pragma once
// Provenance answers rendered for people (text tables, indented trees),
// for Graphviz (DOT) and for programs (JSON).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mesowave/prov/merge.hpp"
#include "mesowave/prov/queries.hpp"

namespace mesowave::prov {

/// `path` relative to `base` when it lies inside it, else unchanged.
std::string display_path(const std::string& path, const std::filesystem::path& base);

std::string runs_text(const std::vector<RunSummary>& runs);
nlohmann::ordered_json runs_json(const std::vector<RunSummary>& runs);

std::string run_text(std::int64_t id, const RunRecord& run, const std::filesystem::path& base);
nlohmann::ordered_json run_json(std::int64_t id, const RunRecord& run);

std::string lineage_text(const LineageNode& root, const std::filesystem::path& base);
std::string lineage_dot(const LineageNode& root, const std::filesystem::path& base);
nlohmann::ordered_json lineage_json(const LineageNode& root);

std::string stale_text(const std::vector<StaleInput>& stale, const std::filesystem::path& base);
nlohmann::ordered_json stale_json(const std::vector<StaleInput>& stale);

std::string diff_text(std::int64_t a, std::int64_t b, const RunDiff& diff, const std::filesystem::path& base);
nlohmann::ordered_json diff_json(std::int64_t a, std::int64_t b, const RunDiff& diff);

std::string verify_text(const std::vector<OutputCheck>& checks, const std::filesystem::path& base);
nlohmann::ordered_json verify_json(const std::vector<OutputCheck>& checks);

std::string metrics_text(const std::string& name, const std::vector<MetricRow>& rows, const std::string& by_param);
nlohmann::ordered_json metrics_json(const std::string& name, const std::vector<MetricRow>& rows, const std::string& by_param);

std::string why_text(const std::string& path, const std::vector<ChangedUpstream>& changed, const std::filesystem::path& base);
nlohmann::ordered_json why_json(const std::string& path, const std::vector<ChangedUpstream>& changed);

/// What `mw-prov merge` did: a line per source, then the target's rows before and after.
std::string merge_text(const std::string& into, const MergeResult& result, const std::filesystem::path& base);
nlohmann::ordered_json merge_json(const std::string& into, const MergeResult& result);

}  // namespace mesowave::prov
