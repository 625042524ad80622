#pragma once
// What one tool run leaves in the provenance database.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mesowave/prov/database.hpp"

namespace mesowave::prov {

struct FileRecord {
  std::string path;  ///< absolute, normalised
  std::int64_t size_bytes = 0;
  std::string sha256;
};

/// Size and SHA-256 of `path` as it is now, under its absolute normalised name.
FileRecord describe_file(const std::filesystem::path& path);
/// As describe_file, but reads the content from `content_path` (a staged
/// output that has not been renamed to `path` yet).
FileRecord describe_file(const std::filesystem::path& path, const std::filesystem::path& content_path);

struct MetricRecord {
  std::string name;
  double value = 0;
  std::string unit;  ///< "" when dimensionless
};

struct RunRecord {
  std::string tool;
  std::string version;
  std::string binary_sha256;
  std::vector<std::string> argv;
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  std::string cwd;
  std::string host;
  std::string started_at;
  std::string ended_at;
  int exit_status = 0;  ///< prov/run_status.hpp
  std::string error;
  double wall_s = 0;
  double cpu_s = 0;
  std::int64_t peak_rss_kib = 0;
  std::vector<FileRecord> inputs;
  std::vector<FileRecord> outputs;
  std::vector<MetricRecord> metrics;
};

/// Inserts the run with its files and metrics in one transaction; returns its id.
std::int64_t record_run(const Database& db, const RunRecord& run);

}  // namespace mesowave::prov
