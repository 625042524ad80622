// The explicit solver's shock (bulk) viscosity (efg/explicit_dynamics: q = rho l (C_0 l eps_dot_v^2 -
// C_1 c eps_dot_v) in compression, the stress -q I in the internal force, its work booked apart, the
// step times r = sqrt(1 + xi^2) - xi), against references worked out here:
//  - q at every Gauss point of a grid moving with the uniform compression rate v = -G x (eps_dot_v = -G,
//    which the MLS reproduces exactly): rho l (C_0 l G^2 + C_1 c G) with l the cell edge and c =
//    sqrt(M / rho) from E and nu (and 2 c for a law that reports a 4x stiffer tangent);
//  - q = 0 in expansion (v = +G x), under a rigid translation and a rigid rotation;
//  - the step factor against LS-DYNA's form l / (Q + sqrt(Q^2 + c^2)) divided by l / c;
//  - the energy identity KE + W_int + W_visc - W_ext = 0 to round-off on a shock strip, W_visc > 0;
//  - the Y-function strip's shock speed against a second method, a fine 1D Lagrangian bar of the same
//    law (the fixed-level jump condition U^2 = [p] / (rho [s]) does not hold where the test times it: the
//    pulse's fall has eaten the shock; see the test) at the bound measured (docs/efg.md "Shock viscosity");
//  - 1 and 2 threads bit-identical.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "mesowave/efg/explicit_dynamics.hpp"
#include "mesowave/efg/shock_front.hpp"
#include "mesowave/efg/strip_law.hpp"
#include "mesowave/efg/wave_strip.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

namespace {

const double E = 20e9, nu = 0.2, rho = 2400;
const ElasticMaterial2D kConcrete{E, nu, 1.0, rho, PlaneState::plane_strain};
const BulkViscosity kLsDyna{1.5, 0.06};

// A law that reports a tangent `scale` times D (and returns D eps: only the scale matters to q).
class ScaledLaw final : public PointMaterial {
 public:
  ScaledLaw(const ElasticMaterial2D& m, double scale) : D_(m.D()), scale_(scale) {}
  Eigen::Vector3d update(const Eigen::Vector3d& strain, PointState& s) const override {
    s.strain = strain;
    s.stress = D_ * strain;
    s.modulus_scale = scale_;
    return s.stress;
  }

 private:
  Eigen::Matrix3d D_;
  double scale_;
};

struct Grid {
  Discretisation disc = rectangular_grid({0, 0, 0.1, 0.05}, 10, 5);  // square cells, l = 10 mm
  MlsApproximation mls{disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, 2.5)};
  ElasticModel model{disc, kConcrete, mls};
  /// q at every point for the nodal-parameter velocity v(x) (a linear field: the parameters are its values)
  std::vector<double> q(const PointMaterial& law, const std::function<Eigen::Vector2d(const Vec2&)>& field,
                        const BulkViscosity& c = kLsDyna) const {
    const ExplicitDynamics dyn(model, law, nullptr, {});
    Eigen::VectorXd v(2 * Eigen::Index(disc.nodes.size()));
    for (std::size_t i = 0; i < disc.nodes.size(); ++i) v.segment<2>(2 * Eigen::Index(i)) = field(disc.nodes[i]);
    std::vector<PointState> states;
    dyn.internal_force(Eigen::VectorXd::Zero(v.size()), v, states);
    return dyn.bulk_viscosity_pressures(states, c);
  }
};

WaveStripOptions hugoniot_strip(double spacing_m) {
  // the study's strip (pipeline/shock-concrete/study.mk: 400 x 12 mm, sensors to 300 mm, 140 us, the
  // step re-read every step) with lab-data's 2 GPa, 20/20 us pulse
  WaveStripOptions o;
  o.length_m = 0.4, o.width_m = 0.012, o.spacing_m = spacing_m;
  o.E_Pa = E, o.nu = nu, o.density_kg_m3 = rho;
  o.triangular = {2e9, 20e-6, 20e-6, 0};
  o.sensor_x_m = {0.01, 0.03, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3};
  o.dynamics.duration_s = 140e-6;
  o.dynamics.stiffness_check_every = 1;
  return o;
}

