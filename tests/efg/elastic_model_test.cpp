// The assembled EFG equilibrium of Eqs. (14)-(18) against what any consistent discretisation must
// give, independent of the MLS details: K symmetric with the rigid-body motions in its null space,
// the strain energy of a linear field equal to its closed form (MLS reproduces linear fields, the
// strain is then constant and the cell weights sum to the area), K u equal to the pointwise internal
// force, loads whose resultant and moment equal the applied ones, the same bits for any thread count,
// and the cache following the CrackSet.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/LU>
#include <cstring>
#include <random>

#include "mesowave/efg/elastic_model.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

namespace {

const ElasticMaterial2D kConcrete{20e9, 0.2, 0.1, 2400, PlaneState::plane_stress};

struct Fixture {
  Discretisation disc;
  MlsApproximation mls;
  ElasticModel model;
  explicit Fixture(Discretisation d, double scale = 2.5, const CrackSet* cracks = nullptr)
      : disc(std::move(d)),
        mls(disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, scale), MlsOptions{}, cracks),
        model(disc, kConcrete, mls) {}
};

// Nodal parameters of the linear field u(x) = a + G x (exactly reproduced: u^h = u).
Eigen::VectorXd linear_field(const std::vector<Vec2>& nodes, const Eigen::Vector2d& a, const Eigen::Matrix2d& G) {
  Eigen::VectorXd u(2 * Eigen::Index(nodes.size()));
  for (std::size_t i = 0; i < nodes.size(); ++i) u.segment<2>(2 * Eigen::Index(i)) = a + G * nodes[i];
  return u;
}

}  // namespace

TEST(ElasticModel, StiffnessIsSymmetricWithRigidModesInItsNullSpace) {
  Fixture f(rectangular_grid({0, 0, 0.2, 0.1}, 8, 4));
  const Eigen::SparseMatrix<double> K = f.model.stiffness();
  ASSERT_EQ(K.rows(), Eigen::Index(f.model.dof_count()));
  const Eigen::SparseMatrix<double> asym = K - Eigen::SparseMatrix<double>(K.transpose());
  EXPECT_LE(asym.cwiseAbs().sum(), 1e-14 * K.cwiseAbs().sum());
  Eigen::Matrix2d rotation;
  rotation << 0, -1, 1, 0;
  for (const Eigen::VectorXd& mode : {linear_field(f.disc.nodes, {1, 0}, Eigen::Matrix2d::Zero()),
                                      linear_field(f.disc.nodes, {0, 1}, Eigen::Matrix2d::Zero()),
                                      linear_field(f.disc.nodes, {0, 0}, rotation)})
    EXPECT_LE((K * mode).norm(), 1e-9 * K.cwiseAbs().sum() / double(K.rows()) * mode.norm());
}

TEST(ElasticModel, LinearFieldHasTheClosedFormEnergyAndStrain) {
  Discretisation d = rectangular_grid({0, 0, 0.2, 0.1}, 8, 4, 2, {Vec2(0.101, 0.052), Vec2(0.033, 0.071)});
  Fixture f(std::move(d));
  Eigen::Matrix2d G;
  G << 1e-3, 4e-4, -2e-4, -3e-4;
  const Eigen::VectorXd u = linear_field(f.disc.nodes, {1e-5, -2e-5}, G);
  const Eigen::Vector3d eps(G(0, 0), G(1, 1), G(0, 1) + G(1, 0));
  const double energy = 0.5 * u.dot(f.model.stiffness() * u);
  const double exact = 0.5 * eps.dot(kConcrete.D() * eps) * 0.2 * 0.1 * kConcrete.thickness_m;
  EXPECT_NEAR(energy, exact, 1e-9 * exact);
  for (const Vec2& x : {Vec2(0.0, 0.0), Vec2(0.137, 0.0291), Vec2(0.2, 0.1)}) {
    EXPECT_LE((f.model.strain(x, u) - eps).norm(), 1e-10 * eps.norm());
    EXPECT_LE((f.model.stress(x, u) - kConcrete.D() * eps).norm(), 1e-10 * (kConcrete.D() * eps).norm());
    EXPECT_LE((f.model.displacement(x, u) - (Eigen::Vector2d(1e-5, -2e-5) + G * x)).norm(), 1e-15);
  }
  for (std::size_t p = 0; p < f.disc.points.size(); p += 17)
    EXPECT_LE((f.model.strain_at_point(p, u) - eps).norm(), 1e-10 * eps.norm());
}

TEST(ElasticModel, InternalForceIsKTimesU) {
  Fixture f(rectangular_grid({0, 0, 0.2, 0.1}, 6, 3, 3));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1e-4, 1e-4);
  Eigen::VectorXd u(Eigen::Index(f.model.dof_count()));
  for (Eigen::Index i = 0; i < u.size(); ++i) u[i] = uniform(rng);
  const Eigen::VectorXd Ku = f.model.stiffness() * u;
  EXPECT_LE((f.model.internal_force(u) - Ku).norm(), 1e-12 * Ku.norm());
}

