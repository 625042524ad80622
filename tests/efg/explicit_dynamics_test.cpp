// The explicit EFG solver (efg/explicit_dynamics) against independent references:
//  - the lumped mass against the row sums of the consistent mass assembled here, and rho t A;
//  - f_int of the linear PointMaterial against K u of the assembled stiffness;
//  - the stable step against a dense generalised eigenproblem on the constraints' null space, a step
//    just above it refused, 5 % above it blowing up (caught, named), just below it bounded;
//  - the forward-increment multipliers against central differences on the reduced unknowns of
//    ConstraintSet (u = T q, the consistent reduced mass T^T M T, a dense solve per step);
//  - the energy balance against the central difference's shadow energy from the assembled K;
//  - the same bits for 1 and 2 threads (a whole run);
//  - the step shrunk when the law stiffens (a law 4x stiffer that says so runs, one that hides it
//    blows up);
//  - pressure histories and the consistent unit-pressure load against their closed forms.
// The strip's wave speed, dispersion and the FEM comparison: tests/efg/wave_strip_test.cpp.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cstring>
#include <random>

#include "mesowave/core/format.hpp"
#include "mesowave/efg/explicit_dynamics.hpp"
#include "mesowave/efg/strain_rate.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;
using mesowave::test::input_error_of;

namespace {

const ElasticMaterial2D kConcrete{30e9, 0.2, 1.0, 2400, PlaneState::plane_strain};

// A roller strip [0, L] x [0, W], pressure on x = 0.
struct Strip {
  Discretisation disc;
  MlsApproximation mls;
  ElasticModel model;
  ConstraintSet constraints;
  LinearElasticPoint linear;
  Strip(double L, double W, int nx, int ny, double scale = 2.5)
      : disc(rectangular_grid({0, 0, L, W}, nx, ny)),
        mls(disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, scale)),
        model(disc, kConcrete, mls),
        constraints(model, {},
                    {{{Vec2(0, 0), Vec2(L, 0)}, 1, [](const Vec2&) { return 0.0; }, "y = 0"},
                     {{Vec2(0, W), Vec2(L, W)}, 1, [](const Vec2&) { return 0.0; }, "y = W"}}),
        linear(kConcrete) {}
  std::vector<PressureLoad> end_load(PressureHistory p) const {
    return {{{Vec2(0, disc.cells.back().y1), Vec2(0, 0)}, std::move(p), "end"}};
  }
};

TriangularPulse pulse(double peak = 10e6) { return {peak, 10e-6, 10e-6, 0}; }

// A law 4x stiffer than D: stress 4 D eps; `honest` reports modulus_scale 4, else 1.
class StiffLaw final : public PointMaterial {
 public:
  StiffLaw(const ElasticMaterial2D& m, bool honest) : D_(4 * m.D()), honest_(honest) {}
  Eigen::Vector3d update(const Eigen::Vector3d& strain, PointState& s) const override {
    s.strain = strain;
    s.stress = D_ * strain;
    s.modulus_scale = honest_ ? 4.0 : 1.0;
    return s.stress;
  }

 private:
  Eigen::Matrix3d D_;
  bool honest_;
};

}  // namespace