// The second method, the same uniaxial-strain bar as a fine 1D Lagrangian column (efg/shock_front's
// bar_1d_shock_speed, h = 0.2 mm: 5-10x finer than the strips), is the library's: the study reads it too.
}  // namespace

TEST(BulkViscosity, UniformCompressionRateGivesTheClosedForm) {
  const Grid g;
  const double G = 300;  // 1/s
  const double l = 0.01, M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)), c0 = std::sqrt(M / rho);
  for (double scale : {1.0, 4.0}) {
    const ScaledLaw law(kConcrete, scale);
    const double c = c0 * std::sqrt(scale);
    const double expected = rho * l * (1.5 * l * G * G + 0.06 * c * G);
    const std::vector<double> q = g.q(law, [&](const Vec2& x) { return Eigen::Vector2d(-G * x.x(), 0); });
    ASSERT_EQ(q.size(), g.disc.points.size());
    for (double qg : q) ASSERT_NEAR(qg, expected, 1e-9 * expected) << "scale " << scale;
    std::printf("scale %.0f: q = %.6g Pa (closed form %.6g Pa)\n", scale, q[0], expected);
  }
  // each term alone
  const ScaledLaw one(kConcrete, 1.0);
  const auto compress = [&](const Vec2& x) { return Eigen::Vector2d(-G * x.x(), -G * x.y()); };  // eps_dot_v = -2 G
  EXPECT_NEAR(g.q(one, compress, {1.5, 0})[7], rho * l * 1.5 * l * 4 * G * G, 1e-9 * rho * l * l * 6 * G * G);
  EXPECT_NEAR(g.q(one, compress, {0, 0.06})[7], rho * l * 0.06 * c0 * 2 * G, 1e-9 * rho * l * 0.12 * c0 * G);
}

TEST(BulkViscosity, NoneInExpansionNorUnderRigidMotion) {
  const Grid g;
  const ScaledLaw law(kConcrete, 1.0);
  // the scale of q at a compression rate of 1 1/s: rho l C_1 c_0 = 4.1e3 Pa
  const double per_rate = rho * 0.01 * 0.06 * 2887;
  for (double qg : g.q(law, [](const Vec2& x) { return Eigen::Vector2d(300 * x.x(), 0); })) ASSERT_EQ(qg, 0.0);
  for (double qg : g.q(law, [](const Vec2& x) { return Eigen::Vector2d(200 * x.x(), 100 * x.y()); })) ASSERT_EQ(qg, 0.0);
  // rigid motions: the rate is round-off (~1e-13 1/s for 10 m/s), so is q (below 1e-9 of the 1/s scale)
  double worst = 0;
  for (double qg : g.q(law, [](const Vec2&) { return Eigen::Vector2d(10, -7); })) worst = std::max(worst, qg);
  for (double qg : g.q(law, [](const Vec2& x) { return Eigen::Vector2d(-500 * x.y(), 500 * x.x()); }))
    worst = std::max(worst, qg);
  std::printf("rigid motions: largest q %.3g Pa\n", worst);
  EXPECT_LT(worst, 1e-9 * per_rate);
}

TEST(BulkViscosity, StepFactorIsLsDynasFormAndOptionsAreChecked) {
  const double l = 2e-3, c = 3000;
  for (double rate : {-1.0, -1e3, -1e5, -3e6}) {
    const double Q = 0.06 * c + 1.5 * l * std::abs(rate);
    const double lsdyna = l / (Q + std::sqrt(Q * Q + c * c));
    EXPECT_NEAR(bulk_viscosity_step_factor(l, c, rate, kLsDyna), lsdyna / (l / c), 1e-14) << rate;
  }
  EXPECT_EQ(bulk_viscosity_step_factor(l, c, 5e3, kLsDyna), 1.0);
  EXPECT_EQ(bulk_viscosity_pressure_Pa(rho, l, c, 5e3, kLsDyna), 0.0);
  EXPECT_FALSE(BulkViscosity{}.on());
  EXPECT_NE(test::input_error_of([] { BulkViscosity{-1, 0}.validate(); }).find("C_0"), std::string::npos);
  EXPECT_NE(test::input_error_of([] { BulkViscosity{0, NAN}.validate(); }).find("C_1"), std::string::npos);
}

