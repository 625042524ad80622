// The strip's laws by name (efg/strip_law) and the front against the characteristics
// (efg/shock_front), each against a closed form worked out here:
//  - every law's point material, held in uniaxial strain, gives the compression law the
//    characteristics trace (-sigma_xx = f(s)), so the reference is the law the strip runs;
//  - the front's levels: p_lo is the Y-function's dip (hugoniot_Y_minimum, found there by its own
//    search), and for the quadratic law p = M s (1 + beta s) the levels' speeds, their meeting
//    distance and the jump condition's speed have closed forms in s(p) = (sqrt(1 + 4 beta p / M) - 1) / (2 beta);
//  - on a coarse strip (h = 2 mm) the measured meeting distance of the quadratic front's 10 % and
//    90 % levels against the closed form.
#include "mesowave/efg/shock_front.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/efg/strip_law.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

namespace {

const ElasticMaterial2D concrete{20e9, 0.2, 1.0, 2400, PlaneState::plane_strain};

TEST(StripLaw, EachPointMaterialHeldInUniaxialStrainIsItsCompressionLaw) {
  StripLawParameters p;
  p.beta = 40;
  p.hugoniot.unloading = false;
  for (const auto& [name, entry] : strip_laws()) {
    const StripLaw law = make_strip_law(name, concrete, p);
    EXPECT_EQ(law.name, name);
    EXPECT_EQ(law.nonlinear, name != "linear");
    for (double s : {1e-4, 0.004, 0.02, 0.0475, 0.1}) {
      PointState state;
      // one increment from rest: the laws integrate their tangent over it in closed form
      const double sigma_xx = law.point->update(Eigen::Vector3d(-s, 0, 0), state)(0);
      EXPECT_NEAR(-sigma_xx / law.compression->pressure_Pa(s), 1, 1e-12) << name << " at s = " << s;
    }
  }
}

TEST(StripLaw, UnknownNamesAndBadParametersAreOneLine) {
  StripLawParameters p;
  EXPECT_NE(test::input_error_of([&] { make_strip_law("cubic", concrete, p); }).find("linear | quadratic"),
            std::string::npos);
  p.beta = 0;
  EXPECT_NE(test::input_error_of([&] { make_strip_law("quadratic", concrete, p); }).find("--beta (0)"), std::string::npos);
  EXPECT_EQ(test::input_error_of([&] { make_strip_law("linear", concrete, p); }), "");  // beta is not the linear law's
  p.hugoniot.a_v = 1;
  EXPECT_NE(test::input_error_of([&] { make_strip_law("hugoniot", concrete, p); }), "");
}

WaveStripOptions quadratic_strip(double spacing) {
  WaveStripOptions o;
  o.length_m = 0.3, o.width_m = 0.012, o.spacing_m = spacing;
  o.E_Pa = 20e9, o.nu = 0.2, o.density_kg_m3 = 2400;
  o.triangular = {0.5e9, 20e-6, 20e-6, 0};
  o.sensor_x_m = {0.01, 0.03, 0.05, 0.1, 0.15, 0.2};
  o.dynamics.duration_s = 95e-6;  // before the reflection from x = 0.3 m reaches 0.2 m
  // the law stiffens 2x within 10 steps of 2 mm (dt ~ 1 us): the step is re-read every step
  o.dynamics.stiffness_check_every = 1;
  return o;
}

TEST(ShockFront, LevelsSpeedsAndMeetingOfTheQuadraticLawInClosedForm) {
  const double beta = 40, M = concrete.D()(0, 0), rho = 2400, p_max = 0.5e9, t_r = 20e-6;
  const QuadraticStiffening law(M, beta);
  const WaveStripOptions o = quadratic_strip(2e-3);
  const ShockFrontComparison c = compare_front_with_characteristics(o, WaveStripResult{}, law);
  const auto s_of = [&](double p) { return (std::sqrt(1 + 4 * beta * p / M) - 1) / (2 * beta); };
  const auto c_of = [&](double s) { return std::sqrt(M * (1 + 2 * beta * s) / rho); };
  EXPECT_DOUBLE_EQ(c.p_lo_Pa, 0.1 * p_max);  // the tangent is least at s = 0: the 10 % level
  EXPECT_DOUBLE_EQ(c.p_hi_Pa, 0.9 * p_max);
  const double s_lo = s_of(0.1 * p_max), s_hi = s_of(0.9 * p_max);
  EXPECT_NEAR(c.s_lo / s_lo, 1, 1e-12);
  EXPECT_NEAR(c.c_hi_m_s / c_of(s_hi), 1, 1e-12);
  const double meet = 0.8 * t_r / (1 / c_of(s_lo) - 1 / c_of(s_hi));
  EXPECT_NEAR(c.meet_distance_m / meet, 1, 1e-10);
  EXPECT_NEAR(c.meet_time_s / (0.9 * t_r + meet / c_of(s_hi)), 1, 1e-10);
  EXPECT_NEAR(c.jump_speed_m_s / std::sqrt(M / rho * (1 + beta * (s_lo + s_hi))), 1, 1e-10);
  EXPECT_NEAR(c.formation.distance_m / (std::sqrt(M / rho) * M * t_r / (beta * p_max)), 1, 1e-9);  // at the front
  EXPECT_TRUE(c.fronts.empty());
  EXPECT_TRUE(std::isnan(c.measured_meet_distance_m));  // no sensors, nothing fitted
}

TEST(ShockFront, TheYFunctionsLowerLevelIsItsDip) {
  HugoniotParameters hp;
  hp.unloading = false;
  const double M = concrete.D()(0, 0);
  const HugoniotCompression law(M, hp);
  WaveStripOptions o = quadratic_strip(1e-3);
  o.triangular.peak_Pa = 2e9;
  const ShockFrontComparison c = compare_front_with_characteristics(o, WaveStripResult{}, law);
  // the golden-section search against hugoniot_Y_minimum's own: the pressure is flat there to
  // first order, so 1e-9 of it is far inside either search's tolerance
  EXPECT_NEAR(c.p_lo_Pa / law.pressure_Pa(-hugoniot_Y_minimum(hp).eps_v), 1, 1e-9);
  o.pulse = "friedlander";
  EXPECT_NE(test::input_error_of([&] { compare_front_with_characteristics(o, WaveStripResult{}, law); }).find("triangular"),
            std::string::npos);
}

TEST(ShockFront, TheQuadraticStripsLevelsMeetWhereTheCharacteristicsSay) {
  const double beta = 40, M = concrete.D()(0, 0);
  WaveStripOptions o = quadratic_strip(2e-3);
  const QuadraticStiffeningPoint point(concrete, beta);
  o.material = &point;
  const WaveStripResult r = run_wave_strip(o);
  const QuadraticStiffening law(M, beta);
  const ShockFrontComparison c = compare_front_with_characteristics(o, r, law);
  ASSERT_EQ(c.fitted_sensors, 3);  // 10, 30, 50 mm: before x_b = 67.6 mm
  double sample = 0;
  for (std::size_t i = 1; i < r.run.sample_t_s.size(); ++i) sample = std::max(sample, r.run.sample_t_s[i] - r.run.sample_t_s[i - 1]);
  for (const FrontWidth& f : c.fronts) {
    std::printf("x = %5.1f mm: width %.3g us, simple wave %.3g us\n", f.x_m * 1e3, f.width_s * 1e6, f.simple_wave_width_s * 1e6);
    // each level's arrival is interpolated between samples: two sample intervals per width
    if (f.before_breaking) {
      EXPECT_NEAR(f.width_s, f.simple_wave_width_s, 2 * sample) << f.x_m;
    }
  }
  // the fitted line's zero moves by (width error) / (its slope), the slope 1/c_lo - 1/c_hi
  const double slope = 1 / c.c_lo_m_s - 1 / c.c_hi_m_s;
  std::printf("meet: measured %.4g mm (%.4g us), characteristics %.4g mm (%.4g us); shock %.5g m/s, jump %.5g m/s\n",
              c.measured_meet_distance_m * 1e3, c.measured_meet_time_s * 1e6, c.meet_distance_m * 1e3, c.meet_time_s * 1e6,
              c.shock_speed_m_s, c.jump_speed_m_s);
  EXPECT_NEAR(c.measured_meet_distance_m, c.meet_distance_m, 2 * sample / slope);
  EXPECT_NEAR(c.measured_meet_time_s, c.meet_time_s, 2 * sample / slope / c.c_hi_m_s + 2 * sample);
}

}  // namespace