TEST(ExplicitDynamics, LumpedMassIsTheConsistentRowSumAndKeepsTheTotal) {
  Strip s(0.2, 0.04, 20, 4);
  const Eigen::VectorXd m = lumped_mass(s.model);
  // The consistent mass assembled here, M_IJ = sum_g rho phi_I phi_J t w, and its row sums.
  const auto n = Eigen::Index(s.disc.nodes.size());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t p = 0; p < s.disc.points.size(); ++p) {
    const ShapeFunctions& sf = s.model.shape_functions()[p];
    const double w = kConcrete.density_kg_m3 * kConcrete.thickness_m * s.disc.points[p].weight_m2;
    for (std::size_t a = 0; a < sf.nodes.size(); ++a)
      for (std::size_t b = 0; b < sf.nodes.size(); ++b) M(sf.nodes[a], sf.nodes[b]) += w * sf.phi[a] * sf.phi[b];
  }
  const Eigen::VectorXd rows = M.rowwise().sum();
  EXPECT_LE((rows - m).cwiseAbs().maxCoeff(), 1e-12 * m.maxCoeff());
  const double total = kConcrete.density_kg_m3 * kConcrete.thickness_m * 0.2 * 0.04;
  EXPECT_NEAR(m.sum(), total, 1e-12 * total);
  EXPECT_GT(m.minCoeff(), 0.0);
  // A node far from the edges (two support radii) of a regular grid: all its neighbours are its
  // translates and sum to 1, so its row sum is rho t h^2 up to the 2 x 2 rule's error on the rational MLS.
  Strip wide(0.12, 0.12, 12, 12);
  const double h2 = kConcrete.density_kg_m3 * kConcrete.thickness_m * 1e-4;
  EXPECT_NEAR(lumped_mass(wide.model)[6 * 13 + 6] / h2, 1.0, 2e-3);
  // Beside the edge the MLS reaches fewer nodes: the strip's middle row, 2 spacings from both edges.
  EXPECT_NEAR(m[2 * 21 + 10] / h2, 0.946, 1e-3);
}

TEST(ExplicitDynamics, InternalForceOfTheLinearLawIsKu) {
  Strip s(0.2, 0.04, 20, 4);
  const ExplicitDynamics dyn(s.model, s.linear, &s.constraints, {});
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1e-5, 1e-5);
  Eigen::VectorXd u(Eigen::Index(s.model.dof_count()));
  for (Eigen::Index i = 0; i < u.size(); ++i) u[i] = U(rng);
  std::vector<PointState> states;
  const Eigen::VectorXd f = dyn.internal_force(u, states);
  const Eigen::VectorXd Ku = s.model.stiffness() * u;
  EXPECT_LE((f - Ku).norm(), 1e-13 * Ku.norm());
  EXPECT_EQ(states.size(), s.disc.points.size());
}

TEST(ExplicitDynamics, StableStepIsTheConstrainedProblemsLargestFrequency) {
  Strip s(0.1, 0.03, 10, 3);
  const ExplicitDynamics dyn(s.model, s.linear, &s.constraints, {});
  const Eigen::MatrixXd K(s.model.stiffness());
  Eigen::VectorXd m2(K.rows());
  for (Eigen::Index i = 0; i < m2.size(); ++i) m2[i] = dyn.mass_per_node()[i / 2];
  // Free: the largest eigenvalue of M^-1 K, dense.
  const Eigen::MatrixXd A = m2.cwiseSqrt().cwiseInverse().asDiagonal() * K * m2.cwiseSqrt().cwiseInverse().asDiagonal();
  const double free = std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues().maxCoeff());
  // Constrained: N spans C u = 0; the generalised problem N^T K N x = w^2 N^T M N x.
  const Eigen::MatrixXd N = Eigen::FullPivLU<Eigen::MatrixXd>(Eigen::MatrixXd(s.constraints.C())).kernel();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> g(N.transpose() * K * N,
                                                                    N.transpose() * m2.asDiagonal() * N);
  const double constrained = std::sqrt(g.eigenvalues().maxCoeff());
  EXPECT_NEAR(dyn.stable().omega_free_rad_s / free, 1.0, 1e-6);
  EXPECT_NEAR(dyn.stable().omega_max_rad_s / constrained, 1.0, 1e-6);
  EXPECT_GE(dyn.stable().omega_max_rad_s, constrained * (1 - 1e-12));  // from above: a safe step
  EXPECT_LE(constrained, free * (1 + 1e-12));
  EXPECT_DOUBLE_EQ(dyn.stable().dt_critical_s, 2.0 / dyn.stable().omega_max_rad_s);
}

