#include <gtest/gtest.h>

#include "mesowave/core/error.hpp"
#include "mesowave/io/csv.hpp"
#include "support/input_error.hpp"

using namespace mesowave;

TEST(Csv, ParsesHeaderCommentsQuotesAndBlankLines) {
  const auto t = io::parse_csv("# comment\nname, value\n\n\"a, b\", 1.5\n\"say \"\"hi\"\"\",-2e3\n", "t.csv");
  ASSERT_EQ(t.header, (std::vector<std::string>{"name", "value"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.text(0, 0), "a, b");
  EXPECT_EQ(t.text(1, 0), "say \"hi\"");
  EXPECT_DOUBLE_EQ(t.number(0, 1), 1.5);
  EXPECT_DOUBLE_EQ(t.number(1, 1), -2000);
  EXPECT_EQ(t.row_lines[0], 4u);
}

TEST(Csv, ErrorsNameFileLineAndColumn) {
  const auto t = io::parse_csv("a,b\n1,x\n", "t.csv");
  EXPECT_EQ(mesowave::test::input_error_of([&] { t.number(0, 1); }), "t.csv:2: column 'b' holds 'x', not a finite number");
  EXPECT_THROW(io::parse_csv("a,b\n1,2,3\n", "t.csv"), InputError);
  EXPECT_THROW(io::parse_csv("a\n\"open\n", "t.csv"), InputError);
  EXPECT_THROW(io::parse_csv("", "t.csv"), InputError);
  EXPECT_THROW(t.column("c"), InputError);
  EXPECT_THROW(io::parse_csv("a\nnan\n", "t.csv").number(0, 0), InputError);
}

TEST(Csv, WriteThenReadRoundTrips) {
  const std::vector<std::string> header = {"k", "v"};
  const std::vector<std::vector<std::string>> rows = {{"x,y", "1"}, {"q\"q", "2"}};
  const auto t = io::parse_csv(io::to_csv(header, rows), "rt");
  EXPECT_EQ(t.header, header);
  EXPECT_EQ(t.rows, rows);
}
