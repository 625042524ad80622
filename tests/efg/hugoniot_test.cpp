// The Y-function of Eqs. (24)-(27) against hand values of Eq. (25) (printed by python3 from the
// formula, digits below), its integral against quadrature, the dip past the threshold against a
// brute-force scan, and HugoniotElastic: step-size independence under uniaxial strain, the
// unloading branch of Eq. (27), and modulus_scale against finite differences of the stress.
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/efg/hugoniot.hpp"
#include "support/input_error.hpp"

namespace mesowave::efg {
namespace {

const HugoniotParameters paper;  // Eq. (26)

ElasticMaterial2D concrete(PlaneState state = PlaneState::plane_strain) {
  return {20e9, 0.2, 0.1, 2400, state};  // E and nu of Section 4.1; rho assumed
}

/// Composite 3-point Gauss-Legendre of Y over the compression [0, s], a piece boundary at the kink.
double integral_by_quadrature(double s, int n = 4000) {
  const double g[3] = {-0.7745966692414834, 0, 0.7745966692414834}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  const auto piece = [&](double a, double b) {
    double sum = 0, h = (b - a) / n;
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) sum += w[k] * h / 2 * hugoniot_Y(-(a + h * (i + 0.5) + h / 2 * g[k]), paper);
    return sum;
  };
  return s <= paper.e_v_th ? piece(0, s) : piece(0, paper.e_v_th) + piece(paper.e_v_th, s);
}

TEST(Hugoniot, YAgainstHandValuesOfEq25) {
  // python3 -c "import math; a,b,e,th=0.7,3.5,0.02,0.008; x=abs(ev)-th;
  //             print((1-a*(1-math.exp(-x/e)))*(1+(x/(b*e))**2))"
  EXPECT_EQ(hugoniot_Y(0.01, paper), 1.0);    // tension
  EXPECT_EQ(hugoniot_Y(-0.005, paper), 1.0);  // compression below the threshold
  EXPECT_NEAR(hugoniot_Y(-0.009, paper), 0.9660577115580814, 1e-15);
  EXPECT_NEAR(hugoniot_Y(-0.02, paper), 0.7042743111675078, 1e-15);
  EXPECT_NEAR(hugoniot_Y(-0.0475, paper), 0.5235873341208748, 1e-15);
  EXPECT_NEAR(hugoniot_Y(-0.1, paper), 0.8373944720456933, 1e-15);
  EXPECT_NEAR(hugoniot_Y(-0.2, paper), 2.557383680829706, 1e-14);
  EXPECT_NEAR(hugoniot_Y(-0.5, paper), 15.120244898690135, 1e-13);
}

TEST(Hugoniot, ContinuousAtTheThresholdWithAKinkThatFallsFirst) {
  const double th = paper.e_v_th;
  EXPECT_EQ(hugoniot_Y(-th, paper), 1.0);
  EXPECT_NEAR(hugoniot_Y(-th - 1e-12, paper), 1.0, 1e-10);
  // the slope jumps from 0 to -a_v / e_v = -35: Y falls below 1 just past the threshold
  EXPECT_EQ(hugoniot_dY_dcompression(-th + 1e-9, paper), 0.0);
  EXPECT_NEAR(hugoniot_dY_dcompression(-th, paper), -35.0, 1e-12);
  const double h = 1e-7;
  EXPECT_NEAR((hugoniot_Y(-th - h, paper) - 1) / h, -35.0, 1e-3);  // one-sided finite difference
  // the derivative elsewhere against central differences
  for (double ev : {-0.02, -0.0475, -0.1, -0.3}) {
    const double fd = (hugoniot_Y(ev - 1e-7, paper) - hugoniot_Y(ev + 1e-7, paper)) / 2e-7;
    EXPECT_NEAR(hugoniot_dY_dcompression(ev, paper), fd, 1e-6 * std::max(1.0, std::abs(fd))) << ev;
  }
}

TEST(Hugoniot, TheDipAgainstAScan) {
  const HugoniotMinimum m = hugoniot_Y_minimum(paper);
  double ev_min = 0, Y_min = 2, ev_one = 0;
  for (int i = 0; i <= 2000000; ++i) {  // |eps_v| in [0.008, 0.208] in steps of 1e-7
    const double ev = -paper.e_v_th - 1e-7 * i, Y = hugoniot_Y(ev, paper);
    if (Y < Y_min) Y_min = Y, ev_min = ev;
    if (ev_one == 0 && i > 0 && Y >= 1 && ev < ev_min) ev_one = ev;
  }
  EXPECT_NEAR(m.eps_v, ev_min, 2e-7);
  EXPECT_NEAR(m.Y, Y_min, 1e-12);
  EXPECT_NEAR(m.eps_v_back_at_one, ev_one, 2e-7);
  // the figures the header states
  EXPECT_NEAR(m.eps_v, -0.0475, 5e-5);
  EXPECT_NEAR(m.Y, 0.5236, 5e-5);
  EXPECT_NEAR(m.eps_v_back_at_one, -0.1140, 5e-5);
  // no dip without softening
  HugoniotParameters stiff = paper;
  stiff.a_v = 0;
  EXPECT_EQ(hugoniot_Y_minimum(stiff).Y, 1.0);
  EXPECT_GT(hugoniot_Y(-0.01, stiff), 1.0);
}

TEST(Hugoniot, IntegralOfYAgainstQuadrature) {
  EXPECT_EQ(hugoniot_compression_integral(-0.005, paper), 0.005);
  EXPECT_EQ(hugoniot_compression_integral(0.003, paper), -0.003);  // tension: Y = 1
  for (double s : {0.0081, 0.02, 0.05, 0.2, 0.5})
    EXPECT_NEAR(hugoniot_compression_integral(-s, paper), integral_by_quadrature(s), 1e-13 * s) << s;
  // and the Simpson values python3 printed (2e5 intervals)
  EXPECT_NEAR(hugoniot_compression_integral(-0.05, paper), 0.035198452628728054, 1e-12);
  EXPECT_NEAR(hugoniot_compression_integral(-0.2, paper), 0.22632268541287942, 1e-12);
  // the mean over an interval, both orders, and the midpoint value for a tiny one
  EXPECT_NEAR(hugoniot_mean_Y(-0.05, -0.2, paper),
              (integral_by_quadrature(0.2) - integral_by_quadrature(0.05)) / 0.15, 1e-12);
  EXPECT_EQ(hugoniot_mean_Y(-0.2, -0.05, paper), hugoniot_mean_Y(-0.05, -0.2, paper));
  // short intervals (3-point Gauss) against the closed form's difference on a long one and Y itself
  EXPECT_NEAR(hugoniot_mean_Y(-0.1, -0.1 - 1e-12, paper), hugoniot_Y(-0.1 - 0.5e-12, paper), 1e-15);
  EXPECT_NEAR(hugoniot_mean_Y(-0.1, -0.1009, paper),
              (integral_by_quadrature(0.1009) - integral_by_quadrature(0.1)) / 0.0009, 1e-11);
  EXPECT_NEAR(hugoniot_mean_Y(-0.0079, -0.0081, paper), (0.0001 + integral_by_quadrature(0.0081) - 0.008) / 0.0002,
              1e-11);  // across the kink
}

TEST(Hugoniot, BadParametersOneLineEach) {
  const auto msg = [](auto change) {
    HugoniotParameters p;
    change(p);
    return test::input_error_of([&] { p.validate(); });
  };
  EXPECT_EQ(msg([](auto&) {}), "");
  EXPECT_EQ(msg([](auto& p) { p.e_v_th = -0.001; }), "Hugoniot threshold e_v_th (-0.001) must be >= 0 and finite");
  EXPECT_EQ(msg([](auto& p) { p.e_v = 0; }), "Hugoniot strain scale e_v (0) must be positive and finite");
  EXPECT_EQ(msg([](auto& p) { p.a_v = 1; }),
            "Hugoniot softening a_v (1) must lie in [0, 1): a_v >= 1 leaves no stiffness far past the threshold");
  EXPECT_EQ(msg([](auto& p) { p.b_v = NAN; }), "Hugoniot stiffening scale b_v (nan) must be positive and finite");
  HugoniotParameters bad;
  bad.a_v = -0.1;
  EXPECT_NE(test::input_error_of([&] { HugoniotElastic(concrete(), bad); }), "");
}

/// Compresses a fresh point uniaxially (eps_xx only) to -s in `steps` equal steps.
PointState compress(const HugoniotElastic& law, double s, int steps, PointState state = {}) {
  const double start = state.strain(0);
  for (int i = 1; i <= steps; ++i) law.update(Eigen::Vector3d(start + (-s - start) * i / steps, 0, 0), state);
  return state;
}

TEST(HugoniotElastic, UniaxialStrainIsExactForAnyStepSize) {
  HugoniotParameters p;
  p.unloading = false;
  const auto m = concrete();
  const HugoniotElastic law(m, p);
  const Eigen::Matrix3d D = m.D();
  for (double s : {0.005, 0.03, 0.1, 0.2})
    for (int steps : {1, 7, 1000}) {
      const PointState st = compress(law, s, steps);
      const double P = integral_by_quadrature(s);
      EXPECT_NEAR(st.stress(0), -D(0, 0) * P, 1e-12 * D(0, 0) * P) << s << " " << steps;
      EXPECT_NEAR(st.stress(1), -D(0, 1) * P, 1e-12 * D(0, 0) * P);
      EXPECT_EQ(st.stress(2), 0);
      EXPECT_DOUBLE_EQ(st.modulus_scale, hugoniot_Y(-s, paper));
    }
}

TEST(HugoniotElastic, PlaneStressVolumetricStrainAndEqualBiaxialCompression) {
  const auto m = concrete(PlaneState::plane_stress);
  // eps_zz = -nu / (1 - nu) (eps_xx + eps_yy) = -0.25 (eps_xx + eps_yy): eps_v = 0.75 (eps_xx + eps_yy)
  EXPECT_NEAR(volumetric_strain(Eigen::Vector3d(-0.01, 0.002, 0.3), m), 0.75 * -0.008, 1e-17);
  EXPECT_EQ(volumetric_strain(Eigen::Vector3d(-0.01, 0.002, 0.3), concrete()), -0.008);
  HugoniotParameters p;
  p.unloading = false;
  const HugoniotElastic law(m, p);
  PointState st;
  const double e = 0.1;  // eps_xx = eps_yy = -e: eps_v = -0.15, a proportional path
  for (int i = 1; i <= 13; ++i) law.update(Eigen::Vector3d(-e * i / 13, -e * i / 13, 0), st);
  const Eigen::Matrix3d D = m.D();
  const double mean_Y = integral_by_quadrature(0.15) / 0.15;
  EXPECT_NEAR(st.stress(0), -(D(0, 0) + D(0, 1)) * e * mean_Y, 1e-12 * D(0, 0) * e);
  EXPECT_NEAR(st.stress(1), st.stress(0), 1e-6);
}

TEST(HugoniotElastic, UnloadingAndReloadingWithMaxYEq27) {
  const auto m = concrete();
  const double D11 = m.D()(0, 0);
  const HugoniotElastic law(m, paper);
  // compacted: loaded to |eps_v| = 0.2, where Y = 2.557 > 1
  PointState st = compress(law, 0.2, 50);
  const double Y_max = hugoniot_Y(-0.2, paper);
  EXPECT_DOUBLE_EQ(st.max_Y, Y_max);
  EXPECT_EQ(st.min_eps_v, -0.2);
  const double sigma_peak = st.stress(0);
  EXPECT_NEAR(sigma_peak, -D11 * integral_by_quadrature(0.2), 1e-11 * D11);
  // unload by 0.05: a straight line of slope max_Y D11
  law.update(Eigen::Vector3d(-0.15, 0, 0), st);
  EXPECT_NEAR(st.stress(0), sigma_peak + Y_max * D11 * 0.05, 1e-12 * D11);
  EXPECT_EQ(st.min_eps_v, -0.2);
  EXPECT_DOUBLE_EQ(st.modulus_scale, Y_max);
  // reload past the history in one step: 0.05 on the line, then 0.05 of virgin envelope
  law.update(Eigen::Vector3d(-0.25, 0, 0), st);
  const double virgin = integral_by_quadrature(0.25) - integral_by_quadrature(0.2);
  EXPECT_NEAR(st.stress(0), sigma_peak - D11 * virgin, 1e-11 * D11);
  EXPECT_DOUBLE_EQ(st.max_Y, hugoniot_Y(-0.25, paper));
  // stopped in the dip (max_Y stays 1): unloads with Y = 1, leaving the compaction s - P(s) at zero stress
  PointState dip = compress(law, 0.03, 10);
  EXPECT_EQ(dip.max_Y, 1.0);
  EXPECT_EQ(dip.modulus_scale, 1.0);
  const double P = integral_by_quadrature(0.03);
  law.update(Eigen::Vector3d(-(0.03 - P), 0, 0), dip);
  EXPECT_NEAR(dip.stress(0), 0, 1e-12 * D11);
  // and without Eq. (27) it goes back down its loading curve
  HugoniotParameters elastic = paper;
  elastic.unloading = false;
  const HugoniotElastic back(m, elastic);
  PointState e = compress(back, 0.2, 50);
  EXPECT_DOUBLE_EQ(e.max_Y, Y_max);  // the record is kept either way
  EXPECT_EQ(e.min_eps_v, -0.2);
  PointState e27 = e;
  back.update(Eigen::Vector3d(0, 0, 0), e);
  EXPECT_NEAR(e.stress(0), 0, 1e-12 * D11);
  law.update(Eigen::Vector3d(0, 0, 0), e27);  // Eq. (27) from the same state: a tensile residual
  EXPECT_NEAR(e27.stress(0), sigma_peak + Y_max * D11 * 0.2, 1e-11 * D11);
  EXPECT_GT(e27.stress(0), 0.28 * D11);
}

/// d sigma_xx / d eps_xx / D11 from the state `st` by a step `h` (negative: further compression).
double fd_ratio(const HugoniotElastic& law, PointState st, double h, double D11) {
  const double before = st.stress(0);
  law.update(st.strain + Eigen::Vector3d(h, 0, 0), st);
  return (st.stress(0) - before) / (h * D11);
}

TEST(HugoniotElastic, ModulusScaleAgainstFiniteDifferences) {
  const auto m = concrete();
  const double D11 = m.D()(0, 0), h = 1e-7;
  HugoniotParameters elastic = paper;
  elastic.unloading = false;
  const HugoniotElastic nonlinear(m, elastic), eq27(m, paper);
  for (double s : {0.004, 0.02, 0.0475, 0.1, 0.3}) {
    // no unloading: the tangent both ways
    const PointState a = compress(nonlinear, s, 20);
    EXPECT_NEAR(fd_ratio(nonlinear, a, -h, D11), a.modulus_scale, 2e-5 * a.modulus_scale) << s;
    EXPECT_NEAR(fd_ratio(nonlinear, a, +h, D11), a.modulus_scale, 2e-5 * a.modulus_scale) << s;
    // Eq. (27): unloading meets modulus_scale exactly; loading meets Y(eps_v) <= modulus_scale
    const PointState b = compress(eq27, s, 20);
    EXPECT_NEAR(fd_ratio(eq27, b, +h, D11), b.modulus_scale, 1e-9 * b.modulus_scale) << s;
    const double loading = fd_ratio(eq27, b, -h, D11);
    EXPECT_NEAR(loading, hugoniot_Y(-s, paper), 2e-5) << s;
    EXPECT_LE(loading, b.modulus_scale * (1 + 1e-4)) << s;  // a forward difference: Y grows over h
  }
  // shear at a compacted point: the same scale on the whole of D
  PointState c = compress(eq27, 0.2, 20);
  const double before = c.stress(2);
  eq27.update(c.strain + Eigen::Vector3d(0, 0, 1e-6), c);
  EXPECT_NEAR((c.stress(2) - before) / 1e-6, c.modulus_scale * m.D()(2, 2), 1e-9 * m.D()(2, 2) * c.modulus_scale);
}

}  // namespace
}  // namespace mesowave::efg
