// Issue 8's make properties, on a copy of the source tree with the quick pipeline
// (scripts/check-pipeline --no-build: the same rules as `make -j 8 reproduce-quick`,
// without the build step, so that this test never rebuilds the tools other tests run):
// a second make runs nothing, one changed lab-data value re-runs exactly the
// outputs the provenance database says depend on it, a measured-signals folder adds
// Table 3's column with the value it must have, and every run is recorded without error.
#include <gtest/gtest.h>

#include "support/run_tool.hpp"

using namespace mesowave::test;
namespace fs = std::filesystem;

TEST(Pipeline, QuickPipelineRerunsExactlyWhatChanged) {
  const fs::path source = MESOWAVE_SOURCE_DIR, build = fs::path(MESOWAVE_BIN_DIR).parent_path();
  const auto r = run_command(source / "scripts/check-pipeline", {"--no-build", build.string()});
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("check-pipeline: all hold"), std::string::npos) << r.out << r.err;
  EXPECT_EQ(r.out.find("FAILED"), std::string::npos) << r.out;
}
