// The lab tools from the command line: results, and every bad input of issue 2
// answered with one line, exit status 1 and no file written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/run_tool.hpp"

using namespace mesowave::test;
using nlohmann::json;

namespace {

const std::vector<std::string> kUpv = {"--path-mm", "150", "--t-p-us", "35", "--t-s-us", "55.1", "--density-kg-m3", "2129.56"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// The contract for bad input: exit 1, a single line "error: ..." naming
// `needle`, nothing on stdout, no file in `dir`.
void expect_rejected(const ToolResult& r, const std::string& needle, const TempDir& dir) {
  EXPECT_EQ(r.exit_status, 1) << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(count_files(dir.path()), 0u);
}

}  // namespace

TEST(UpvCli, PrintsThePaperModuli) {
  TempDir dir;
  const auto r = run_tool("mw-upv", with(kUpv, {"--out", (dir / "upv.json").string()}));
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = json::parse(r.out);
  EXPECT_NEAR(j["E_d_GPa"].get<double>(), 36.6714, 1e-4);
  EXPECT_NEAR(j["nu_d"].get<double>(), 0.16179, 1e-5);
  EXPECT_EQ(json::parse(read_file(dir / "upv.json")), j);
}

TEST(UpvCli, RejectsBadInput) {
  struct Case {
    std::vector<std::string> args;
    std::string needle;
  };
  const std::vector<Case> cases = {
      {{"--path-mm", "0", "--t-p-us", "35", "--t-s-us", "55", "--density-kg-m3", "2129"}, "--path-mm (0 mm)"},
      {{"--path-mm", "150", "--t-p-us", "-35", "--t-s-us", "55", "--density-kg-m3", "2129"}, "--t-p-us (-35 us)"},
      {{"--path-mm", "150", "--t-p-us", "nan", "--t-s-us", "55", "--density-kg-m3", "2129"}, "--t-p-us (nan us)"},
      {{"--path-mm", "150", "--t-p-us", "35", "--t-s-us", "inf", "--density-kg-m3", "2129"}, "--t-s-us (inf us)"},
      {{"--path-mm", "150", "--t-p-us", "35", "--t-s-us", "55", "--density-kg-m3", "-1"}, "--density-kg-m3 (-1"},
      {{"--path-mm", "150", "--t-p-us", "35", "--t-s-us", "30", "--density-kg-m3", "2129"}, "t_s (30 us) must exceed t_p (35 us)"},
      {{"--path-mm", "150", "--t-p-us", "35", "--t-s-us", "35", "--density-kg-m3", "2129"}, "must exceed t_p"},
      {{"--path-mm", "150", "--t-p-us", "35", "--t-s-us", "45", "--density-kg-m3", "2129"}, "sqrt(2)"},
      {{"--path-mm", "150", "--t-p-us", "35", "--density-kg-m3", "2129"}, "--nu-assumed"},
      {{"--path-mm", "150", "--t-p-us", "abc", "--t-s-us", "55", "--density-kg-m3", "2129"}, "--t-p-us"},
  };
  for (const auto& c : cases) {
    TempDir dir;
    SCOPED_TRACE(c.needle);
    expect_rejected(run_tool("mw-upv", with(c.args, {"--out", (dir / "upv.json").string()})), c.needle, dir);
  }
}

TEST(EstaticCli, WritesTable1) {
  TempDir dir;
  const auto r = run_tool("mw-estatic", {"--E-d-GPa", "36.68", "--density-kg-m3", "2129.56", "--E-st-measured-GPa",
                                         "27.42", "--table", (dir / "t1.csv").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = json::parse(r.out);
  EXPECT_NEAR(j["E_st_bs8110_GPa"].get<double>(), 26.85, 1e-9);
  EXPECT_NEAR(j["rel_error_mean_pct"].get<double>(), 9.109, 1e-3);
  const auto table = read_file(dir / "t1.csv");
  EXPECT_NE(table.find("Popovics,Eq. (13)"), std::string::npos);
  EXPECT_NE(table.find("static test"), std::string::npos);
}

TEST(EstaticCli, RejectsBadInput) {
  TempDir dir;
  const auto table = (dir / "t1.csv").string();
  expect_rejected(run_tool("mw-estatic", {"--E-d-GPa", "12", "--density-kg-m3", "2129", "--table", table}),
                  "too small for BS 8110-2", dir);
  // At E_d = 15.2 GPa Eq. (12) gives exactly 0: non-positive, refused as well.
  expect_rejected(run_tool("mw-estatic", {"--E-d-GPa", "15.2", "--density-kg-m3", "2129", "--table", table}),
                  "gives a non-positive static modulus", dir);
  expect_rejected(run_tool("mw-estatic", {"--E-d-GPa", "0", "--density-kg-m3", "2129", "--table", table}),
                  "--E-d-GPa (0 GPa)", dir);
  expect_rejected(run_tool("mw-estatic", {"--E-d-GPa", "nan", "--density-kg-m3", "2129", "--table", table}),
                  "--E-d-GPa (nan GPa)", dir);
  expect_rejected(run_tool("mw-estatic", {"--E-d-GPa", "36", "--density-kg-m3", "inf", "--table", table}),
                  "--density-kg-m3 (inf kg/m3)", dir);
  expect_rejected(run_tool("mw-estatic", {"--E-d-GPa", "36", "--density-kg-m3", "0", "--table", table}),
                  "--density-kg-m3 (0 kg/m3)", dir);
  expect_rejected(run_tool("mw-estatic", {"--E-d-GPa", "36", "--density-kg-m3", "2129", "--E-st-measured-GPa", "-3",
                                          "--table", table}),
                  "--E-st-measured-GPa (-3 GPa)", dir);
}

TEST(SpecimenCli, OneCubeAndABatch) {
  TempDir dir;
  auto r = run_tool("mw-specimen", {"--shape", "cube", "--side-mm", "150", "--mass-g", "7187.265"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NEAR(json::parse(r.out)["density_kg_m3"].get<double>(), 2129.56, 1e-9);

  write_file(dir / "batch.csv",
             "specimen,shape,mass_g,side_mm,diameter_mm,height_mm\nA,cube,7187.265,150,,\n"
             "B,cylinder,3000,,100,180\n");
  r = run_tool("mw-specimen", {"--csv", (dir / "batch.csv").string(), "--table", (dir / "each.csv").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = json::parse(r.out);
  const double cylinder = 3.0 / (3.14159265358979323846 / 4 * 0.1 * 0.1 * 0.18);
  EXPECT_EQ(j["specimens"].get<int>(), 2);
  EXPECT_NEAR(j["density_kg_m3"].get<double>(), (2129.56 + cylinder) / 2, 1e-9);
  EXPECT_NE(read_file(dir / "each.csv").find("B,cylinder"), std::string::npos);
}

TEST(SpecimenCli, RejectsBadInput) {
  {
    TempDir dir;
    expect_rejected(run_tool("mw-specimen", {"--side-mm", "150", "--mass-g", "0", "--out", (dir / "o").string()}),
                    "--mass-g (0 g)", dir);
  }
  {
    TempDir dir;
    expect_rejected(run_tool("mw-specimen", {"--side-mm", "-1", "--mass-g", "7", "--out", (dir / "o").string()}),
                    "--side-mm (-1 mm)", dir);
  }
  // Non-finite mass and length, and the prism's sides.
  for (const auto& [args, needle] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--side-mm", "150", "--mass-g", "nan"}, "--mass-g (nan g)"},
           {{"--side-mm", "150", "--mass-g", "-inf"}, "--mass-g (-inf g)"},
           {{"--side-mm", "inf", "--mass-g", "7000"}, "--side-mm (inf mm)"},
           {{"--shape", "prism", "--length-mm", "0", "--width-mm", "100", "--height-mm", "100", "--mass-g", "7000"},
            "--length-mm (0 mm)"},
           {{"--shape", "cylinder", "--diameter-mm", "nan", "--height-mm", "200", "--mass-g", "3000"},
            "--diameter-mm (nan mm)"}}) {
    TempDir dir;
    SCOPED_TRACE(needle);
    expect_rejected(run_tool("mw-specimen", with(args, {"--out", (dir / "o").string()})), needle, dir);
  }
  {
    TempDir dir;
    expect_rejected(run_tool("mw-specimen", {"--shape", "cylinder", "--diameter-mm", "100", "--mass-g", "7",
                                             "--out", (dir / "o").string()}),
                    "--height-mm", dir);
  }
  TempDir data;
  write_file(data / "bad.csv", "specimen,mass_kg,side_mm\nA,7.2,150\n");
  TempDir out;
  expect_rejected(run_tool("mw-specimen", {"--csv", (data / "bad.csv").string(), "--out", (out / "o").string()}),
                  "unknown column 'mass_kg'", out);
  write_file(data / "nan.csv", "specimen,mass_g,side_mm\nA,7200,abc\n");
  expect_rejected(run_tool("mw-specimen", {"--csv", (data / "nan.csv").string(), "--out", (out / "o").string()}),
                  "nan.csv:2: column 'side_mm'", out);
}

TEST(FromFiles, LabDataTomlAndToolJsonFillOptions) {
  TempDir dir;
  write_file(dir / "upv.toml",
             "[path]\nvalue = 150.0\nunit = \"mm\"\nsource = \"paper\"\ncite = \"s\"\n"
             "[t_p]\nvalue = 35.0\nunit = \"us\"\nsource = \"paper\"\ncite = \"s\"\n"
             "[t_s]\nvalue = 55.1\nunit = \"us\"\nsource = \"paper\"\ncite = \"s\"\n");
  write_file(dir / "density.json",
             "{\"density_kg_m3\": 2129.56, \"unrelated_key\": 1, \"foreign_keys\": [\"unrelated_key\"]}");
  const auto r = run_tool("mw-upv", {"--from", (dir / "density.json").string(), "--from", (dir / "upv.toml").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NEAR(json::parse(r.out)["E_d_GPa"].get<double>(), 36.6714, 1e-4);
  // The command line wins over the files.
  const auto o = run_tool("mw-upv", {"--from", (dir / "density.json").string(), "--from", (dir / "upv.toml").string(),
                                     "--path-mm", "300"});
  EXPECT_NEAR(json::parse(o.out)["v_p_m_s"].get<double>(), 300e-3 / 35e-6, 1e-6);
}

// The --from contract (app/tool.hpp): an entry no option takes is an error, so
// that a renamed key cannot leave an option silently at its default.
const std::string kUpvToml = "[path]\nvalue = 150.0\nunit = \"mm\"\nsource = \"paper\"\ncite = \"s\"\n"
                             "[t_p]\nvalue = 35.0\nunit = \"us\"\nsource = \"paper\"\ncite = \"s\"\n"
                             "[t_s]\nvalue = 55.1\nunit = \"us\"\nsource = \"paper\"\ncite = \"s\"\n";

TEST(FromFiles, ARenamedEntryIsAnErrorNamingEntryAndFile) {
  TempDir dir;
  write_file(dir / "upv.toml", kUpvToml);
  write_file(dir / "density.json", "{\"density_kgm3\": 2129.56}");
  TempDir out;
  const auto r = run_tool("mw-upv", {"--from", (dir / "density.json").string(), "--from", (dir / "upv.toml").string(),
                                     "--density-kg-m3", "2129.56", "--out", (out / "o.json").string()});
  expect_rejected(r, (dir / "density.json").string() + ": entry 'density_kgm3' (--density-kgm3) fills no option of mw-upv",
                  out);
  // In a lab-data file too, and every stray entry is named at once.
  write_file(dir / "extra.toml", kUpvToml + "[t_pp]\nvalue = 1.0\nunit = \"us\"\nsource = \"assumed\"\ncite = \"s\"\n"
                                            "[t_ss]\nvalue = 1.0\nunit = \"us\"\nsource = \"assumed\"\ncite = \"s\"\n");
  expect_rejected(run_tool("mw-upv", {"--from", (dir / "extra.toml").string(), "--density-kg-m3", "2129.56", "--out",
                                      (out / "o.json").string()}),
                  "extra.toml: entries 't_pp' (--t-pp-us), 't_ss' (--t-ss-us) fill no option of mw-upv", out);
}

TEST(FromFiles, ForeignEntriesAreLeftAndRecordedAsIgnored) {
  TempDir dir;
  const std::string db = (dir / "p.sqlite").string();
  // The producer's word (foreign_keys in the file) and the reader's (--from-ignore).
  write_file(dir / "upv.toml", "foreign_keys = [\"frequency\"]\n" + kUpvToml +
                                   "[frequency]\nvalue = 54.0\nunit = \"kHz\"\nsource = \"paper\"\ncite = \"s\"\n");
  write_file(dir / "density.json", "{\"density_kg_m3\": 2129.56, \"mass_g\": 7187.265}");
  const auto r = run_tool("mw-upv", {"--from", (dir / "density.json").string(), "--from", (dir / "upv.toml").string(),
                                     "--from-ignore", "mass_g", "--db", db});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NEAR(json::parse(r.out)["E_d_GPa"].get<double>(), 36.6714, 1e-4);  // what the files fill still arrives
  const auto shown = run_tool("mw-prov", {"--db", db, "show", "1", "--json"});
  ASSERT_EQ(shown.exit_status, 0) << shown.err;
  const auto ignored = json::parse(shown.out)["params"]["from_ignored"];
  EXPECT_EQ(ignored[(dir / "upv.toml").string()], json::array({"frequency"})) << ignored;
  EXPECT_EQ(ignored[(dir / "density.json").string()], json::array({"mass_g"})) << ignored;
  // A declaration that names no entry is stale (the entry was renamed): an error as well.
  TempDir out;
  expect_rejected(run_tool("mw-upv", {"--from", (dir / "density.json").string(), "--from", (dir / "upv.toml").string(),
                                      "--from-ignore", "mass_kg", "--out", (out / "o.json").string()}),
                  "--from-ignore names 'mass_kg', which is an entry of no --from file", out);
  write_file(dir / "stale.json", "{\"density_kg_m3\": 2129.56, \"foreign_keys\": [\"mass_g\"]}");
  expect_rejected(run_tool("mw-upv", {"--from", (dir / "stale.json").string(), "--from", (dir / "upv.toml").string(),
                                      "--out", (out / "o.json").string()}),
                  "stale.json: foreign_keys names 'mass_g', which is not an entry of the file", out);
}

TEST(FromFiles, ABadLabFileIsNamed) {
  TempDir dir;
  write_file(dir / "bad.toml", "[t_p]\nvalue = 35.0\nunit = \"us\"\nsource = \"measured\"\n");
  TempDir out;
  expect_rejected(run_tool("mw-upv", {"--from", (dir / "bad.toml").string(), "--out", (out / "o").string()}),
                  "bad.toml: [t_p] has source 'measured'", out);
}

// Every tool of tools/cli (found there, so a new tool is covered without
// editing this list): --help that explains, --db, --version.
TEST(Help, EveryToolTeachesAndVersions) {
  std::vector<std::string> tools;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(MESOWAVE_SOURCE_DIR) / "tools/cli"))
    if (e.path().extension() == ".cpp" && e.path().stem().string().rfind("mw-", 0) == 0)
      tools.push_back(e.path().stem().string());
  EXPECT_GE(tools.size(), 15u);
  for (const std::string& tool : tools) {
    const auto h = run_tool(tool, {"--help"});
    EXPECT_EQ(h.exit_status, 0) << tool;
    EXPECT_NE(h.out.find("--db"), std::string::npos) << tool;
    EXPECT_NE(h.out.find("Usage: " + tool), std::string::npos) << tool;
    // More than CLI11's option list: a description of what the tool computes before it.
    EXPECT_GT(h.out.find("Usage: "), 40u) << tool << " has no description";
    const auto v = run_tool(tool, {"--version"});
    EXPECT_EQ(v.exit_status, 0) << tool;
    EXPECT_EQ(v.out.rfind(tool + " ", 0), 0u) << v.out;
  }
}
