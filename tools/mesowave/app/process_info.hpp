#pragma once
// Facts about this process for its provenance record.
#include <cstdint>
#include <string>

namespace mesowave::app {

struct ResourceUsage {
  double cpu_s = 0;             ///< user + system
  std::int64_t peak_rss_kib = 0;
};

ResourceUsage resource_usage();
std::string host_name();
/// Now, as ISO 8601 UTC with milliseconds (2026-11-22T03:09:12.345Z).
std::string utc_timestamp();
/// SHA-256 of the running executable (/proc/self/exe).
std::string executable_sha256();

}  // namespace mesowave::app
