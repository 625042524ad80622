// Tables gathered from other runs' outputs (io/table_gather): values land in
// the right row and column, whatever file kind they come from, and every
// ambiguity is an error naming the file.
#include <gtest/gtest.h>

#include <fstream>

#include "mesowave/core/error.hpp"
#include "mesowave/io/table_gather.hpp"
#include "support/input_error.hpp"
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

// A row of several files: the first name wins in whichever file holds it, whatever the files'
// order (cube-150.mk's upv150.csv: a DEM row's picks hold E_d_GPa, its material E_glob_GPa; with
// the picks listed first, a search file by file gave E_d in the E_glob column).
TEST(TableGather, AlternativeSourcesAreSearchedByNameAcrossTheRowsFiles) {
  TempDir dir;
  write_file(dir / "picks.json", R"({"t_p_us": 36.18, "E_d_GPa": 36.71})");
  write_file(dir / "material.json", R"({"E_glob_GPa": 36.66})");
  write_file(dir / "upv.json", R"({"t_p_us": 35.0, "E_d_GPa": 36.70})");
  GatherSpec spec;
  spec.rows = {parse_gather_row("DEM=" + (dir / "picks.json").string() + "," + (dir / "material.json").string()),
               parse_gather_row("DEM reversed=" + (dir / "material.json").string() + "," + (dir / "picks.json").string()),
               parse_gather_row("measured=" + (dir / "upv.json").string())};
  spec.columns = {parse_column_source("E_glob_GPa=E_glob_GPa|E_d_GPa"), parse_column_source("t_p_us")};
  const auto t = gather_rows(spec);
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[0][1], "36.66");  // the material's E_glob, though the picks come first
  EXPECT_EQ(t.rows[1][1], "36.66");
  EXPECT_EQ(t.rows[2][1], "36.7");   // no file of the row holds E_glob: the second name
  EXPECT_EQ(t.rows[0][2], "36.18");
  // mean(): each file gives its own first name, as before
  spec.rows = {parse_gather_row("both=" + (dir / "picks.json").string() + "," + (dir / "upv.json").string())};
  spec.columns = {parse_column_source("E=mean(E_glob_GPa|E_d_GPa)")};
  EXPECT_DOUBLE_EQ(std::stod(gather_rows(spec).rows[0][1]), (36.71 + 36.70) / 2);
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
  auto message = [](const std::function<void()>& f) { return mesowave::test::input_error_of(f); };
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

// A JSON null (a value its run could not measure, e.g. a shock speed before the shock reached two
// sensors) is an empty cell, as a missing CSV cell is: never a zero, never an error.
TEST(TableGather, AJsonNullIsAnEmptyCell) {
  TempDir dir;
  write_file(dir / "a.json", R"({"c": {"speed": null, "x": 2}})");
  GatherSpec spec;
  spec.key_name = "run";
  spec.rows.push_back(parse_gather_row("a=" + (dir / "a.json").string()));
  spec.columns = {parse_column_source("speed=c.speed"), parse_column_source("x=c.x")};
  const auto t = gather_rows(spec);
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"a", "", "2"}));
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

TEST(TableGather, KeysOfTwoColumnsAndSelectorsNamingTheKey) {
  TempDir dir;
  write_file(dir / "m.csv", "run,f_kHz,c_m_s\nFEM,50,5103.5\nFEM,100,4995.25\n");
  write_file(dir / "p.csv", pcc_table(0.5, 0.7));
  GatherSpec spec;
  spec.key_name = "model, f_kHz";
  spec.rows = {parse_gather_row("FEM,100=" + (dir / "m.csv").string()), parse_gather_row("FEM,50=" + (dir / "m.csv").string())};
  spec.columns = {parse_column_source("c=c_m_s@f_kHz={f_kHz}")};
  const auto t = gather_rows(spec);
  EXPECT_EQ(t.header, (std::vector<std::string>{"model", "f_kHz", "c"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"FEM", "100", "4995.25"}));
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"FEM", "50", "5103.5"}));
  // A row key of the wrong number of parts, a selector naming no key column.
  spec.rows = {parse_gather_row("FEM=" + (dir / "m.csv").string())};
  EXPECT_NE(test::input_error_of([&] { gather_rows(spec); }).find("row FEM: 1 key part(s), the key model, f_kHz has 2"),
            std::string::npos);
  spec.rows = {parse_gather_row("FEM,50=" + (dir / "m.csv").string())};
  spec.columns = {parse_column_source("c=c_m_s@f_kHz={frequency}")};
  EXPECT_NE(test::input_error_of([&] { gather_rows(spec); }).find("'frequency' is not a key column"), std::string::npos);
}