// The smooth law's shock strip (2 mm, 0.5 GPa, beta = 40: a shock forms at 68 mm and runs to 300 mm):
// the identity with the viscous work closes to round-off (measured 1e-15 of the largest term; the
// solver's own drift measure, held to 1e-12), the viscosity does work, and the step took its factor.
TEST(BulkViscosity, EnergyIdentityHoldsWithTheViscousWork) {
  WaveStripOptions o;
  o.length_m = 0.3, o.width_m = 0.012, o.spacing_m = 2e-3;
  o.E_Pa = E, o.nu = nu, o.density_kg_m3 = rho;
  o.triangular = {0.5e9, 20e-6, 20e-6, 0};
  o.sensor_x_m = {0.1, 0.2};
  o.dynamics.duration_s = 95e-6;
  o.dynamics.stiffness_check_every = 1;
  StripLawParameters p;
  p.beta = 40;
  const StripLaw law = make_strip_law("quadratic", kConcrete, p);
  o.material = law.point.get();
  const WaveStripResult off = run_wave_strip(o);
  o.dynamics.viscosity = kLsDyna;
  const WaveStripResult on = run_wave_strip(o);
  const EnergySample& e = on.run.energy.back();
  std::printf("drift %.3g; W_ext %.6g J, KE %.6g J, W_int %.6g J, W_visc %.6g J; dt_min %.4g us (off %.4g us), "
              "min factor %.4f, max q %.4g MPa\n",
              on.run.energy_drift, e.external_work_J, e.kinetic_J, e.internal_work_J, e.viscous_J, on.run.dt_min_s * 1e6,
              off.run.dt_min_s * 1e6, on.run.min_viscous_step_factor, on.run.max_viscous_pressure_Pa * 1e-6);
  EXPECT_LT(on.run.energy_drift, 1e-12);
  EXPECT_NEAR(e.kinetic_J + e.internal_work_J + e.viscous_J, e.external_work_J, 1e-12 * e.external_work_J);
  EXPECT_GT(e.viscous_J, 1e-3 * e.external_work_J);  // it dissipates at the shock
  EXPECT_EQ(off.run.energy.back().viscous_J, 0.0);
  // any compressing point: r <= 1 / (C_1 + sqrt(1 + C_1^2)) = 0.9418
  EXPECT_LE(on.run.min_viscous_step_factor, 1 / (0.06 + std::sqrt(1 + 0.06 * 0.06)));
  EXPECT_LT(on.run.dt_min_s, off.run.dt_min_s);
  EXPECT_GT(on.run.max_viscous_pressure_Pa, 0.0);
}

// The Y-function strip (no Eq. (27)) at 1 mm: the speed of the level midway between the dip (753 MPa)
// and 1800 MPa between 250 and 300 mm. The jump condition between those two fixed levels (2543.9 m/s)
// is not the continuum's speed there: the pulse's peak characteristic (c_0 sqrt(Y) > U) has caught the
// shock near 100 mm and its fall has eaten it to 1.5 GPa by 300 mm (the 1D bar), so the reference is the
// 1D bar's 2386 m/s (0.938 of the jump). Measured: undamped +10.9 % (and +9.0 / +12.2 % at 2 / 0.5 mm:
// growing with refinement); with LS-DYNA's C_0, C_1 +0.13 % (+1.9 / -0.24 % at 2 / 0.5 mm). Held to 1 %.
TEST(BulkViscosity, YFunctionShockSpeedAgainstTheContinuum) {
  WaveStripOptions o = hugoniot_strip(1e-3);
  StripLawParameters p;
  p.hugoniot.unloading = false;
  const StripLaw law = make_strip_law("hugoniot", kConcrete, p);
  o.material = law.point.get();
  o.dynamics.viscosity = kLsDyna;
  const WaveStripResult r = run_wave_strip(o);
  const ShockFrontComparison c = compare_front_with_characteristics(o, r, *law.compression);
  const double bar = bar_1d_shock_speed(*law.compression, rho, o.triangular, o.length_m, o.dynamics.duration_s, 0.25, 0.3,
                                        c.speed_level_Pa, {0.2e-3, kLsDyna});
  // the comparison carries the same bar when asked for (what `mw-efg wave` and the study report)
  const BarShockSpeedOptions bar_options{0.2e-3, kLsDyna};
  EXPECT_EQ(compare_front_with_characteristics(o, r, *law.compression, &bar_options).bar_speed_m_s, bar);
  EXPECT_TRUE(std::isnan(c.bar_speed_m_s));  // none without
  std::printf("strip %.5g m/s, 1D bar %.5g m/s (%+.3f %%), jump condition %.5g m/s; drift %.3g\n", c.shock_speed_m_s, bar,
              100 * (c.shock_speed_m_s / bar - 1), c.jump_speed_m_s, r.run.energy_drift);
  ASSERT_TRUE(std::isfinite(c.shock_speed_m_s));
  EXPECT_NEAR(bar, 2386, 5);  // the converged bar (the header's sequence): the reference is itself checked
  EXPECT_NEAR(c.shock_speed_m_s / bar, 1.0, 0.01);
  EXPECT_LT(r.run.energy_drift, 1e-12);
}

