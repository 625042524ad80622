// mw-table as the pipeline runs it: a table gathered from per-run files, joined
// with a paper's table, plotted; bad input exits 1 with one line and leaves
// nothing behind; the run records every file it read.
#include <gtest/gtest.h>

#include "mesowave/io/csv.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::test;

namespace {

bool is_png(const std::filesystem::path& p) { return read_file(p).rfind("\x89PNG\r\n\x1a\n", 0) == 0; }

void write_runs(const TempDir& dir) {
  write_file(dir / "pcc-100kHz.csv", "sensor,pcc_signal,pcc_envelope\nB,0.5,0.9\nmean,0.5,0.9\n");
  write_file(dir / "pcc-300kHz.csv", "sensor,pcc_signal,pcc_envelope\nB,0.25,0.8\nmean,0.25,0.8\n");
  write_file(dir / "paper.csv", "# Table 3\nf_kHz,pcc_mean\n100,0.68\n300,0.75\n500,0.70\n");
}

}  // namespace

TEST(TableCli, GatherJoinAndPlotAsRecordedRuns) {
  TempDir dir;
  write_runs(dir);
  const std::string db = (dir / "prov.sqlite").string(), table = (dir / "table3.csv").string();
  const auto g = run_tool("mw-table", {"gather", "--key-name", "f_kHz", "--row", "100=" + (dir / "pcc-100kHz.csv").string(),
                                       "--row", "300=" + (dir / "pcc-300kHz.csv").string(), "--where", "sensor=mean",
                                       "--column", "dem_vs_fem=pcc_signal", "--join",
                                       (dir / "paper.csv").string() + ":paper=pcc_mean", "--csv", table, "--db", db});
  ASSERT_EQ(g.exit_status, 0) << g.err;
  const auto t = io::read_csv(table);
  EXPECT_EQ(t.header, (std::vector<std::string>{"f_kHz", "dem_vs_fem", "paper"}));
  EXPECT_EQ(t.rows, (std::vector<std::vector<std::string>>{{"100", "0.5", "0.68"}, {"300", "0.25", "0.75"}}));

  const std::string png = (dir / "table3.png").string();
  const auto p = run_tool("mw-table", {"plot", table, "--x", "f_kHz", "--y", "dem_vs_fem=DEM vs FEM", "--y",
                                       "paper=paper", "--out", png, "--db", db});
  ASSERT_EQ(p.exit_status, 0) << p.err;
  EXPECT_TRUE(is_png(png));
  EXPECT_NE(p.out.find("2 series, 2 rows"), std::string::npos) << p.out;
  const auto points = run_tool("mw-table", {"plot", table, "--x", "f_kHz", "--y", "paper", "--label-column", "f_kHz",
                                            "--log-x", "--log-y", "--out", (dir / "points.svg").string()});
  ASSERT_EQ(points.exit_status, 0) << points.err;
  EXPECT_NE(read_file(dir / "points.svg").find("<svg"), std::string::npos);

  // The table's lineage reaches the per-run files and the paper's table.
  const auto lineage = run_tool("mw-prov", {"--db", db, "lineage", png});
  ASSERT_EQ(lineage.exit_status, 0) << lineage.err;
  for (const char* f : {"table3.csv", "pcc-100kHz.csv", "pcc-300kHz.csv", "paper.csv"})
    EXPECT_NE(lineage.out.find(f), std::string::npos) << f << " not in\n" << lineage.out;
}

TEST(TableCli, BadInputIsOneLineAndNothingWritten) {
  TempDir dir;
  write_runs(dir);
  const std::string table = (dir / "t.csv").string();
  auto refuse = [&](const std::vector<std::string>& args, const std::string& what) {
    const auto r = run_tool("mw-table", args);
    EXPECT_EQ(r.exit_status, 1) << r.out << r.err;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << "expected '" << what << "' in: " << r.err;
    EXPECT_EQ(count_files(dir.path()), 3u) << "a refused run left a file behind";
  };
  const std::string pcc = (dir / "pcc-100kHz.csv").string();
  refuse({"gather", "--row", "100=" + pcc, "--column", "pcc_signal", "--csv", table}, "has 2 rows: say which one");
  refuse({"gather", "--row", "100=" + pcc, "--where", "sensor=mean", "--column", "wall_s", "--csv", table},
         "row 100: no file holds 'wall_s'");
  refuse({"gather", "--row", "100", "--column", "x", "--csv", table}, "must read KEY=FILE");
  refuse({"gather", "--row", "100=" + pcc, "--where", "sensor=mean", "--column", "pcc_signal", "--join",
          (dir / "paper.csv").string(), "--csv", table},
         "must read FILE:NAME=SOURCE");
  refuse({"plot", (dir / "paper.csv").string(), "--x", "f_kHz", "--y", "pcc_mean", "--out", (dir / "p.pdf").string()},
         "must end in .png or .svg");
  refuse({"plot", (dir / "paper.csv").string(), "--x", "frequency", "--y", "pcc_mean", "--out", (dir / "p.png").string()},
         "frequency");
  refuse({"plot", (dir / "paper.csv").string(), "--x", "f_kHz", "--y", "pcc_mean", "--style", "bars", "--out",
          (dir / "p.png").string()},
         "--style bars");
}

TEST(TableCli, MeanFormatsMarkdownAndTheRodFindings) {
  TempDir dir;
  write_runs(dir);
  const std::string table = (dir / "t.csv").string(), md = (dir / "t.md").string();
  // One row from both frequencies' tables: the mean (0.5 + 0.25) / 2 with three decimals.
  const auto g = run_tool("mw-table", {"gather", "--key-name", "model", "--row",
                                       "DEM=" + (dir / "pcc-100kHz.csv").string() + "," + (dir / "pcc-300kHz.csv").string(),
                                       "--where", "sensor=B", "--column", "pcc=mean(pcc_signal)", "--decimals", "pcc=3",
                                       "--csv", table});
  ASSERT_EQ(g.exit_status, 0) << g.err;
  EXPECT_EQ(read_file(table), "model,pcc\nDEM,0.375\n");
  const auto m = run_tool("mw-table", {"markdown", table, "--header", "pcc=PCC", "--out", md});
  ASSERT_EQ(m.exit_status, 0) << m.err;
  EXPECT_EQ(read_file(md), "| model | PCC |\n|---|---|\n| DEM | 0.375 |\n");

  write_file(dir / "v.csv", "f_kHz,FEM,1.03R,1.05R,1.15R\n50,3,3,2,1\n150,1,2,1.5,0.5\n");
  write_file(dir / "t1.csv", "model,pcc_vs_fem_envelope\n0.95R,-0.1\n1.03R,0.9\n1.05R,0.8\n1.15R,0.7\n");
  write_file(dir / "t2.csv", "model,rss_m2_s2\n0.95R,1e7\n1.03R,2e4\n1.05R,5e4\n1.15R,6e4\n");
  const auto f = run_tool("mw-table", {"findings", "--velocity", (dir / "v.csv").string(), "--table1",
                                       (dir / "t1.csv").string(), "--table2", (dir / "t2.csv").string(), "--fem-column",
                                       "FEM", "--out", md});
  ASSERT_EQ(f.exit_status, 0) << f.err;
  EXPECT_EQ(read_file(md).find("- [x] velocity falls with frequency"), 0u) << read_file(md);
  EXPECT_NE(read_file(md).find("at 2 of 2 frequencies\n"), std::string::npos) << read_file(md);
}
