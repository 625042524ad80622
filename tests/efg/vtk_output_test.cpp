// The EFG's ParaView snapshots read back by VTK's own XML reader (scripts/check-vtk, Debian
// python3-vtk9 - the reader ParaView uses): the .pvd's steps and parts, the node and crack counts,
// every array with its components and its values' range. Fails, saying what to install, when VTK
// is missing: a snapshot nobody could open must not pass.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "mesowave/efg/vtk_output.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

json check_vtk(const fs::path& file) {
  const auto r = test::run_command(fs::path(MESOWAVE_SOURCE_DIR) / "scripts/check-vtk", {file.string()});
  if (r.exit_status == 2) ADD_FAILURE() << "VTK's Python module is missing: run scripts/install-deps\n" << r.err;
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  return r.exit_status == 0 ? json::parse(r.out) : json::array();
}

// A 3 x 2 grid of nodes, displaced and stressed by simple known fields; two crack polylines.
efg::NodeSnapshot nodes(double scale) {
  efg::NodeSnapshot n;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector2d x(0.1 * i, 0.05 * j);
      n.positions_m.push_back(x);
      n.displacement_m.push_back(scale * Eigen::Vector2d(1e-5 * x.x(), -2e-5 * x.x()));
      n.stress_Pa.push_back(scale * Eigen::Vector3d(1e6 * (i + 1), -5e5, 2e5));
    }
  return n;
}

}  // namespace

