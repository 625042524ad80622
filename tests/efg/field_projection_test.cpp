// The projection of MLS parameters onto a cut space (efg/field_projection, issue 16) against fields the
// cut space holds exactly. A linear basis reproduces linear fields (MLS consistency, Eqs. 1-12), on each
// side of a crack as well (every point sees only nodes on its side, and still at least 3 of them):
//  - a field linear on each side of a crack across the whole body, with a jump at the crack, is in the cut
//    space: fitting it from parameters that are wrong on every node the cut reaches must give it back to
//    round-off (field and parameters);
//  - a uniform strain u = E x + b is in both spaces: its projection keeps the field and the strain energy
//    1/2 eps.D eps A t (closed form), and so does DynamicCracks when cracks start in a uniform tension with
//    project_fields on (the energy jump and the kinetic energy's change vanish to round-off).
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/efg/dynamic_cracks.hpp"
#include "mesowave/efg/field_projection.hpp"

using namespace mesowave;
using namespace mesowave::efg;

namespace {

const ElasticMaterial2D kConcrete{30e9, 0.2, 1.0, 2400, PlaneState::plane_stress};
const double kL = 0.05, kW = 0.02, kH = 2.5e-3;
// between the node columns (25, 27.5 mm) and the Gauss columns (25.53, 26.97 mm): no point on the line
const double kCrackX = 0.02625;

std::vector<double> point_masses(const ElasticModel& model) {
  std::vector<double> m;
  for (const GaussPoint& g : model.discretisation().points)
    m.push_back(model.material().density_kg_m3 * model.material().thickness_m * g.weight_m2);
  return m;
}

// u_I = G x_I + b for a linear field with gradient G (2 x 2) and offset b
Eigen::VectorXd linear_parameters(const std::vector<Vec2>& nodes, const Eigen::Matrix2d& G, const Eigen::Vector2d& b) {
  Eigen::VectorXd u(Eigen::Index(2 * nodes.size()));
  for (std::size_t i = 0; i < nodes.size(); ++i) u.segment<2>(Eigen::Index(2 * i)) = G * nodes[i] + b;
  return u;
}

}  // namespace

TEST(ParameterProjection, FitsAFieldLinearOnEachSideOfACrackToRoundOff) {
  const Discretisation disc = rectangular_grid({0, 0, kL, kW}, int(kL / kH + 0.5), int(kW / kH + 0.5));
  CrackSet cracks;
  const MlsApproximation mls(disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, 2.5), {}, &cracks);
  ElasticModel model(disc, kConcrete, mls);
  const std::vector<ShapeFunctions> before = model.shape_functions();
  Crack c;
  c.points = {Vec2(kCrackX, -0.5 * kH), Vec2(kCrackX, kW + 0.5 * kH)};
  c.tip_at_start = c.tip_at_end = false;
  cracks.add(c);
  model.update_shape_functions();
  const ParameterProjection p(before, model.shape_functions(), point_masses(model), disc.nodes.size());
  ASSERT_TRUE(p.ok());
  ASSERT_GT(p.changed_points(), 0u);
  ASSERT_GT(p.nodes().size(), 8u);  // the columns either side of the cut
  // on the left -: u = G- x + b-, on the right +: another gradient and a jump at the crack
  Eigen::Matrix2d Gm, Gp;
  Gm << 1e-4, -2e-5, 3e-5, 5e-5;
  Gp << -7e-5, 4e-5, 1e-5, 2e-4;
  const Eigen::Vector2d bm(1e-6, -2e-6), bp(4e-6, 3e-6);
  const auto exact = [&](const Vec2& x) -> Eigen::Vector2d { return x.x() < kCrackX ? Gm * x + bm : Gp * x + bp; };
  Eigen::VectorXd u_exact(Eigen::Index(2 * disc.nodes.size()));
  for (std::size_t i = 0; i < disc.nodes.size(); ++i) u_exact.segment<2>(Eigen::Index(2 * i)) = exact(disc.nodes[i]);
  Eigen::VectorXd start = u_exact;  // wrong on every node of A: the fit must find them
  for (std::int32_t i : p.nodes()) start.segment<2>(2 * i) = Eigen::Vector2d(1e-3, -1e-3);
  const Eigen::VectorXd fitted = p.fit(start, [&](std::int32_t g) { return exact(disc.points[std::size_t(g)].x); });
  double misfit = 0, norm = 0;  // over every Gauss point of the body
  for (std::size_t g = 0; g < disc.points.size(); ++g) {
    const Eigen::Vector2d e = exact(disc.points[g].x);
    misfit += disc.points[g].weight_m2 * (displacement_of(model.shape_functions()[g], fitted) - e).squaredNorm();
    norm += disc.points[g].weight_m2 * e.squaredNorm();
  }
  const double parameters = (fitted - u_exact).norm() / u_exact.norm();
  std::printf("A: %zu nodes, %zu points (%zu changed); relative L2 misfit %.2e, parameters %.2e\n", p.nodes().size(),
              p.points().size(), p.changed_points(), std::sqrt(misfit / norm), parameters);
  EXPECT_LT(std::sqrt(misfit / norm), 1e-12);
  EXPECT_LT(parameters, 1e-11);  // the minimiser is unique (N positive definite): the parameters themselves
}

