#include <gtest/gtest.h>

#include "mesowave/core/error.hpp"
#include "mesowave/io/output_stage.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

TEST(OutputStage, NothingAppearsUntilCommit) {
  test::TempDir dir;
  {
    io::OutputStage stage;
    stage.write_text(dir / "sub/a.txt", "A");
    EXPECT_FALSE(fs::exists(dir / "sub/a.txt"));
    stage.commit();
  }
  EXPECT_EQ(test::read_file(dir / "sub/a.txt"), "A");
  EXPECT_EQ(test::count_files(dir.path()), 1u);
}

TEST(OutputStage, DiscardLeavesNoTrace) {
  test::TempDir dir;
  test::write_file(dir / "old.txt", "old");
  {
    io::OutputStage stage;
    stage.write_text(dir / "old.txt", "new");
    stage.write_text(dir / "b.txt", "B");
  }  // destroyed without commit, as when a tool fails
  EXPECT_EQ(test::read_file(dir / "old.txt"), "old");
  EXPECT_EQ(test::count_files(dir.path()), 1u);
}

TEST(OutputStage, SamePathTwiceIsAnError) {
  test::TempDir dir;
  io::OutputStage stage;
  stage.stage(dir / "a");
  EXPECT_THROW(stage.stage(dir / "./a"), InputError);
}