TEST(VtkOutput, SeriesIsReadBackByVtk) {
  test::TempDir dir;
  efg::VtkSeries series(dir.path(), "beam");
  efg::CrackSnapshot cracks;
  cracks.polylines = {{{0.1, 0.0}, {0.1, 0.02}, {0.1, 0.03}}, {{0.2, 0.0}, {0.21, 0.01}}};
  cracks.opening_m = {2e-5, 1e-5, 3e-6};
  cracks.traction_Pa = {0.5e6, 1.2e6, 2.0e6};
  cracks.damage = {0.8, 0.5, 0.0};
  series.add(0.0, nodes(0.0), efg::CrackSnapshot{});
  series.add(1e-4, nodes(1.0), cracks);
  const fs::path pvd = series.finish();
  EXPECT_EQ(pvd, dir / "beam.pvd");

  const json all = check_vtk(pvd);
  ASSERT_EQ(all.size(), 1u);
  const json& sets = all[0]["datasets"];
  ASSERT_EQ(sets.size(), 4u);  // two steps x (nodes, cracks)
  EXPECT_EQ(sets[2]["timestep"], 1e-4);
  EXPECT_EQ(sets[2]["part"], 0);
  EXPECT_EQ(sets[3]["part"], 1);

  const json& n = sets[2];
  EXPECT_EQ(n["type"], "vtkPolyData");
  EXPECT_EQ(n["points"], 6);
  EXPECT_EQ(n["verts"], 6);
  EXPECT_DOUBLE_EQ(n["time"].get<double>(), 1e-4);
  EXPECT_DOUBLE_EQ(n["bounds"][1].get<double>(), 0.2);
  EXPECT_DOUBLE_EQ(n["bounds"][3].get<double>(), 0.05);
  const json& u = n["point_data"]["displacement"];
  EXPECT_EQ(u["components"], 3);
  EXPECT_NEAR(u["range"][1].get<double>(), std::hypot(2e-6, 4e-6), 1e-14);  // largest magnitude
  const json& s = n["point_data"]["stress"];
  EXPECT_EQ(s["components"], 6);
  EXPECT_EQ(s["tuples"], 6);
  // The largest principal stress of (3e6, -5e5, 2e5): the 2 x 2 eigenvalue, written out.
  const double c = 0.5 * (3e6 - 5e5), r = std::hypot(0.5 * (3e6 + 5e5), 2e5);
  EXPECT_NEAR(n["point_data"]["max_principal_stress"]["range"][1].get<double>(), c + r, 1e-8 * (c + r));  // %.9g

  const json& k = sets[3];
  EXPECT_EQ(k["points"], 5);
  EXPECT_EQ(k["lines"], 3);
  // the crack's cell data in the units its name says: 2e-5 m = 0.02 mm, 0.5e6 Pa = 0.5 MPa
  EXPECT_EQ(k["cell_data"]["opening_mm"]["tuples"], 3);
  EXPECT_DOUBLE_EQ(k["cell_data"]["opening_mm"]["range"][0].get<double>(), 3e-3);
  EXPECT_DOUBLE_EQ(k["cell_data"]["opening_mm"]["range"][1].get<double>(), 2e-2);
  EXPECT_DOUBLE_EQ(k["cell_data"]["traction_MPa"]["range"][0].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(k["cell_data"]["traction_MPa"]["range"][1].get<double>(), 2.0);
  EXPECT_EQ(k["cell_data"]["damage"]["tuples"], 3);
  EXPECT_DOUBLE_EQ(k["cell_data"]["damage"]["range"][1].get<double>(), 0.8);
  EXPECT_EQ(sets[1]["points"], 0);  // no crack yet: an empty but valid file
}

TEST(VtkOutput, CheckerRejectsABrokenFile) {
  // The reader's verdict is not a formality: a truncated file fails.
  test::TempDir dir;
  efg::write_node_vtp(dir / "n.vtp", nodes(1.0), 0.0);
  const std::string text = test::read_file(dir / "n.vtp");
  test::write_file(dir / "broken.vtp", text.substr(0, text.size() / 2));
  const auto r = test::run_command(fs::path(MESOWAVE_SOURCE_DIR) / "scripts/check-vtk", {(dir / "broken.vtp").string()});
  EXPECT_EQ(r.exit_status, 1) << r.out << r.err;
}

TEST(VtkOutput, MismatchedArraysAreRefused) {
  test::TempDir dir;
  auto n = nodes(1.0);
  n.stress_Pa.pop_back();
  EXPECT_THROW(efg::write_node_vtp(dir / "n.vtp", n, 0.0), std::invalid_argument);
  efg::CrackSnapshot c;
  c.polylines = {{{0, 0}, {0, 1}}};
  c.opening_m = {1, 2};
  EXPECT_THROW(efg::write_crack_vtp(dir / "c.vtp", c, 0.0), std::invalid_argument);
  c.opening_m = {1};
  c.damage = {0.1, 0.2};
  EXPECT_THROW(efg::write_crack_vtp(dir / "c.vtp", c, 0.0), std::invalid_argument);
}

// The third part (the blasted slab's Gauss points): scalar arrays read back by VTK with their range; a
// series that gives points at one step and not at another is refused.
TEST(VtkOutput, PointPartIsReadBackByVtk) {
  test::TempDir dir;
  efg::VtkSeries series(dir.path(), "slab");
  efg::PointCloudSnapshot p;
  p.positions_m = {{0.0, 0.0}, {0.1, 0.05}, {0.2, 0.1}};
  p.scalars = {{"min_eps_v", {-0.02, -0.001, 0.0}}, {"compacted", {1, 0, 0}}};
  series.add(2e-5, nodes(1.0), efg::CrackSnapshot{}, &p);
  const json all = check_vtk(series.finish());
  ASSERT_EQ(all.size(), 1u);
  const json& sets = all[0]["datasets"];
  ASSERT_EQ(sets.size(), 3u);
  EXPECT_EQ(sets[2]["part"], 2);
  EXPECT_EQ(sets[2]["points"], 3);
  EXPECT_DOUBLE_EQ(sets[2]["point_data"]["min_eps_v"]["range"][0].get<double>(), -0.02);
  EXPECT_DOUBLE_EQ(sets[2]["point_data"]["compacted"]["range"][1].get<double>(), 1.0);
  EXPECT_THROW(series.add(3e-5, nodes(1.0), efg::CrackSnapshot{}), std::invalid_argument);
  p.scalars[0].second.pop_back();
  EXPECT_THROW(efg::write_point_vtp(dir / "p.vtp", p, 0.0), std::invalid_argument);
}
