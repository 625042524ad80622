// The Q4 plane static solver (fem/plane_static) against independent references: the patch test
// (a linear displacement field is reproduced exactly, also on distorted elements, and a uniform
// traction gives a uniform stress), the Timoshenko & Goodier cantilever with its convergence order,
// the notch (a traction-free slit: the mesh splits there, reactions balance the load) and bad input.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>

#include "mesowave/efg/beam_theory.hpp"
#include "mesowave/efg/cantilever.hpp"
#include "mesowave/fem/plane_static.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::fem;
using Vec2 = Eigen::Vector2d;

namespace {

// Plane stress D written out here (the reference, not the library's).
Eigen::Matrix3d plane_stress_D(double E, double nu) {
  Eigen::Matrix3d D;
  D << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
  return D * E / (1 - nu * nu);
}

}  // namespace

TEST(PlaneStatic, PatchTestLinearFieldIsExactOnDistortedElements) {
  // u = a + B x prescribed on the boundary; the interior nodes, moved off the grid, must follow it.
  PlaneStaticProblem p;
  p.mesh = structured_plane_mesh({0, 0, 2.0, 1.0, 4, 3});
  p.D = plane_stress_D(30e9, 0.2);
  p.thickness_m = 0.1;
  Eigen::Matrix2d G;
  G << 1e-3, 2e-4, -5e-4, 3e-4;
  const Vec2 a(1e-4, -2e-4);
  const double dx = 0.5, dy = 1.0 / 3;
  for (auto& x : p.mesh.nodes) {
    const bool boundary = x.x() < 1e-9 || x.x() > 2 - 1e-9 || x.y() < 1e-9 || x.y() > 1 - 1e-9;
    if (!boundary) x += Vec2(0.23 * dx * std::sin(7 * x.x() + 3 * x.y()), 0.21 * dy * std::cos(5 * x.x() - x.y()));
  }
  for (const auto& x : p.mesh.nodes) {
    const bool boundary = x.x() < 1e-9 || x.x() > 2 - 1e-9 || x.y() < 1e-9 || x.y() > 1 - 1e-9;
    if (!boundary) continue;
    const Vec2 u = a + G * x;
    p.constraints.push_back({x, 0, u.x(), "boundary"});
    p.constraints.push_back({x, 1, u.y(), "boundary"});
  }
  const auto s = solve_plane_static(p);
  double worst = 0;
  for (std::size_t n = 0; n < p.mesh.nodes.size(); ++n)
    worst = std::max(worst, (s.u_m.segment<2>(2 * Eigen::Index(n)) - (a + G * p.mesh.nodes[n])).norm());
  EXPECT_LT(worst / G.norm(), 1e-10);
  // Constant strain in every element: nodal stresses equal D eps everywhere.
  const Eigen::Vector3d eps(G(0, 0), G(1, 1), G(0, 1) + G(1, 0));
  const Eigen::Vector3d sigma = p.D * eps;
  for (const auto& st : plane_nodal_stress(p.mesh, p.D, s.u_m)) EXPECT_LT((st - sigma).norm() / sigma.norm(), 1e-10);
}

TEST(PlaneStatic, PatchTestUniformTractionGivesUniformStress) {
  // sigma_xx = 2 MPa from a traction on the right edge, the left edge on rollers, one pin.
  PlaneStaticProblem p;
  p.mesh = structured_plane_mesh({0, 0, 3.0, 1.0, 6, 4});
  const double E = 20e9, nu = 0.25, t = 0.05, s0 = 2e6;
  p.D = plane_stress_D(E, nu);
  p.thickness_m = t;
  for (auto n : p.mesh.nodes_on_segment({0, 0}, {0, 1})) p.constraints.push_back({p.mesh.nodes[std::size_t(n)], 0, 0, "roller"});
  p.constraints.push_back({{0, 0}, 1, 0, "pin"});
  p.edge_loads.push_back({{3, 0}, {3, 1}, [&](const Vec2&) { return Vec2(s0, 0); }});
  const auto s = solve_plane_static(p);
  for (const auto& x : p.mesh.nodes) {
    const Vec2 u = plane_displacement(p.mesh, s.u_m, x);
    EXPECT_NEAR(u.x(), s0 / E * x.x(), 1e-10 * s0 / E * 3);
    EXPECT_NEAR(u.y(), -nu * s0 / E * x.y(), 1e-10 * s0 / E * 3);
  }
  EXPECT_LT((plane_stress(p.mesh, p.D, s.u_m, {1.7, 0.4}) - Eigen::Vector3d(s0, 0, 0)).norm(), 1e-9 * s0);
  double reaction = 0;
  for (std::size_t c = 0; c + 1 < p.constraints.size(); ++c) reaction += s.reactions_N[c];
  EXPECT_NEAR(reaction, -s0 * 1.0 * t, 1e-9 * s0 * t);
}

