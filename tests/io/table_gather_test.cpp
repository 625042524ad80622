// Tables gathered from other runs' outputs (io/table_gather): values land in
// the right row and column, whatever file kind they come from, and every
// ambiguity is an error naming the file.
#include <gtest/gtest.h>

#include <fstream>

#include "mesowave/core/error.hpp"
#include "mesowave/io/table_gather.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::io;
using mesowave::test::TempDir;
using mesowave::test::write_file;

namespace {

// An mw-pcc table: one row per sensor and a last row "mean".
std::string pcc_table(double b, double c) {
  const double mean = (b + c) / 2;
  return "sensor,pcc_signal,pcc_envelope\nB," + std::to_string(b) + ",0.9\nC," + std::to_string(c) + ",0.8\nmean," +
         std::to_string(mean) + ",0.85\n";
}

}  // namespace

TEST(TableGather, ParsesRowsColumnsAndSelectors) {
  const auto r = parse_gather_row("100=a.csv, b.json");
  EXPECT_EQ(r.key, "100");
  ASSERT_EQ(r.files.size(), 2u);
  EXPECT_EQ(r.files[1], "b.json");
  const auto c = parse_column_source("B=pcc_signal@sensor=B");
  EXPECT_EQ(c.name, "B");
  EXPECT_EQ(c.source, "pcc_signal");
  ASSERT_TRUE(c.where);
  EXPECT_EQ(*c.where, (RowSelector{"sensor", "B"}));
  const auto same = parse_column_source("wall_s");
  EXPECT_EQ(same.source, "wall_s");
  EXPECT_FALSE(same.where);
  EXPECT_THROW(parse_gather_row("100"), InputError);
  EXPECT_THROW(parse_gather_row("=a.csv"), InputError);
  EXPECT_THROW(parse_column_source("=x"), InputError);
  EXPECT_THROW(parse_row_selector("sensor"), InputError);
}

TEST(TableGather, OneRowPerRunFromCsvJsonAndToml) {
  TempDir dir;
  write_file(dir / "pcc-100.csv", pcc_table(0.5, 0.7));
  write_file(dir / "pcc-150.csv", pcc_table(0.25, 0.75));
  write_file(dir / "run-100.json", R"({"wall_s": 51.5, "model": "linear", "energy": {"residual_relative": -1.5e-06}})");
  write_file(dir / "run-150.json", R"({"wall_s": 12, "model": "full", "energy": {"residual_relative": 2e-06}})");
  write_file(dir / "lab.toml", "[E_dem]\nvalue = 23.31\nunit = \"GPa\"\nsource = \"paper\"\ncite = \"Table 2\"\n");
  GatherSpec spec;
  spec.key_name = "f_kHz";
  spec.where = RowSelector{"sensor", "mean"};
  for (const char* f : {"100", "150"})
    spec.rows.push_back(parse_gather_row(std::string(f) + "=" + (dir / ("pcc-" + std::string(f) + ".csv")).string() +
                                         "," + (dir / ("run-" + std::string(f) + ".json")).string() + "," +
                                         (dir / "lab.toml").string()));
  for (const char* c : {"mean=pcc_signal", "C=pcc_signal@sensor=C", "wall_s", "model", "residual=energy.residual_relative",
                        "E_dem"})
    spec.columns.push_back(parse_column_source(c));
  const auto t = gather_rows(spec);
  EXPECT_EQ(t.header, (std::vector<std::string>{"f_kHz", "mean", "C", "wall_s", "model", "residual", "E_dem"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"100", "0.600000", "0.700000", "51.5", "linear", "-1.5e-06", "23.31"}));
  EXPECT_EQ(t.rows[1][1], "0.500000");
  EXPECT_EQ(t.rows[1][2], "0.750000");
  EXPECT_EQ(t.rows[1][3], "12");
}

// One quantity under different names in different tools' summaries (a lab-data
// TOML entry, mw-calibrate's flat JSON, mw-dem's nested "test" object).
TEST(TableGather, AlternativeSourcesTakeTheFirstNameAFileHolds) {
  TempDir dir;
  write_file(dir / "lab.toml", "[E_glob_GPa]\nvalue = 27.65\nunit = \"GPa\"\nsource = \"paper\"\ncite = \"Table 2\"\n");
  write_file(dir / "calibration.json", R"({"E_glob_GPa": 27.45, "test": {"E_glob_GPa": 1.0}})");
  write_file(dir / "run.json", R"({"test": {"E_glob_GPa": 24.2}})");
  GatherSpec spec;
  for (const char* r : {"paper", "calibrated", "run"}) {
    const std::string file = std::string(r) == "paper" ? "lab.toml" : std::string(r) == "run" ? "run.json" : "calibration.json";
    spec.rows.push_back(parse_gather_row(std::string(r) + "=" + (dir / file).string()));
  }
  spec.columns.push_back(parse_column_source("E=E_glob_GPa|test.E_glob_GPa"));
  const auto t = gather_rows(spec);
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[0][1], "27.65");
  EXPECT_EQ(t.rows[1][1], "27.45");  // the first name wins in a file holding both
  EXPECT_EQ(t.rows[2][1], "24.2");
  spec.significant_digits = 4;  // JSON numbers rounded; the TOML value as written
  const auto rounded = gather_rows(spec);
  EXPECT_EQ(rounded.rows[0][1], "27.65");
  EXPECT_EQ(rounded.rows[2][1], "24.2");
  write_file(dir / "run.json", R"({"test": {"E_glob_GPa": 24.210599476597476}})");
  EXPECT_EQ(gather_rows(spec).rows[2][1], "24.21");
  spec.columns = {parse_column_source("E=E_st_GPa|E_glob")};
  EXPECT_THROW(gather_rows(spec), InputError);
}

