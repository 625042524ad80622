// Tables for people (io/text_table): a column's numbers printed as asked, and
// CSV tables as Markdown.
#include <gtest/gtest.h>

#include "mesowave/core/error.hpp"
#include "mesowave/io/text_table.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::io;
using Style = ColumnFormat::Style;

TEST(ColumnFormat, FixedRoundedAndSignificant) {
  // Fixed: C's %.Nf (0.125 is exact in binary, and printf rounds the tie to even).
  EXPECT_EQ(apply_column_format("0.15", {Style::fixed, 3}, "x"), "0.150");
  EXPECT_EQ(apply_column_format("0.125", {Style::fixed, 2}, "x"), "0.12");
  EXPECT_EQ(apply_column_format("-0.0004", {Style::fixed, 3}, "x"), "-0.000");
  // Rounded: half away from zero (jq's round), then the shortest exact text.
  EXPECT_EQ(apply_column_format("0.125", {Style::rounded, 2}, "x"), "0.13");
  EXPECT_EQ(apply_column_format("-2.5", {Style::rounded, 0}, "x"), "-3");
  EXPECT_EQ(apply_column_format("2452.96", {Style::rounded, 1}, "x"), "2453");
  EXPECT_EQ(apply_column_format("18051665.597567238", {Style::rounded, 0}, "x"), "18051666");
  EXPECT_EQ(apply_column_format("80.41157935380771", {Style::rounded, 1}, "x"), "80.4");
  EXPECT_EQ(apply_column_format("6141.0002", {Style::rounded, 2}, "x"), "6141");
  EXPECT_EQ(apply_column_format("3246734475.537446", {Style::rounded, -6}, "x"), "3247000000");  // not 3.247e+09
  EXPECT_EQ(apply_column_format("0.0001", {Style::rounded, 4}, "x"), "0.0001");                  // not 1e-04
  // Significant: C's %.Ng.
  EXPECT_EQ(apply_column_format("1.864725512", {Style::significant, 3}, "x"), "1.86");
  EXPECT_EQ(apply_column_format("0.032076463", {Style::significant, 3}, "x"), "0.0321");
  EXPECT_EQ(test::input_error_of([] { apply_column_format("n/a", {Style::fixed, 1}, "column paper"); }),
            "column paper: 'n/a' is not a number to print with 1 digits");
}

TEST(ColumnFormat, ParsesNameEqualsDigits) {
  const auto [name, f] = parse_column_format("FEM 1 mm=0", Style::fixed);
  EXPECT_EQ(name, "FEM 1 mm");
  EXPECT_EQ(f.style, Style::fixed);
  EXPECT_EQ(f.digits, 0);
  EXPECT_EQ(parse_column_format("a=b=17", Style::rounded).first, "a=b");
  EXPECT_THROW(parse_column_format("wall_s", Style::fixed), InputError);
  EXPECT_THROW(parse_column_format("wall_s=18", Style::fixed), InputError);
  EXPECT_THROW(parse_column_format("wall_s=-1", Style::fixed), InputError);
  EXPECT_EQ(parse_column_format("Kn=-6", Style::rounded).second.digits, -6);
  EXPECT_THROW(parse_column_format("wall_s=1.5", Style::fixed), InputError);
  EXPECT_THROW(parse_column_format("=3", Style::fixed), InputError);
  EXPECT_NE(test::input_error_of([] { parse_column_format("wall_s=0", Style::significant); }).find("(1 to 17)"),
            std::string::npos);
}

TEST(MarkdownTable, HeadersFormatsAndEmptyFields) {
  const std::vector<std::string> header{"model", "wall_s", "paper"};
  const std::vector<std::vector<std::string>> rows{{"FEM 1 mm", "1.864725512", "6056"}, {"0.95R-EDEM", "0.0327", ""}};
  MarkdownTableOptions o;
  o.headers = {{"wall_s", "wall [s]"}};
  o.formats = {{"wall_s", {Style::significant, 2}}};
  EXPECT_EQ(format_markdown_table(header, rows, o),
            "| model | wall [s] | paper |\n"
            "|---|---|---|\n"
            "| FEM 1 mm | 1.9 | 6056 |\n"
            "| 0.95R-EDEM | 0.033 | - |\n");
  o.empty = "";
  o.formats.clear();
  EXPECT_EQ(format_markdown_table(header, {{"a", "1", ""}}, o), "| model | wall [s] | paper |\n|---|---|---|\n| a | 1 |  |\n");
  o.headers = {{"nope", "x"}};
  EXPECT_EQ(test::input_error_of([&] { format_markdown_table(header, rows, o); }), "the table has no column 'nope'");
}
