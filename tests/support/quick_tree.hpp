#pragma once
// A pipeline test's tree: a copy of the source tree (scripts/copy-tree) in a temporary folder,
// and make run in it on the quick tree (QUICK=1) with this build's tools (BUILD=..., so that a
// test never rebuilds the tools the other tests run) and the copy's own provenance database.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "mesowave/io/quantity_file.hpp"
#include "support/run_tool.hpp"

namespace mesowave::test {

struct QuickTree {
  std::filesystem::path source = MESOWAVE_SOURCE_DIR;
  std::filesystem::path build = std::filesystem::path(MESOWAVE_BIN_DIR).parent_path();
  TempDir work;
  std::filesystem::path root = work / "tree";
  std::filesystem::path db = root / "db/provenance-quick.sqlite";
  bool copied = run_command(source / "scripts/copy-tree", {root.string()}).exit_status == 0;  ///< ASSERT it

  /// make -C root QUICK=1 BUILD=... MESOWAVE_DB=db, then `args` (options and targets).
  ToolResult make(const std::vector<std::string>& args) const {
    std::vector<std::string> a = {"-C", root.string(), "--no-print-directory", "QUICK=1", "BUILD=" + build.string(),
                                  "MESOWAVE_DB=" + db.string()};
    a.insert(a.end(), args.begin(), args.end());
    return run_command("/usr/bin/make", a);
  }
};

/// The value of entry `name` of a lab-data quantity file (TOML); a test failure naming both if absent.
inline double quantity_entry(const std::filesystem::path& toml, const std::string& name) {
  for (const auto& q : io::read_quantity_file(toml))
    if (q.name == name) return std::stod(q.value);
  ADD_FAILURE() << name << " is not in " << toml;
  return NAN;
}

}  // namespace mesowave::test