// The bar itself on the linear law p = M s, whose every level travels at c_p = sqrt(M / rho) (d'Alembert):
// the half-peak level of a 20/20 us triangle between 100 and 200 mm; a level above the peak never arrives.
TEST(BulkViscosity, TheBarReferenceCarriesALinearPulseAtThePWaveSpeed) {
  const double M = kConcrete.D()(0, 0), c_p = std::sqrt(M / rho);
  const LinearCompression law(M);
  const TriangularPulse pulse{1e9, 20e-6, 20e-6, 0};
  const double bar = bar_1d_shock_speed(law, rho, pulse, 0.3, 100e-6, 0.1, 0.2, 0.5e9);
  std::printf("linear bar: %.6g m/s, c_p %.6g m/s (%+.2e)\n", bar, c_p, bar / c_p - 1);
  EXPECT_NEAR(bar / c_p, 1.0, 1e-6);
  EXPECT_TRUE(std::isnan(bar_1d_shock_speed(law, rho, pulse, 0.3, 100e-6, 0.1, 0.2, 1.1e9)));
  EXPECT_NE(test::input_error_of([&] { bar_1d_shock_speed(law, rho, pulse, 0.3, 100e-6, 0.2, 0.1, 0.5e9); }).find("stations"),
            std::string::npos);
}

TEST(BulkViscosity, SameBitsForOneAndTwoThreads) {
  WaveStripOptions o = hugoniot_strip(2e-3);
  o.length_m = 0.2;
  o.sensor_x_m = {0.05, 0.1};
  o.dynamics.duration_s = 60e-6;
  o.dynamics.min_points_per_thread = 1;
  o.dynamics.viscosity = kLsDyna;
  StripLawParameters p;
  const StripLaw law = make_strip_law("hugoniot", kConcrete, p);
  o.material = law.point.get();
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const WaveStripResult r1 = run_wave_strip(o);
  omp_set_num_threads(2);
  const WaveStripResult r2 = run_wave_strip(o);
  omp_set_num_threads(threads);
  EXPECT_EQ(r1.run.threads, 1);
  EXPECT_EQ(r2.run.threads, 2);
  ASSERT_EQ(r1.run.u.size(), r2.run.u.size());
  EXPECT_EQ(std::memcmp(r1.run.u.data(), r2.run.u.data(), sizeof(double) * std::size_t(r1.run.u.size())), 0);
  EXPECT_EQ(std::memcmp(r1.run.v.data(), r2.run.v.data(), sizeof(double) * std::size_t(r1.run.v.size())), 0);
  EXPECT_EQ(r1.run.steps, r2.run.steps);
  EXPECT_EQ(r1.run.energy.back().viscous_J, r2.run.energy.back().viscous_J);
  EXPECT_EQ(r1.run.energy.back().balance_J(), r2.run.energy.back().balance_J());
  EXPECT_GT(r1.run.energy.back().viscous_J, 0.0);
}
