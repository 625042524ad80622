// The method-of-characteristics reference against the closed form (quadratic stiffening, linear
// rise: t_b = M t_r / (beta p_max) at the front) and against the second method (characteristics
// traced as straight lines and intersected: consecutive pairs, and every pair for a smaller count,
// which shows no non-neighbour crossing comes first); the jump condition against U = c_0 (linear
// law) and U^2 = (M / rho)(1 + beta (s_a + s_b)); the paper's Y-function law, whose figures
// docs/efg.md ("Shock steepening") quotes from this test's output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>

#include "mesowave/efg/characteristics.hpp"
#include "support/input_error.hpp"

namespace mesowave::efg {
namespace {

// the bar: E, nu of Section 4.1 (20 GPa, 0.2) in uniaxial strain, rho = 2400 kg/m3 (assumed)
const double M = 20e9 * 0.8 / (1.2 * 0.6), rho = 2400, c0 = std::sqrt(M / rho);
const TriangularPulse pulse{0.5e9, 20e-6, 20e-6, 0};  // 0.5 GPa peak, 20 us rise, 20 us fall

void print(const char* what, const ShockFormation& f) {
  std::printf("%-44s t_b = %.6g us, x_b = %.6g mm, tau_b = %.4g us, s_b = %.5g, c_b = %.6g m/s, %s\n", what,
              f.time_s * 1e6, f.distance_m * 1e3, f.emitted_at_s * 1e6, f.compression, f.wave_speed_m_s,
              f.loading ? "rise" : "fall");
}

TEST(Characteristics, LinearLawNeverBreaksAndItsShockRunsAtC0) {
  const LinearCompression law(M);
  EXPECT_FALSE(shock_formation(law, rho, pulse).forms);
  EXPECT_FALSE(traced_first_crossing(law, rho, pulse, 1000, true).forms);
  EXPECT_NEAR(shock_speed_m_s(law, rho, 0, 0.01), c0, 1e-12 * c0);
  EXPECT_NEAR(shock_speed_m_s(law, rho, 0.02, 0.005), c0, 1e-12 * c0);
  EXPECT_NEAR(c0, 3042.9030972509227, 1e-9);  // sqrt(22.222 GPa / 2400)
}

TEST(Characteristics, QuadraticLawAgainstTheClosedForm) {
  for (double beta : {2.0, 10.0, 40.0}) {
    const QuadraticStiffening law(M, beta);
    const double t_b = M * pulse.rise_s / (beta * pulse.peak_Pa), x_b = c0 * t_b;
    const ShockFormation f = shock_formation(law, rho, pulse);
    ASSERT_TRUE(f.forms);
    EXPECT_NEAR(f.time_s, t_b, 1e-12 * t_b) << beta;
    EXPECT_NEAR(f.distance_m, x_b, 1e-12 * x_b) << beta;
    EXPECT_EQ(f.emitted_at_s, 0);  // the front breaks first
    EXPECT_TRUE(f.loading);
    // the second method: 2e5 characteristics, consecutive crossings. The first pair (0, dtau) meets
    // at t_b + 2.5 dtau to leading order (c = c_0 (1 + k tau)^(1/4) on the rise): within 3 spacings
    const double dtau = pulse.duration_s() / 200000;
    const ShockFormation g = traced_first_crossing(law, rho, pulse, 200000);
    EXPECT_NEAR(g.time_s, t_b, 3 * dtau) << beta;
    EXPECT_NEAR(g.distance_m, x_b, 3 * dtau * c0) << beta;
    // every pair of 2000: the same earliest crossing as the consecutive ones
    const ShockFormation all = traced_first_crossing(law, rho, pulse, 2000, true);
    const ShockFormation next = traced_first_crossing(law, rho, pulse, 2000, false);
    EXPECT_EQ(all.time_s, next.time_s);
    EXPECT_NEAR(all.time_s, t_b, 3 * pulse.duration_s() / 2000);
    if (beta == 10.0) print("quadratic beta = 10, 0.5 GPa, 20/40 us:", f);
  }
}

TEST(Characteristics, QuadraticShockSpeedFromTheJumpCondition) {
  const double beta = 10;
  const QuadraticStiffening law(M, beta);
  for (auto [a, b] : {std::pair{0.0, 0.0184}, std::pair{0.005, 0.03}, std::pair{0.03, 0.01}}) {
    const double U = std::sqrt(M / rho * (1 + beta * (a + b)));
    EXPECT_NEAR(shock_speed_m_s(law, rho, a, b), U, 1e-12 * U);
    // the Lax condition: between the characteristic speeds ahead and behind
    EXPECT_GT(U, wave_speed_m_s(law, rho, std::min(a, b)));
    EXPECT_LT(U, wave_speed_m_s(law, rho, std::max(a, b)));
  }
  // the pulse's peak compression: s (1 + 10 s) = p_max / M
  const double s_peak = (-1 + std::sqrt(1 + 4 * beta * pulse.peak_Pa / M)) / (2 * beta);
  EXPECT_NEAR(compression_at_pressure(law, pulse.peak_Pa), s_peak, 1e-14);
  std::printf("quadratic beta = 10: s_peak = %.6g, U(0 -> s_peak) = %.6g m/s, c(s_peak) = %.6g m/s\n", s_peak,
              shock_speed_m_s(law, rho, 0, s_peak), wave_speed_m_s(law, rho, s_peak));
}

TEST(Characteristics, TheYFunctionLawAgainstTracing) {
  const HugoniotParameters paper;
  const HugoniotCompression law(M, paper);
  // the elastic precursor up to M e_v,th = 177.8 MPa: no crossing below it at all
  const TriangularPulse small{0.17e9, 20e-6, 20e-6, 0};
  EXPECT_FALSE(shock_formation(law, rho, small).forms);
  EXPECT_FALSE(traced_first_crossing(law, rho, small, 2000, true).forms);
  for (double peak : {1e9, 2e9, 3e9, 5e9}) {
    const TriangularPulse p{peak, 20e-6, 20e-6, 0};
    const ShockFormation f = shock_formation(law, rho, p);
    const ShockFormation g = traced_first_crossing(law, rho, p, 200000);
    ASSERT_TRUE(f.forms && g.forms);
    EXPECT_NEAR(g.time_s, f.time_s, 2e-4 * f.time_s) << peak;
    EXPECT_NEAR(g.distance_m, f.distance_m, 2e-3 * f.distance_m) << peak;
    EXPECT_EQ(g.loading, f.loading);
    const ShockFormation all = traced_first_crossing(law, rho, p, 3000, true);
    EXPECT_EQ(all.time_s, traced_first_crossing(law, rho, p, 3000, false).time_s) << peak;
    // on the rise, the level that breaks lies past the dip's minimum (|eps_v| = 0.0475); on the fall, in the dip
    const double s_min = -hugoniot_Y_minimum(paper).eps_v;
    if (f.loading)
      EXPECT_GT(f.compression, s_min);
    else
      EXPECT_TRUE(f.compression > paper.e_v_th && f.compression < s_min);
    char what[64];
    std::snprintf(what, sizeof what, "Y-function, %.0f GPa (s_peak %.4f):", peak / 1e9,
                  compression_at_pressure(law, peak));
    print(what, f);
  }
  // the jump from rest to 0.2 against the integral of Y: U^2 = M P(0.2) / (rho 0.2)
  EXPECT_NEAR(shock_speed_m_s(law, rho, 0, 0.2), std::sqrt(M * 0.22632268541287942 / (rho * 0.2)), 1e-9);
}

TEST(Characteristics, QuadraticPointMaterialIsTheLawUnderUniaxialStrain) {
  const ElasticMaterial2D m{20e9, 0.2, 1.0, rho, PlaneState::plane_strain};
  const QuadraticStiffeningPoint point(m, 10);
  const QuadraticStiffening law(m.D()(0, 0), 10);
  for (int steps : {1, 9}) {
    PointState st;
    st.strain = Eigen::Vector3d(0.004, 0, 0);  // from tension, through zero, into compression
    st.stress = m.D() * st.strain;
    for (int i = 1; i <= steps; ++i) point.update(Eigen::Vector3d(0.004 - 0.024 * i / steps, 0, 0), st);
    EXPECT_NEAR(-st.stress(0), law.pressure_Pa(0.02), 1e-12 * law.pressure_Pa(0.02)) << steps;
    EXPECT_DOUBLE_EQ(st.modulus_scale, 1 + 2 * 10 * 0.02);
  }
}

TEST(Characteristics, InversionAndBadInput) {
  const QuadraticStiffening law(M, 10);
  for (double s : {1e-6, 0.01, 0.3}) EXPECT_NEAR(compression_at_pressure(law, law.pressure_Pa(s)), s, 1e-14 * s + 1e-18);
  EXPECT_EQ(compression_at_pressure(law, 0), 0);
  EXPECT_EQ(test::input_error_of([&] { shock_formation(law, rho, TriangularPulse{1e9, 0, 20e-6, 0}); }),
            "pulse rise time (0 s) must be positive and finite");
  EXPECT_EQ(test::input_error_of([&] { shock_formation(law, rho, TriangularPulse{-1, 20e-6, 20e-6, 0}); }),
            "pulse peak (-1 Pa) must be positive and finite");
  // a later start shifts the time, not the distance; a fall of 0 (instant drop) adds no crossing
  const QuadraticStiffening q(M, 10);
  const ShockFormation later = shock_formation(q, rho, TriangularPulse{0.5e9, 20e-6, 20e-6, 5e-6});
  EXPECT_NEAR(later.time_s, shock_formation(q, rho, pulse).time_s + 5e-6, 1e-15);
  EXPECT_NEAR(later.distance_m, shock_formation(q, rho, pulse).distance_m, 1e-12);
  EXPECT_NEAR(traced_first_crossing(q, rho, TriangularPulse{0.5e9, 20e-6, 0, 0}, 20000).time_s,
              shock_formation(q, rho, TriangularPulse{0.5e9, 20e-6, 0, 0}).time_s, 3e-9);
  EXPECT_EQ(test::input_error_of([] { QuadraticStiffening(M, 0); }), "stiffening beta (0) must be positive and finite");
  EXPECT_NE(test::input_error_of([&] { shock_speed_m_s(law, rho, 0.01, 0.01); }), "");
  EXPECT_NE(test::input_error_of([&] { compression_at_pressure(law, -1); }), "");
}

}  // namespace
}  // namespace mesowave::efg