TEST(ParameterProjection, KeepsAUniformStrainAndItsEnergyAcrossACut) {
  const Discretisation disc = rectangular_grid({0, 0, kL, kW}, int(kL / kH + 0.5), int(kW / kH + 0.5));
  CrackSet cracks;
  const MlsApproximation mls(disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, 2.5), {}, &cracks);
  ElasticModel model(disc, kConcrete, mls);
  const std::vector<ShapeFunctions> before = model.shape_functions();
  Crack c;  // an edge crack from the bottom to mid-height: a tip inside, the field continuous around it
  c.points = {Vec2(kCrackX, -0.5 * kH), Vec2(kCrackX, 0.55 * kW)};
  c.tip_at_start = false;
  c.tip_at_end = true;
  cracks.add(c);
  model.update_shape_functions();
  const ParameterProjection p(before, model.shape_functions(), point_masses(model), disc.nodes.size());
  ASSERT_TRUE(p.ok());
  ASSERT_GT(p.changed_points(), 0u);
  Eigen::Matrix2d G;  // eps_xx = 1e-4, eps_yy = -2e-5, gamma_xy = 3e-5 + 1e-5
  G << 1e-4, 3e-5, 1e-5, -2e-5;
  const Eigen::VectorXd u = linear_parameters(disc.nodes, G, Eigen::Vector2d(2e-6, -1e-6));
  const Eigen::VectorXd projected = p.project(u);
  const Eigen::Vector3d eps(G(0, 0), G(1, 1), G(0, 1) + G(1, 0));
  const double energy_exact = 0.5 * eps.dot(model.D() * eps) * kL * kW * kConcrete.thickness_m;
  const double energy = 0.5 * projected.dot(model.internal_force(projected));
  std::printf("relative misfit %.2e, energy %.12g J against 1/2 eps.D eps A t = %.12g J\n",
              std::sqrt(p.relative_misfit(u, projected)), energy, energy_exact);
  EXPECT_LT(std::sqrt(p.relative_misfit(u, projected)), 1e-12);
  EXPECT_NEAR(energy, energy_exact, 1e-11 * energy_exact);
}

// DynamicCracks with project_fields: every Gauss point above f_t in a uniform tension sigma_xx (states set
// by hand), so cracks start across the strip at the first advance; u and v are uniform-strain fields, so
// each change's projection must keep them: misfits at round-off, the energy jump (strain + faces +
// kinetic) ~ 0 against the strain energy, which stays the closed form.
TEST(ParameterProjection, DynamicCracksKeepAUniformFieldWhileCracksStart) {
  const Discretisation disc = rectangular_grid({0, 0, kL, kW}, int(kL / kH + 0.5), int(kW / kH + 0.5));
  CrackSet cracks;
  const MlsApproximation mls(disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, 2.5), {}, &cracks);
  ElasticModel model(disc, kConcrete, mls);
  DynamicCrackOptions co;
  co.cohesive.f_t_Pa = 3e6;
  co.cohesive.G_f_J_m2 = 100;
  co.strain_rate_effect = false;
  co.project_fields = FieldProjection::displacement_and_velocity;
  DynamicCracks dc(model, cracks, co);
  Eigen::Matrix2d G, Gv;  // sigma_xx = E eps_xx / (1 - nu^2) = 3.9 MPa > f_t (plane stress, eps_yy = 0)
  G << 1.25e-4, 0, 0, 0;
  Gv << 2.0, 0.5, 0.5, -1.0;  // a strain-rate field [1/s]
  Eigen::VectorXd u = linear_parameters(disc.nodes, G, Eigen::Vector2d(1e-6, 0));
  Eigen::VectorXd v = linear_parameters(disc.nodes, Gv, Eigen::Vector2d(0.1, -0.2));
  const Eigen::VectorXd u0 = u, v0 = v;
  std::vector<PointState> states(disc.points.size());
  for (std::size_t g = 0; g < states.size(); ++g) {
    states[g].strain = model.strain_at_point(g, u);
    states[g].stress = model.D() * states[g].strain;
  }
  const Eigen::Vector3d eps(G(0, 0), G(1, 1), G(0, 1) + G(1, 0));
  const double energy_exact = 0.5 * eps.dot(model.D() * eps) * kL * kW * kConcrete.thickness_m;
  ASSERT_TRUE(dc.advance(1e-6, u, v, states));
  ASSERT_FALSE(dc.projections().empty());
  double worst_u = 0, worst_v = 0;
  for (const auto& p : dc.projections()) {
    EXPECT_TRUE(p.ok);
    worst_u = std::max(worst_u, std::sqrt(p.misfit_u));
    worst_v = std::max(worst_v, std::sqrt(p.misfit_v));
  }
  const double energy = 0.5 * u.dot(model.internal_force(u));
  std::printf("%zu cracks, %zu projections (%zu refused changes); misfit u %.2e v %.2e; energy %.12g J (exact %.12g), "
              "jump %.2e J (kinetic %.2e J); max |u' - u| / max |u| %.2e\n",
              dc.cracks().cracks().size(), dc.projections().size(), dc.refused().size(), worst_u, worst_v, energy, energy_exact,
              dc.energy_jump_J(), dc.kinetic_jump_J(), (u - u0).cwiseAbs().maxCoeff() / u0.cwiseAbs().maxCoeff());
  EXPECT_GE(dc.cracks().cracks().size(), 2u);
  EXPECT_LT(worst_u, 1e-12);
  EXPECT_LT(worst_v, 1e-12);
  EXPECT_NEAR(energy, energy_exact, 1e-11 * energy_exact);
  // the faces are born closed (w_birth) on a continuous field: no stored or dissipated energy, no jump
  EXPECT_LT(std::abs(dc.energy_jump_J()), 1e-11 * energy_exact);
  EXPECT_LT((u - u0).cwiseAbs().maxCoeff(), 1e-11 * u0.cwiseAbs().maxCoeff());
  EXPECT_LT((v - v0).cwiseAbs().maxCoeff(), 1e-11 * v0.cwiseAbs().maxCoeff());
}
