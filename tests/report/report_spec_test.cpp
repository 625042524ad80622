// report/report_spec: one spec file, and a report read from several (the top spec's title and
// text, then each study's sections in the order the files are given).
#include <gtest/gtest.h>

#include "mesowave/core/error.hpp"
#include "mesowave/report/report_spec.hpp"
#include "support/input_error.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using mesowave::test::TempDir;
using mesowave::test::write_file;

namespace {

std::string section(const std::string& title, const std::string& file) {
  return "[[section]]\ntitle = \"" + title + "\"\n[[section.item]]\ntable = \"" + file + "\"\n";
}

TEST(ReportSpec, OneFileGivesTitleTextAndSections) {
  TempDir dir;
  write_file(dir / "a.toml", std::string("title = \"T\"\ntext = \"opening\"\n") + section("S1", "x.csv"));
  const auto spec = report::read_report_spec(dir / "a.toml");
  EXPECT_EQ(spec.title, "T");
  EXPECT_EQ(spec.text, "opening");
  ASSERT_EQ(spec.sections.size(), 1u);
  EXPECT_EQ(spec.sections[0].items.at(0).file, "x.csv");
}

TEST(ReportSpec, FurtherFilesAppendTheirSectionsInOrder) {
  TempDir dir;
  write_file(dir / "top.toml", "title = \"T\"\ntext = \"opening\"\n");
  write_file(dir / "b.toml", section("B1", "b1.csv") + section("B2", "b2.csv"));
  write_file(dir / "c.toml", section("C1", "c1.csv"));
  const auto spec = report::read_report_spec(std::vector<std::filesystem::path>{dir / "top.toml", dir / "b.toml", dir / "c.toml"});
  EXPECT_EQ(spec.title, "T");
  ASSERT_EQ(spec.sections.size(), 3u);
  EXPECT_EQ(spec.sections[0].title, "B1");
  EXPECT_EQ(spec.sections[1].title, "B2");
  EXPECT_EQ(spec.sections[2].title, "C1");
}

TEST(ReportSpec, AFurtherFileWithATitleOrNoSectionAnywhereIsAnError) {
  TempDir dir;
  write_file(dir / "top.toml", "title = \"T\"\n");
  write_file(dir / "titled.toml", std::string("title = \"mine\"\n") + section("S", "s.csv"));
  const std::string error = mesowave::test::input_error_of(
      [&] { report::read_report_spec(std::vector<std::filesystem::path>{dir / "top.toml", dir / "titled.toml"}); });
  EXPECT_NE(error.find("titled.toml: title and text belong in the first spec"), std::string::npos) << error;
  write_file(dir / "empty.toml", "# no sections yet\n");
  EXPECT_THROW(report::read_report_spec(std::vector<std::filesystem::path>{dir / "top.toml", dir / "empty.toml"}), InputError);
  EXPECT_THROW(report::read_report_spec(dir / "top.toml"), InputError);  // alone: no [[section]]
}

}  // namespace