TEST(ExplicitDynamics, StepAboveTheStableOneIsRefusedAndBlowsUpWhenForced) {
  Strip s(0.1, 0.03, 10, 3);
  const ExplicitDynamics dyn(s.model, s.linear, &s.constraints, s.end_load(pulse()));
  const double dt = dyn.stable().dt_critical_s;
  DynamicsOptions o;
  o.duration_s = 3000 * dt;
  o.dt_s = 1.001 * dt;
  const std::string refused = input_error_of([&] { dyn.run(o); });
  EXPECT_NE(refused.find("exceeds the stable step"), std::string::npos) << refused;
  EXPECT_NE(refused.find(format_quantity(o.dt_s * 1e6, "us")), std::string::npos) << refused;
  EXPECT_NE(refused.find(format_quantity(dt * 1e6, "us")), std::string::npos) << refused;

  o.allow_unstable = true;
  o.dt_s = 1.05 * dt;  // |amplification| of the top mode ~1.4 a step: round-off grows to the bound
  const std::string blew = input_error_of([&] { dyn.run(o); });
  EXPECT_NE(blew.find("blew up at step"), std::string::npos) << blew;
  EXPECT_NE(blew.find("node "), std::string::npos) << blew;

  o.allow_unstable = false;
  o.dt_s = 0.99 * dt;
  const DynamicsResult r = dyn.run(o);
  EXPECT_GT(r.steps, 2900);
  EXPECT_TRUE(r.u.allFinite());
  EXPECT_LT(r.energy_drift, 1e-9);
}

TEST(ExplicitDynamics, MultipliersGiveTheReducedSchemeAndHoldTheRollers) {
  Strip s(0.1, 0.03, 10, 3);
  const TriangularPulse p = pulse();
  const ExplicitDynamics dyn(s.model, s.linear, &s.constraints, s.end_load(p));
  DynamicsOptions o;
  o.dt_s = 0.8 * dyn.stable().dt_critical_s;
  o.duration_s = 200.5 * o.dt_s;
  const DynamicsResult r = dyn.run(o);
  ASSERT_EQ(r.steps, 201);
  // Central differences on u = T q (g = 0): T^T M T q'' = T^T (f_ext - K T q), from rest, the same
  // half-step start.
  const Eigen::MatrixXd T(s.constraints.T());
  Eigen::VectorXd m2(T.rows());
  for (Eigen::Index i = 0; i < m2.size(); ++i) m2[i] = dyn.mass_per_node()[i / 2];
  const Eigen::LLT<Eigen::MatrixXd> Mr(T.transpose() * m2.asDiagonal() * T);
  const Eigen::MatrixXd K(s.model.stiffness());
  const Eigen::VectorXd f1 = unit_pressure_load(s.model, {Vec2(0, 0.03), Vec2(0, 0)});
  Eigen::VectorXd q = Eigen::VectorXd::Zero(T.cols()), w = q;
  for (int n = 0; n < 201; ++n) {
    const Eigen::VectorXd a = Mr.solve(T.transpose() * (p(n * o.dt_s) * f1 - K * (T * q)));
    w += (n == 0 ? 0.5 : 1.0) * o.dt_s * a;
    q += o.dt_s * w;
  }
  const Eigen::VectorXd u = T * q;
  EXPECT_LE((r.u - u).norm(), 1e-9 * u.norm());
  EXPECT_GT(u.norm(), 0.0);
  EXPECT_LE(r.max_constraint_violation_m, 1e-12 * r.u.cwiseAbs().maxCoeff());
}

