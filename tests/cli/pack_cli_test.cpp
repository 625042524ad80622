// mw-pack end to end: a small box and the rod line succeed with the right
// numbers; bad input fails with one clear line and writes nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "mesowave/dem/packing/packing_file.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using mesowave::test::count_files;
using mesowave::test::run_tool;
using mesowave::test::TempDir;
using mesowave::test::write_file;

namespace {

std::vector<std::string> small_box(const TempDir& dir) {
  return {"box", "--cube-side-mm", "8", "--porosity-pct", "7", "--d-min-mm", "1.6", "--d-max-mm", "2",
          "--packing", (dir / "p.h5").string(), "--quiet"};
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// Runs mw-pack expecting exit 1, one "error: ..." line naming `words`, and no file written.
void expect_refused(const TempDir& dir, const std::vector<std::string>& args, const std::string& words) {
  const std::size_t before = count_files(dir.path());
  const auto r = run_tool("mw-pack", args);
  EXPECT_EQ(r.exit_status, 1) << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
  EXPECT_EQ(count_files(dir.path()), before) << r.err;
}

}  // namespace

TEST(PackCli, SmallBoxWithDensity) {
  TempDir dir;
  const auto r = run_tool("mw-pack", with(small_box(dir), {"--density-kg-m3", "2129.56", "--seed", "3", "--export-yade",
                                                            (dir / "p.txt").string(), "--out", (dir / "p.json").string()}));
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["porosity_pct"].get<double>(), 7.0, 1e-9);
  EXPECT_EQ(j["spheres_outside"].get<int>(), 0);
  EXPECT_EQ(j["seed"].get<int>(), 3);
  // rho_p = rho / (1 - p) for a box filled to porosity p.
  EXPECT_NEAR(j["particle_density_kg_m3"].get<double>(), 2129.56 / 0.93, 1e-6);
  const auto p = dem::read_packing_file(dir / "p.h5");
  EXPECT_EQ(p.size(), j["spheres"].get<std::size_t>());
  EXPECT_NEAR(p.particle_density_kg_m3, 2129.56 / 0.93, 1e-6);
  EXPECT_FALSE(dem::read_packing_origin(dir / "p.h5").empty());
  // The Yade export imports back to the same spheres.
  const auto back = run_tool("mw-pack", {"import", (dir / "p.txt").string(), "--lower-mm", "0", "0", "0", "--upper-mm", "8",
                                         "8", "8", "--packing", (dir / "q.h5").string()});
  ASSERT_EQ(back.exit_status, 0) << back.err;
  const auto q = dem::read_packing_file(dir / "q.h5");
  EXPECT_EQ(q.centres_m, p.centres_m);
  EXPECT_EQ(q.radii_m, p.radii_m);
  EXPECT_NEAR(nlohmann::json::parse(back.out)["porosity_pct"].get<double>(), 7.0, 1e-9);
}

