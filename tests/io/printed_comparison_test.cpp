// mw-compare's pairing and rounding (io/printed_comparison.hpp) on
// hand-made tables, checked digit by digit.
#include "mesowave/io/printed_comparison.hpp"

#include <gtest/gtest.h>

#include "mesowave/core/error.hpp"

using namespace mesowave;
using namespace mesowave::io;

TEST(PrintedComparison, DecimalsAsPrinted) {
  EXPECT_EQ(printed_decimals("30.44"), 2);
  EXPECT_EQ(printed_decimals("27"), 0);
  EXPECT_EQ(printed_decimals("0.160"), 3);  // a printed trailing zero counts
  EXPECT_EQ(printed_decimals("1.5e-06"), 1);
}

TEST(PrintedComparison, RoundsToThePapersDigits) {
  const auto c = compare_printed({{"Lydon", "E_st_GPa", "30.4449", "30.44"},
                                  {"BS 8110", "E_st_GPa", "26.8551", "26.85"},
                                  {"mean", "method", "mean of the three", "mean of the three"}});
  ASSERT_EQ(c.rows.size(), 3u);
  // 30.4449 rounds to 30.44 (same digits); 0.0049 / 30.44 = 0.0161 %.
  EXPECT_EQ(c.rows[0], (std::vector<std::string>{"Lydon", "E_st_GPa", "30.44490", "30.44", "30.44", "0.0049", "0.02", "yes"}));
  // 26.8551 rounds to 26.86, not the paper's 26.85.
  EXPECT_EQ(c.rows[1][3], "26.86");
  EXPECT_EQ(c.rows[1][7], "no");
  EXPECT_EQ(c.rows[2][7], "yes");  // text compared as text
  EXPECT_EQ(c.same_printed_digits, 2u);
  EXPECT_NEAR(c.max_abs_rel_difference_pct, 100 * 0.0051 / 26.85, 1e-9);
  EXPECT_EQ(c.header.size(), 8u);
}

TEST(PrintedComparison, PairsTablesOnTheKey) {
  const CsvTable ours = parse_csv("method,E_st_GPa,extra\nA,1.234,9\nB,2.5,9\n", "ours.csv");
  const CsvTable paper = parse_csv("method,E_st_GPa,cite\nB,2.50,p. 3\nA,,p. 3\n", "paper.csv");
  const auto v = pair_tables(ours, paper, "method", {});
  ASSERT_EQ(v.size(), 1u);  // A's empty paper cell is skipped; cite and extra are not compared
  EXPECT_EQ(v[0].row, "B");
  EXPECT_EQ(v[0].column, "E_st_GPa");
  EXPECT_EQ(v[0].ours_text, "2.5");
  EXPECT_EQ(v[0].paper_text, "2.50");
  const CsvTable missing = parse_csv("method,E_st_GPa\nC,1\n", "paper.csv");
  EXPECT_THROW(pair_tables(ours, missing, "method", {}), InputError);
  const CsvTable nothing_shared = parse_csv("method,other\nA,1\n", "paper.csv");
  EXPECT_THROW(pair_tables(ours, nothing_shared, "method", {}), InputError);
}