TEST(TableGather, AmbiguousOrMissingValuesAreErrorsNamingTheFile) {
  TempDir dir;
  const auto pcc = (dir / "pcc.csv").string();
  write_file(dir / "pcc.csv", pcc_table(0.5, 0.7));
  write_file(dir / "run.json", R"({"wall_s": 1, "energy": {"kinetic_J": [1, 2]}})");
  auto gather = [&](const std::string& row, const std::string& column, std::optional<RowSelector> where) {
    GatherSpec spec;
    spec.rows = {parse_gather_row(row)};
    spec.columns = {parse_column_source(column)};
    spec.where = where;
    return gather_rows(spec);
  };
  auto message = [&](auto&& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([&] { gather("1=" + pcc, "pcc_signal", std::nullopt); }),
            pcc + " has 3 rows: say which one (a row selector COLUMN=VALUE)");
  EXPECT_EQ(message([&] { gather("1=" + pcc, "pcc_signal", RowSelector{"sensor", "D"}); }),
            pcc + " has 0 rows with sensor = D (need exactly one)");
  EXPECT_EQ(message([&] { gather("1=" + pcc, "pcc_signal", RowSelector{"probe", "B"}); }),
            pcc + " has no column 'probe' to pick a row by");
  EXPECT_EQ(message([&] { gather("1=" + pcc, "wall_s", RowSelector{"sensor", "B"}); }),
            "row 1: no file holds 'wall_s' (" + pcc + ")");
  EXPECT_NE(message([&] { gather("1=" + (dir / "run.json").string(), "energy.kinetic_J", std::nullopt); })
                .find("is not a number, text or true/false"),
            std::string::npos);
  EXPECT_NE(message([&] { gather("1=" + (dir / "none.csv").string(), "x", std::nullopt); }).find("does not exist"),
            std::string::npos);
}

TEST(TableGather, JoinMatchesKeysAsNumbersAndLeavesGapsEmpty) {
  CsvTable ours;
  ours.header = {"f_kHz", "pcc"};
  ours.rows = {{"100", "0.5"}, {"120", "0.6"}, {"150", "0.7"}};
  const auto paper = parse_csv("f_kHz,pcc_mean,source\n100.0,0.68,Table 3\n150,0.72,Table 3\n", "table3.csv");
  join_columns(ours, paper, "f_kHz", {parse_column_source("paper=pcc_mean")});
  EXPECT_EQ(ours.header, (std::vector<std::string>{"f_kHz", "pcc", "paper"}));
  EXPECT_EQ(ours.rows[0][2], "0.68");
  EXPECT_EQ(ours.rows[1][2], "");
  EXPECT_EQ(ours.rows[2][2], "0.72");
  const auto twice = parse_csv("f_kHz,pcc_mean\n100,0.1\n100.0,0.2\n", "twice.csv");
  EXPECT_THROW(join_columns(ours, twice, "f_kHz", {parse_column_source("p=pcc_mean")}), InputError);
  EXPECT_THROW(join_columns(ours, paper, "f_kHz", {parse_column_source("p=nothing")}), InputError);
}

TEST(TableGather, JoinsParseFileAndColumnsAtTheLastColon) {
  const auto j = parse_table_join("C:/lab/paper/table3.csv:paper=pcc_mean, fem=pcc_fem");
  EXPECT_EQ(j.file, "C:/lab/paper/table3.csv");
  ASSERT_EQ(j.columns.size(), 2u);
  EXPECT_EQ(j.columns[0].name, "paper");
  EXPECT_EQ(j.columns[0].source, "pcc_mean");
  EXPECT_EQ(j.columns[1].name, "fem");
  EXPECT_EQ(j.columns[1].source, "pcc_fem");
  EXPECT_THROW(parse_table_join("table3.csv"), InputError);
  EXPECT_THROW(parse_table_join(":paper=pcc_mean"), InputError);
  EXPECT_THROW(parse_table_join("table3.csv:"), InputError);
}

// The joined columns follow the gathered ones, matched by key as numbers
// ("100" meets "100.0"); a key the joined table lacks is an empty field; the
// spec's files are the rows', then the joins'.
TEST(TableGather, JoinedColumnsFollowTheGatheredOnesByKey) {
  TempDir dir;
  write_file(dir / "pcc-100.csv", pcc_table(0.5, 0.7));
  write_file(dir / "pcc-150.csv", pcc_table(0.25, 0.75));
  write_file(dir / "paper.csv", "f_kHz,pcc_mean,note\n100.0,0.63,\n200,0.41,\n");
  GatherSpec spec;
  spec.key_name = "f_kHz";
  spec.where = RowSelector{"sensor", "mean"};
  for (const char* f : {"100", "150"})
    spec.rows.push_back(parse_gather_row(std::string(f) + "=" + (dir / ("pcc-" + std::string(f) + ".csv")).string()));
  spec.columns.push_back(parse_column_source("mesowave=pcc_signal"));
  spec.joins.push_back(parse_table_join((dir / "paper.csv").string() + ":paper=pcc_mean"));
  EXPECT_EQ(spec.files(), (std::vector<std::filesystem::path>{dir / "pcc-100.csv", dir / "pcc-150.csv", dir / "paper.csv"}));
  const auto t = gather_rows(spec);
  EXPECT_EQ(t.header, (std::vector<std::string>{"f_kHz", "mesowave", "paper"}));
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"100", "0.600000", "0.63"}));
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"150", "0.500000", ""}));
  spec.joins = {parse_table_join((dir / "paper.csv").string() + ":paper=pcc_std")};
  EXPECT_THROW(gather_rows(spec), InputError);
}