TEST(PackCli, RodLine) {
  TempDir dir;
  const auto r = run_tool("mw-pack", {"line", "--sphere-radius-mm", "5.1", "--spacing-R", "1.03", "--length-mm", "1000",
                                      "--rod-diameter-mm", "10.2", "--density-kg-m3", "7850.66", "--packing",
                                      (dir / "rod.h5").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["spheres"].get<int>(), 191);  // rod paper, Table 1
  EXPECT_NEAR(j["particle_density_kg_m3"].get<double>() / 6044.37, 1.0, 1e-4);
}

TEST(PackCli, RefusesBadSizes) {
  TempDir dir;
  expect_refused(dir, {"box", "--cube-side-mm", "8", "--porosity-pct", "7", "--d-min-mm", "-1.6", "--d-max-mm", "2",
                       "--packing", (dir / "p.h5").string()},
                 "--d-min-mm");
  expect_refused(dir, {"box", "--cube-side-mm", "8", "--porosity-pct", "7", "--d-min-mm", "2.2", "--d-max-mm", "2",
                       "--packing", (dir / "p.h5").string()},
                 "exceeds --d-max-mm");
  expect_refused(dir, {"box", "--cube-side-mm", "-8", "--porosity-pct", "7", "--d-min-mm", "1.6", "--d-max-mm", "2",
                       "--packing", (dir / "p.h5").string()},
                 "--cube-side-mm");
  expect_refused(dir, {"box", "--cube-side-mm", "1.5", "--porosity-pct", "7", "--d-min-mm", "1.6", "--d-max-mm", "2",
                       "--packing", (dir / "p.h5").string()},
                 "cannot hold a sphere");
}

TEST(PackCli, RefusesBadPorosity) {
  TempDir dir;
  for (const char* p : {"0", "100", "-3", "150"})
    expect_refused(dir, {"box", "--cube-side-mm", "8", "--porosity-pct", p, "--d-min-mm", "1.6", "--d-max-mm", "2",
                         "--packing", (dir / "p.h5").string()},
                   "--porosity-pct");
  // Unreachable: 99.99 % of a 2 mm cube leaves less solid than one sphere.
  expect_refused(dir, {"box", "--cube-side-mm", "2", "--porosity-pct", "99.99", "--d-min-mm", "1.6", "--d-max-mm", "2",
                       "--packing", (dir / "p.h5").string()},
                 "less solid than one sphere");
  expect_refused(dir, {"box", "--cube-side-mm", "8", "--d-min-mm", "1.6", "--d-max-mm", "2", "--packing",
                       (dir / "p.h5").string()},
                 "--porosity-pct");
}

TEST(PackCli, RefusesBadSpacing) {
  TempDir dir;
  for (const char* s : {"0", "-1"})
    expect_refused(dir, {"line", "--sphere-radius-mm", "5.1", "--spacing-R", s, "--length-mm", "1000", "--packing",
                         (dir / "rod.h5").string()},
                   "--spacing-R");
  expect_refused(dir, {"line", "--sphere-radius-mm", "5.1", "--spacing-mm", "0", "--length-mm", "1000", "--packing",
                       (dir / "rod.h5").string()},
                 "--spacing-mm");
  expect_refused(dir, {"line", "--sphere-radius-mm", "5.1", "--length-mm", "1000", "--packing", (dir / "rod.h5").string()},
                 "spacing");
}

TEST(PackCli, RefusesMalformedImports) {
  TempDir dir;
  write_file(dir / "bad.txt", "#format x_y_z_r\n0 0 0 0.001\n0.1 0.2 oops 0.001\n");
  expect_refused(dir, {"import", (dir / "bad.txt").string(), "--packing", (dir / "p.h5").string()},
                 "bad.txt:3: 'oops' is not a finite number");
  write_file(dir / "short.txt", "0 0 0\n");
  expect_refused(dir, {"import", (dir / "short.txt").string(), "--packing", (dir / "p.h5").string()}, "short.txt:1");
  write_file(dir / "nounit.csv", "x,y,z,r\n1,2,3,1\n");
  expect_refused(dir, {"import", (dir / "nounit.csv").string(), "--packing", (dir / "p.h5").string()}, "units go in the name");
  write_file(dir / "negative.csv", "x_mm,y_mm,z_mm,r_mm\n1,2,3,-1\n");
  expect_refused(dir, {"import", (dir / "negative.csv").string(), "--packing", (dir / "p.h5").string()}, "not positive");
  write_file(dir / "empty.txt", "# nothing here\n");
  expect_refused(dir, {"import", (dir / "empty.txt").string(), "--packing", (dir / "p.h5").string()}, "no spheres");
  expect_refused(dir, {"import", (dir / "missing.txt").string(), "--packing", (dir / "p.h5").string()}, "missing.txt");
}

TEST(PackCli, RefusesBadSieveCurve) {
  TempDir dir;
  write_file(dir / "sieve.csv", "d_mm,passing_pct\n1,50\n2,40\n");
  expect_refused(dir, {"box", "--cube-side-mm", "8", "--porosity-pct", "7", "--sieve-curve", (dir / "sieve.csv").string(),
                       "--packing", (dir / "p.h5").string()},
                 "decreases");
}