TEST(TableGather, MeanAndMedianOverTheRowsFiles) {
  TempDir dir;
  // Three runs' tables and summaries; the mean and the median worked by hand.
  write_file(dir / "a.csv", pcc_table(0.5, 0.7));    // B: 0.5
  write_file(dir / "b.csv", pcc_table(0.25, 0.7));   // B: 0.25
  write_file(dir / "c.csv", pcc_table(-0.125, 0.7)); // B: -0.125
  write_file(dir / "a.json", R"({"wall_s": 3.5})");
  write_file(dir / "b.json", R"({"wall_s": 1.25})");
  write_file(dir / "c.json", R"({"wall_s": 2})");
  write_file(dir / "d.json", R"({"rss": 7})");  // holds no wall_s: not counted
  const auto files = [&](const std::vector<std::string>& names) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ",") + (dir / n).string();
    return list;
  };
  GatherSpec spec;
  spec.key_name = "model";
  spec.where = RowSelector{"sensor", "B"};
  spec.rows = {parse_gather_row("x=" + files({"a.csv", "b.csv", "c.csv", "a.json", "b.json", "c.json", "d.json"}))};
  spec.columns = {parse_column_source("pcc=mean(pcc_signal)"), parse_column_source("wall=median(wall_s)"),
                  parse_column_source("rss")};
  auto t = gather_rows(spec);
  // (0.5 + 0.25 - 0.125) / 3 in doubles, the shortest text that reads back (Python: repr(0.625 / 3)).
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"x", "0.20833333333333334", "2", "7"}));
  // An even count: the median is the mean of the middle two, (1.25 + 2) / 2.
  spec.rows = {parse_gather_row("x=" + files({"a.csv", "b.json", "c.json", "d.json", "a.json", "b.json"}))};
  t = gather_rows(spec);
  EXPECT_EQ(t.rows[0][2], "1.625");
  // Text cannot be averaged.
  write_file(dir / "e.json", R"({"wall_s": "fast"})");
  spec.rows = {parse_gather_row("x=" + files({"a.csv", "e.json", "d.json"}))};
  EXPECT_NE(test::input_error_of([&] { gather_rows(spec); }).find("'wall_s' holds 'fast', not a number"),
            std::string::npos);
  EXPECT_EQ(parse_column_source("m=median( wall_s )").source, "wall_s");
  EXPECT_EQ(parse_column_source("m=median( wall_s )").aggregate, ColumnSource::Aggregate::median);
  EXPECT_EQ(parse_column_source("m=means").aggregate, ColumnSource::Aggregate::first);
}

TEST(TableGather, FormatsAndJoinKeysAsAnotherTableSpellsThem) {
  TempDir dir;
  write_file(dir / "fem.json", R"({"rss": 1992.5, "rms": 25.849})");
  write_file(dir / "dem.json", R"({"rss": 19398.06, "rms": 2452.96})");
  write_file(dir / "paper.csv", "# the paper's\nmodel,RSS\nFEM,6056\n1.03R,22436\n");
  GatherSpec spec;
  spec.key_name = "model";
  spec.rows = {parse_gather_row("FEM 1 mm=" + (dir / "fem.json").string()),
               parse_gather_row("1.03R=" + (dir / "dem.json").string())};
  spec.columns = {parse_column_source("rss"), parse_column_source("rms")};
  spec.joins = {parse_table_join((dir / "paper.csv").string() + ":paper=RSS")};
  spec.join_keys = {{"FEM 1 mm", "FEM"}};
  spec.formats = {{"rss", {ColumnFormat::Style::rounded, 0}}, {"rms", {ColumnFormat::Style::fixed, 1}}};
  const auto t = gather_rows(spec);
  // 1992.5 rounds half away from zero to 1993; 2452.96 to one decimal is 2453.0 fixed.
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"FEM 1 mm", "1993", "25.8", "6056"}));
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"1.03R", "19398", "2453.0", "22436"}));
  spec.formats = {{"nothing", {ColumnFormat::Style::fixed, 1}}};
  EXPECT_THROW(gather_rows(spec), InputError);
}

// --pareto min:wall_s,max:pcc: five runs whose front is known by inspection - fast (1 s, 0.90),
// mid (3 s, 0.99) and exact (10 s, 1.0) are each the cheapest for their accuracy; slow (5 s, 0.95)
// is beaten by mid in both, and tie (3 s, 0.99 again) neither beats nor is beaten by mid: both stay.
TEST(TableGather, TheParetoFrontMarksTheCheapestRunForEachAccuracy) {
  TempDir dir;
  GatherSpec spec;
  spec.key_name = "run";
  const std::vector<std::tuple<const char*, double, double>> runs = {
      {"fast", 1, 0.90}, {"slow", 5, 0.95}, {"mid", 3, 0.99}, {"tie", 3, 0.99}, {"exact", 10, 1.0}};
  for (const auto& [name, wall, pcc] : runs) {
    const auto file = dir / (std::string(name) + ".json");
    write_file(file, "{\"wall_s\": " + std::to_string(wall) + ", \"pcc\": " + std::to_string(pcc) + "}");
    spec.rows.push_back(parse_gather_row(std::string(name) + "=" + file.string()));
  }
  for (const char* c : {"wall_s", "pcc"}) spec.columns.push_back(parse_column_source(c));
  spec.pareto = {"min:wall_s", "max:pcc"};
  const auto t = gather_rows(spec);
  EXPECT_EQ(t.header.back(), "pareto");
  std::vector<std::string> front;
  for (const auto& row : t.rows) front.push_back(row.back());
  EXPECT_EQ(front, (std::vector<std::string>{"yes", "", "yes", "yes", "yes"}));
  spec.pareto = {"least:wall_s", "max:pcc"};
  EXPECT_NE(test::input_error_of([&] { gather_rows(spec); }).find("min:COLUMN or max:COLUMN"), std::string::npos);
}