TEST(ExplicitDynamics, EnergyBalanceIsTheShadowEnergyAndHoldsToRoundOff) {
  Strip s(0.2, 0.03, 40, 6);
  const ExplicitDynamics dyn(s.model, s.linear, &s.constraints, s.end_load(pulse()));
  DynamicsOptions o;
  o.dt_fraction = 0.9;
  o.duration_s = 100e-6;  // the pulse in, along and reflected
  const DynamicsResult r = dyn.run(o);
  ASSERT_GT(r.steps, 40);  // 48 steps of 2.1 us
  EXPECT_LT(r.energy_drift, 1e-10);
  // The pulse is over: the work done stays in the strip (W_ext constant), KE + W_int = W_ext.
  const EnergySample& e = r.energy.back();
  EXPECT_GT(e.external_work_J, 0.0);
  EXPECT_NEAR(e.kinetic_J + e.internal_work_J, e.external_work_J, 1e-10 * e.external_work_J);
  // W_int = 1/2 u^{N-1} K u^N and KE = 1/2 v M v with v = (u^N - u^{N-1}) / dt, from the assembled K.
  const Eigen::SparseMatrix<double> K = s.model.stiffness();
  const double shadow = 0.5 * r.u_previous.dot(K * r.u);
  EXPECT_NEAR(e.internal_work_J, shadow, 1e-10 * e.external_work_J);
  Eigen::VectorXd v = (r.u - r.u_previous) / r.dt_first_s;
  double ke = 0;
  for (Eigen::Index i = 0; i < v.size(); ++i) ke += 0.5 * dyn.mass_per_node()[i / 2] * v[i] * v[i];
  EXPECT_NEAR(e.kinetic_J, ke, 1e-10 * e.external_work_J);

  // Damping: the balance still closes, and it takes energy out.
  o.alpha_damping_per_s = 2e4;
  const DynamicsResult d = dyn.run(o);
  EXPECT_LT(d.energy_drift, 1e-10);
  EXPECT_GT(d.energy.back().damping_J, 0.1 * d.energy.back().external_work_J);
  EXPECT_LT(d.energy.back().kinetic_J + d.energy.back().internal_work_J, 0.9 * e.external_work_J);
}

TEST(ExplicitDynamics, SameBitsForOneAndTwoThreads) {
  Strip s(0.2, 0.04, 40, 8);
  const ExplicitDynamics dyn(s.model, s.linear, &s.constraints, s.end_load(pulse()));
  DynamicsOptions o;
  o.duration_s = 40e-6;
  o.min_points_per_thread = 1;
  const std::vector<Sensor> sensors{{"a", Vec2(0.05, 0.02)}, {"b", Vec2(0.1, 0.013)}};
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const DynamicsResult r1 = dyn.run(o, sensors);
  omp_set_num_threads(2);
  const DynamicsResult r2 = dyn.run(o, sensors);
  omp_set_num_threads(threads);
  EXPECT_EQ(r1.threads, 1);
  EXPECT_EQ(r2.threads, 2);
  ASSERT_EQ(r1.u.size(), r2.u.size());
  EXPECT_EQ(std::memcmp(r1.u.data(), r2.u.data(), sizeof(double) * std::size_t(r1.u.size())), 0);
  EXPECT_EQ(std::memcmp(r1.v.data(), r2.v.data(), sizeof(double) * std::size_t(r1.v.size())), 0);
  for (std::size_t k = 0; k < sensors.size(); ++k)
    for (std::size_t i = 0; i < r1.sensors[k].size(); ++i) {
      ASSERT_EQ(r1.sensors[k][i].stress_Pa, r2.sensors[k][i].stress_Pa);
      ASSERT_EQ(r1.sensors[k][i].velocity_m_s, r2.sensors[k][i].velocity_m_s);
    }
  EXPECT_EQ(r1.energy.back().balance_J(), r2.energy.back().balance_J());
  EXPECT_GT(r1.u.norm(), 0.0);
}

TEST(ExplicitDynamics, StepShrinksWhenTheLawStiffens) {
  Strip s(0.1, 0.03, 10, 3);
  const StiffLaw honest(kConcrete, true), hiding(kConcrete, false);
  DynamicsOptions o;
  o.dt_fraction = 0.9;
  o.duration_s = 2000 * 0.9 * ExplicitDynamics(s.model, s.linear, &s.constraints, {}).stable().dt_critical_s;
  // Four times stiffer: the frequencies double, the linear law's step is 1.8x the stiff one's limit.
  const ExplicitDynamics a(s.model, honest, &s.constraints, s.end_load(pulse()));
  const DynamicsResult r = a.run(o);
  EXPECT_DOUBLE_EQ(r.dt_min_s, 0.5 * r.dt_first_s);
  EXPECT_EQ(r.max_modulus_scale, 4.0);
  EXPECT_TRUE(r.u.allFinite());
  EXPECT_LT(r.energy_drift, 1e-9);
  const ExplicitDynamics b(s.model, hiding, &s.constraints, s.end_load(pulse()));
  EXPECT_NE(input_error_of([&] { b.run(o); }).find("blew up"), std::string::npos);
}

