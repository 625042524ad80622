// A lab's own specimen is one folder: scripts/check-new-study makes a study of a 100 mm cube of
// another mix from the concrete cube (make new-study), runs the quick pipeline on a copy of the
// tree with the three studies, and checks the new study's density and pulse velocity against
// their closed forms and its sections in the report.
#include <gtest/gtest.h>

#include "support/run_tool.hpp"

using namespace mesowave::test;
namespace fs = std::filesystem;

TEST(Pipeline, ANewStudyIsOneFolderPickedUpByTheMakefileAndTheReport) {
  const fs::path source = MESOWAVE_SOURCE_DIR, build = fs::path(MESOWAVE_BIN_DIR).parent_path();
  const auto r = run_command(source / "scripts/check-new-study", {build.string()});
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("check-new-study: all hold"), std::string::npos) << r.out << r.err;
  EXPECT_EQ(r.out.find("FAILED"), std::string::npos) << r.out;
}
