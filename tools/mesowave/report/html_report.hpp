#pragma once
// The report as one static HTML page (opens from disk, no server): every
// table and figure of the spec, each with the provenance of the file it shows
// (the run that made it: tool, version, parameters, input hashes, and its
// lineage back to lab-data), and the machine and compute time behind it all.
#include <filesystem>
#include <string>
#include <vector>

#include "mesowave/prov/database.hpp"
#include "mesowave/report/report_spec.hpp"

namespace mesowave::report {

struct RenderedReport {
  std::string html;
  /// Figures to copy next to the page: (source file, name under figures/).
  std::vector<std::pair<std::filesystem::path, std::string>> figures;
  std::size_t tables = 0;
  std::size_t runs_behind = 0;  ///< distinct recorded runs in the items' lineage
};

/// Renders `spec`. Files are resolved against `base`; a missing file is an
/// InputError naming it. `db` may be null (then no provenance panels).
RenderedReport render_report(const ReportSpec& spec, const prov::Database* db, const std::filesystem::path& base);

std::string escape_html(const std::string& text);

}  // namespace mesowave::report