TEST(ExplicitDynamics, PressureHistoriesAndTheUnitLoad) {
  const TriangularPulse t{2e6, 10e-6, 30e-6, 5e-6};
  EXPECT_EQ(t(0), 0.0);
  EXPECT_DOUBLE_EQ(t(10e-6), 1e6);
  EXPECT_DOUBLE_EQ(t(15e-6), 2e6);
  EXPECT_DOUBLE_EQ(t(30e-6), 2e6 * 15.0 / 30.0);  // 25 us in: 15 of the 30 us fall left
  EXPECT_EQ(t(45e-6), 0.0);
  const FriedlanderPulse f{1e6, 20e-6, 1.5, 0};
  EXPECT_DOUBLE_EQ(f(0), 1e6);
  EXPECT_NEAR(f(20e-6), 0.0, 1e-9);
  EXPECT_NEAR(f(10e-6), 1e6 * 0.5 * std::exp(-0.75), 1e-6);
  EXPECT_LT(f(30e-6), 0.0);  // the negative phase
  EXPECT_NE(input_error_of([] { TriangularPulse{1e6, 0, 0, 0}.validate(); }).find("pulse length"), std::string::npos);
  EXPECT_NE(input_error_of([] { TriangularPulse{1e6, -1e-6, 2e-6, 0}.validate(); }).find("rise time"), std::string::npos);
  EXPECT_NE(input_error_of([] { FriedlanderPulse{1e6, 0, 1, 0}.validate(); }).find("positive-phase"), std::string::npos);
  // The unit load's resultant: a 1 Pa push over the edge's length x thickness, along -n (MLS sums to 1).
  Strip s(0.1, 0.03, 10, 3);
  const Segment top{Vec2(0.1, 0.03), Vec2(0.02, 0.03)};  // walked right to left: the body below
  EXPECT_EQ(outward_normal(top), Eigen::Vector2d(0, 1));
  const Eigen::VectorXd f1 = unit_pressure_load(s.model, top);
  double fx = 0, fy = 0;
  for (Eigen::Index i = 0; i < f1.size(); i += 2) fx += f1[i], fy += f1[i + 1];
  EXPECT_NEAR(fx, 0.0, 1e-14);
  EXPECT_NEAR(fy, -0.08 * kConcrete.thickness_m, 1e-14);
}

TEST(ExplicitDynamics, BadOptionsAreOneLineEach) {
  Strip s(0.1, 0.03, 10, 3);
  const ExplicitDynamics dyn(s.model, s.linear, &s.constraints, {});
  const auto err = [&](auto edit) {
    DynamicsOptions o;
    o.duration_s = 1e-6;
    edit(o);
    return input_error_of([&] { dyn.run(o); });
  };
  EXPECT_NE(err([](DynamicsOptions& o) { o.duration_s = 0; }).find("duration"), std::string::npos);
  EXPECT_NE(err([](DynamicsOptions& o) { o.dt_fraction = 1.5; }).find("fraction"), std::string::npos);
  EXPECT_NE(err([](DynamicsOptions& o) { o.alpha_damping_per_s = -1; }).find("damping"), std::string::npos);
  EXPECT_NE(err([](DynamicsOptions& o) { o.dt_s = -1; }).find("time step"), std::string::npos);
  EXPECT_NE(err([](DynamicsOptions& o) { o.sample_stride = 0; }).find("sample stride"), std::string::npos);
  ElasticMaterial2D massless = kConcrete;
  massless.density_kg_m3 = 0;
  const ElasticModel m0(s.disc, massless, s.mls);
  EXPECT_NE(input_error_of([&] { lumped_mass(m0); }).find("density"), std::string::npos);
}