TEST(PlaneStatic, TimoshenkoCantileverConvergesWithOrderTwo) {
  // efg/cantilever's Q4 run: the clamp holds the closed form's displacements at the nodes of
  // x = 0, the end carries its traction; errors over the elements with 4 x 4 Gauss points.
  const efg::CantileverBeam beam;
  efg::CantileverOptions options;
  options.error_gauss = 4;
  std::vector<double> err_u, err_e;
  for (int k : {1, 2, 4, 8}) {
    options.cells_x = 8 * k;
    options.cells_y = 2 * k;
    const auto r = efg::run_fem_cantilever(beam, options);
    err_u.push_back(r.errors.displacement_L2);
    err_e.push_back(r.errors.energy);
  }
  for (std::size_t i = 1; i < err_u.size(); ++i) {
    const double order_u = std::log2(err_u[i - 1] / err_u[i]), order_e = std::log2(err_e[i - 1] / err_e[i]);
    EXPECT_GT(order_u, 1.8) << "refinement " << i;  // Q4: h^2 in L2, h in energy
    EXPECT_LT(order_u, 2.3) << "refinement " << i;
    EXPECT_GT(order_e, 0.9) << "refinement " << i;
    std::printf("h/%d: displacement L2 %.3e (order %.2f), energy %.3e (order %.2f)\n", 1 << i, err_u[i], order_u,
                err_e[i], order_e);
  }
  EXPECT_LT(err_u.back(), 5e-3);
}

TEST(PlaneStatic, CantileverErrorsOfTheExactFieldAreZero) {
  // The error measure itself: the closed form against itself gives 0, a 1 % scaled field 1 %.
  const efg::CantileverBeam beam;
  auto u = [&](const Vec2& x) { return Vec2(1.01 * beam.at(x).u_m); };
  auto s = [&](const Vec2& x) { return Eigen::Vector3d(beam.at(x).stress_Pa); };
  const auto e = efg::cantilever_errors(beam, u, s, 4, 2, 5);
  EXPECT_NEAR(e.displacement_L2, 0.01, 1e-12);
  EXPECT_NEAR(e.energy, 0.0, 1e-12);
  EXPECT_NEAR(e.tip_deflection, 0.01, 1e-12);
}

TEST(PlaneStatic, NotchIsATractionFreeSlit) {
  // A simply supported beam with a central notch half its depth, loaded at the top centre: the
  // notch faces separate (the slit opens at the bottom) and the supports carry the load.
  PlaneStaticProblem p;
  const double L = 0.5, D = 0.1;
  p.mesh = structured_plane_mesh({0, 0, L, D, 20, 8, L / 2, D / 2});
  EXPECT_EQ(p.mesh.nodes.size(), std::size_t(21 * 9 + 4));  // 4 nodes below the tip doubled
  p.D = plane_stress_D(20e9, 0.2);
  p.thickness_m = 0.1;
  p.constraints = {{{0.025, 0}, 1, 0, "left support"}, {{0.475, 0}, 1, 0, "right support"}, {{0.025, 0}, 0, 0, "pin"}};
  p.point_loads.push_back({{L / 2, D}, {0, -1000}});
  const auto s = solve_plane_static(p);
  const auto left = p.mesh.node_at({L / 2, 0}, "mouth"), right = std::int32_t(21 * 9);  // first copy: bottom
  const double opening = s.u_m(2 * right) - s.u_m(2 * left);
  EXPECT_GT(opening, 0);
  EXPECT_NEAR(s.reactions_N[0] + s.reactions_N[1], 1000, 1e-8);
  EXPECT_NEAR(s.reactions_N[0], 500, 1e-6);  // symmetry
  // A notched beam is softer than the plain one.
  PlaneStaticProblem plain = p;
  plain.mesh = structured_plane_mesh({0, 0, L, D, 20, 8});
  const auto sp = solve_plane_static(plain);
  const auto top = p.mesh.node_at({L / 2, D}, "load");
  EXPECT_LT(s.u_m(2 * top + 1), sp.u_m(2 * top + 1));
}

TEST(PlaneStatic, BadInputNamesTheValue) {
  using test::input_error_of;
  EXPECT_NE(input_error_of([] { structured_plane_mesh({0, 0, 1, 1, 0, 2}); }).find("0 x 2"), std::string::npos);
  EXPECT_NE(input_error_of([] { structured_plane_mesh({0, 0, 1, 0.1, 10, 4, 0.5, 0.1}); }).find("notch depth 0.1"),
            std::string::npos);
  EXPECT_NE(input_error_of([] { structured_plane_mesh({0, 0, 1, 0.1, 10, 4, 1.5, 0.05}); }).find("x = 1.5"),
            std::string::npos);
  EXPECT_NE(input_error_of([] { structured_plane_mesh({0, 0, 1, 0.1, 10, 4, 0.53, 0.05}); }).find("mesh lines"),
            std::string::npos);
  PlaneStaticProblem p;
  p.mesh = structured_plane_mesh({0, 0, 1, 1, 2, 2});
  p.D = plane_stress_D(1e9, 0.2);
  p.thickness_m = 1;
  p.constraints = {{{0, 0}, 0, 0, "a"}, {{0, 0}, 1, 0, "b"}};  // rotation free
  EXPECT_NE(input_error_of([&] { solve_plane_static(p); }).find("rigid-body"), std::string::npos);
  p.constraints.push_back({{0.3, 0}, 1, 0, "c"});
  EXPECT_NE(input_error_of([&] { solve_plane_static(p); }).find("constraint c at (0.3, 0)"), std::string::npos);
}