TEST(ElasticModel, LoadsHaveTheAppliedResultantAndMoment) {
  Fixture f(rectangular_grid({0, 0, 0.2, 0.1}, 8, 4));
  const auto resultant = [&](const Eigen::VectorXd& load) {
    Eigen::Vector3d r = Eigen::Vector3d::Zero();  // (F_x, F_y, M_z about the origin)
    for (std::size_t i = 0; i < f.disc.nodes.size(); ++i) {
      const Eigen::Vector2d fi = load.segment<2>(2 * Eigen::Index(i));
      r += Eigen::Vector3d(fi.x(), fi.y(), f.disc.nodes[i].x() * fi.y() - f.disc.nodes[i].y() * fi.x());
    }
    return r;
  };
  // A linear traction t_y = q (1 + y / 0.1) on the edge x = 0.2: F_y = 1.5 q 0.1 t, M = 0.2 F_y.
  const double q = 1e5, t = kConcrete.thickness_m;
  const Eigen::Vector3d r = resultant(f.model.traction_load(
      {Vec2(0.2, 0), Vec2(0.2, 0.1)}, [&](const Vec2& x) { return Eigen::Vector2d(0, q * (1 + x.y() / 0.1)); }));
  EXPECT_NEAR(r[0], 0, 1e-9);
  EXPECT_NEAR(r[1], 1.5 * q * 0.1 * t, 1e-9);
  EXPECT_NEAR(r[2], 0.2 * 1.5 * q * 0.1 * t, 1e-9);
  // the moment of a linear traction along the edge: t_x = q y / 0.1 on x = 0.2 gives M = -int t_x y t
  const Eigen::Vector3d rx = resultant(f.model.traction_load(
      {Vec2(0.2, 0), Vec2(0.2, 0.1)}, [&](const Vec2& x) { return Eigen::Vector2d(q * x.y() / 0.1, 0); }));
  EXPECT_NEAR(rx[0], 0.5 * q * 0.1 * t, 1e-9);
  EXPECT_NEAR(rx[2], -q / 0.1 * std::pow(0.1, 3) / 3 * t, 1e-9);
  const Eigen::Vector3d rp = resultant(f.model.point_load(Vec2(0.0731, 0.0412), Eigen::Vector2d(3, -5)));
  EXPECT_NEAR(rp[0], 3, 1e-12);
  EXPECT_NEAR(rp[1], -5, 1e-12);
  EXPECT_NEAR(rp[2], 0.0731 * -5 - 0.0412 * 3, 1e-12);
  const Eigen::Vector3d rb = resultant(f.model.body_load(Eigen::Vector2d(0, -9.81 * 2400)));
  EXPECT_NEAR(rb[1], -9.81 * 2400 * 0.2 * 0.1 * t, 1e-9);
  EXPECT_NEAR(rb[2], 0.1 * rb[1], 1e-9);  // about the centroid x = 0.1
}

TEST(ElasticModel, StiffnessHasTheSameBitsForAnyThreadCount) {
  Fixture f(rectangular_grid({0, 0, 0.4, 0.1}, 40, 10, 3));
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Eigen::SparseMatrix<double> K1 = f.model.stiffness();
  omp_set_num_threads(std::max(2, threads));
  const Eigen::SparseMatrix<double> K2 = f.model.stiffness();
  omp_set_num_threads(threads);
  ASSERT_EQ(K1.nonZeros(), K2.nonZeros());
  EXPECT_EQ(std::memcmp(K1.valuePtr(), K2.valuePtr(), sizeof(double) * std::size_t(K1.nonZeros())), 0);
}

TEST(ElasticModel, ShapeFunctionsFollowTheCrackSet) {
  CrackSet cracks;
  Fixture f(rectangular_grid({0, 0, 0.2, 0.1}, 8, 4), 2.5, &cracks);
  const ShapeFunctions before = f.model.shape_functions()[0];
  f.model.update_shape_functions();  // nothing changed: kept
  EXPECT_EQ(f.model.shape_functions()[0].phi, before.phi);
  cracks.add(Crack{{Vec2(0.0, 0.0375), Vec2(0.06, 0.0375)}, false, true});
  f.model.update_shape_functions();
  EXPECT_NE(f.model.shape_functions()[0].nodes, before.nodes);  // the row y = 0.05 above the crack no longer reaches it
}

TEST(ElasticModel, BadInputIsOneLineNamingTheValue) {
  const Discretisation d = rectangular_grid({0, 0, 0.2, 0.1}, 8, 4);
  const MlsApproximation mls(d.nodes, support_radii_by_spacing(d.nodes, d.spacing_m, 2.5));
  Discretisation fewer = d;
  fewer.nodes.pop_back();
  EXPECT_NE(test::input_error_of([&] { ElasticModel(fewer, kConcrete, mls); }).find("44 nodes"), std::string::npos);
  ElasticMaterial2D fluid = kConcrete;
  fluid.nu = 0.5;
  EXPECT_NE(test::input_error_of([&] { ElasticModel(d, fluid, mls); }).find("nu (0.5)"), std::string::npos);
  // supports too small to hold three nodes: the first Gauss point is named
  const MlsApproximation tiny(d.nodes, support_radii_by_spacing(d.nodes, d.spacing_m, 0.6));
  EXPECT_NE(test::input_error_of([&] { ElasticModel(d, kConcrete, tiny); }).find("Gauss point"), std::string::npos);
}