// Issue 16, strain rate: a prescribed uniform strain-rate field. v(x) = G x (MLS parameters v_I = G x_I:
// a linear field, which the linear basis reproduces exactly) has the strain rate (G_xx, G_yy, G_xy + G_yx)
// at every point, so each point's PointState::strain_rate_1_s (B v, what the run writes before every
// update) is that to round-off, and f_t,dyn = DIF(rate) f_t follows CEB-FIP 1990's tensile formula at the
// stretching principal rate, written out here from the code's printed coefficients (efg/strain_rate.hpp).
TEST(ExplicitDynamics, PointsGetTheStrainRateOfAPrescribedUniformRateField) {
  const Discretisation disc = rectangular_grid({0, 0, 0.1, 0.05}, 10, 5);
  const MlsApproximation mls(disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, 2.5));
  const ElasticModel model(disc, kConcrete, mls);
  const LinearElasticPoint linear(kConcrete);
  const ExplicitDynamics dyn(model, linear, nullptr, {});
  StrainRateParameters srp;
  srp.f_cm_Pa = 30e6;
  const double f_t = 3e6;
  const double delta_s = 1.0 / (10 + 6 * 3.0);  // f_cm / 10 MPa = 3
  struct Case {
    Eigen::Matrix2d G;
    double expected_dif;
  };
  // 1) rates (20, -5, 8) 1/s: the stretching principal rate 7.5 + hypot(12.5, 4) = 20.624 1/s, the low branch;
  // 2) 200 1/s uniaxial: above the cap (100 1/s), the high branch at the cap.
  const double r1 = 7.5 + std::hypot(12.5, 4.0);
  Eigen::Matrix2d G1, G2;
  G1 << 20, 3, 5, -5;  // G_xy + G_yx = 8
  G2 << 200, 0, 0, 0;
  const std::vector<Case> cases{{G1, std::pow(r1 / 3e-6, 1.016 * delta_s)},
                                {G2, std::pow(10.0, 7.11 * delta_s - 2.33) * std::cbrt(100 / 3e-6)}};
  for (const Case& c : cases) {
    Eigen::VectorXd v(2 * Eigen::Index(disc.nodes.size()));
    for (std::size_t i = 0; i < disc.nodes.size(); ++i) v.segment<2>(2 * Eigen::Index(i)) = c.G * disc.nodes[i];
    std::vector<PointState> states;
    dyn.internal_force(Eigen::VectorXd::Zero(v.size()), v, states);
    const Eigen::Vector3d rate(c.G(0, 0), c.G(1, 1), c.G(0, 1) + c.G(1, 0));
    ASSERT_EQ(states.size(), disc.points.size());
    for (const PointState& st : states) {
      // 1e-11 of the rate: the MLS reproduces a linear field to round-off (mls_test holds 1e-12 on the
      // shape functions; the rate sums about 16 of them times |G x| ~ 20 1/s x 0.1 m)
      ASSERT_LT((st.strain_rate_1_s - rate).norm(), 1e-11 * rate.norm());
      // 1e-9 of f_t: the same formula at a rate that differs by round-off (1e-11), DIF ~ rate^0.036 or capped
      EXPECT_NEAR(dynamic_tensile_strength_Pa(f_t, st.strain_rate_1_s, srp), c.expected_dif * f_t, 1e-9 * f_t);
    }
  }
  // without a velocity (the static internal_force) the rate is zero and the strength static
  std::vector<PointState> states;
  dyn.internal_force(Eigen::VectorXd::Zero(2 * Eigen::Index(disc.nodes.size())), states);
  for (const PointState& st : states) EXPECT_EQ(dynamic_tensile_strength_Pa(f_t, st.strain_rate_1_s, srp), f_t);
}
