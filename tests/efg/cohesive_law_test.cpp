// The cohesive laws against their closed forms: the area under sigma(w) is G_f
// (Gauss-Legendre quadrature, not the formula w_max comes from), w_max from
// Eqs. (20)/(23), the bilinear kink, beta_t of Eq. (22), tangents against
// finite differences, and the unloading rule (secant to the origin).
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/core/format.hpp"
#include "mesowave/efg/cohesive_law.hpp"
#include "support/input_error.hpp"

namespace mesowave::efg {
namespace {

constexpr double f_t = 2.4e6, G_f = 113;  // the Koermeling-Reinhardt beam, Section 4.1

CohesiveParameters beam(std::map<std::string, double> keys = {}) { return {f_t, G_f, std::move(keys), std::nullopt}; }

/// Composite 5-point Gauss-Legendre quadrature of f over [a, b] in n pieces (exact on each
/// polynomial piece of degree <= 9 when a piece boundary sits at each kink).
template <class F>
double integrate(F f, double a, double b, int n) {
  static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831, 0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                              0.2369268850561891};
  double sum = 0, h = (b - a) / n;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 5; ++k) sum += w[k] * h / 2 * f(a + h * (i + 0.5) + h / 2 * x[k]);
  return sum;
}

TEST(CohesiveLaw, RegistryNamesAndKeys) {
  ASSERT_EQ(cohesive_laws().size(), 2u);
  EXPECT_EQ(cohesive_laws()[0].name, "exponential");
  EXPECT_EQ(cohesive_laws()[1].name, "bilinear");
  EXPECT_EQ(make_cohesive_law("bilinear", beam())->name(), "bilinear");
  EXPECT_EQ(test::input_error_of([] { make_cohesive_law("hordijk", beam()); }),
            "cohesive law (\"hordijk\") must be exponential or bilinear");
  EXPECT_EQ(test::input_error_of([] { make_cohesive_law("exponential", {f_t, 0, {}, std::nullopt}); }),
            "cohesive law exponential: G_f_J_m2 (0) must be positive and finite");
  EXPECT_EQ(test::input_error_of([] { make_cohesive_law("bilinear", {-1, G_f, {}, std::nullopt}); }),
            "cohesive law bilinear: f_t_Pa (-1) must be positive and finite");
  EXPECT_NE(test::input_error_of([] { make_cohesive_law("bilinear", beam({{"alpha", 2}})); }).find("unknown key alpha"),
            std::string::npos);
  EXPECT_NE(test::input_error_of([] { make_cohesive_law("exponential", beam({{"alpha", -1}})); }).find("alpha (-1)"),
            std::string::npos);
}

TEST(CohesiveLaw, ExponentialWmaxAndEnergy) {
  for (double alpha : {0.5, 1.0, 2.0, 3.7}) {
    auto law = make_cohesive_law("exponential", beam({{"alpha", alpha}}));
    EXPECT_NEAR(law->w_max_m(), (1 + alpha) * G_f / f_t, 1e-18);  // Eq. (20)
    EXPECT_DOUBLE_EQ(law->traction_Pa(0), f_t);
    EXPECT_EQ(law->traction_Pa(law->w_max_m()), 0);
    EXPECT_EQ(law->traction_Pa(2 * law->w_max_m()), 0);
    // the area under the curve, by quadrature (graded pieces near w_max where (1-w/w_max)^alpha is singular for alpha < 1)
    const double area = integrate([&](double w) { return law->traction_Pa(w); }, 0, law->w_max_m(), 4000);
    EXPECT_NEAR(area / G_f, 1, alpha < 1 ? 1e-5 : 1e-10) << alpha;
    // the closed form of Eq. (19) at one point
    EXPECT_NEAR(law->traction_Pa(0.3 * law->w_max_m()), f_t * std::pow(0.7, alpha), 1e-6);
  }
}

TEST(CohesiveLaw, BilinearWmaxKinkAndEnergy) {
  auto law = make_cohesive_law("bilinear", beam());
  const auto& b = dynamic_cast<const BilinearCohesiveLaw&>(*law);
  EXPECT_DOUBLE_EQ(b.alpha_t(), 0.14);
  EXPECT_DOUBLE_EQ(b.beta_t(), 0.25);
  const double w_max = 2 * G_f / (f_t * (0.14 + 0.25));  // Eq. (23)
  EXPECT_NEAR(law->w_max_m(), w_max, 1e-18);
  EXPECT_NEAR(law->traction_Pa(0.14 * w_max), 0.25 * f_t, 1e-6);  // the kink at (alpha_t w_max, beta_t f_t)
  EXPECT_DOUBLE_EQ(law->traction_Pa(0), f_t);
  EXPECT_NEAR(law->traction_Pa(w_max * (1 - 1e-12)), 0, 1e-3);
  // both branches linear: the slopes from the two end points of each
  EXPECT_NEAR(law->tangent_Pa_per_m(0.05 * w_max), (0.25 * f_t - f_t) / (0.14 * w_max), 1e-3);
  EXPECT_NEAR(law->tangent_Pa_per_m(0.5 * w_max), (0 - 0.25 * f_t) / (0.86 * w_max), 1e-3);
  // area: quadrature on the two pieces (exact for linear pieces) and the trapezoid areas
  const double area = integrate([&](double w) { return law->traction_Pa(w); }, 0, 0.14 * w_max, 3) +
                      integrate([&](double w) { return law->traction_Pa(w); }, 0.14 * w_max, w_max, 3);
  EXPECT_NEAR(area / G_f, 1, 1e-12);
  // Eq. (22): f_c enters only through beta_t
  EXPECT_DOUBLE_EQ(bilinear_beta_t(25e6), 0.25);
  EXPECT_NEAR(bilinear_beta_t(50e6), 0.25 - 0.0015 * 20, 1e-15);
  CohesiveParameters strong_concrete = beam();
  strong_concrete.f_c_Pa = 50e6;  // a concrete property, not a key of the law
  auto strong = make_cohesive_law("bilinear", strong_concrete);
  EXPECT_NEAR(dynamic_cast<const BilinearCohesiveLaw&>(*strong).beta_t(), 0.22, 1e-15);
  EXPECT_NEAR(strong->w_max_m(), 2 * G_f / (f_t * (0.14 + 0.22)), 1e-18);
  EXPECT_NEAR(integrate([&](double w) { return strong->traction_Pa(w); }, 0, 0.14 * strong->w_max_m(), 2) +
                  integrate([&](double w) { return strong->traction_Pa(w); }, 0.14 * strong->w_max_m(), strong->w_max_m(), 2),
              G_f, 1e-9);
  const auto parameters = strong->parameters();
  ASSERT_EQ(parameters.size(), 2u);
  EXPECT_EQ(parameters.at("alpha_t"), 0.14);
  EXPECT_NEAR(parameters.at("beta_t"), 0.22, 1e-15);
  // below 30 MPa (the beam's 22.6 MPa, lab-data) the same as no f_c; f_c out of Eq. (22)'s useful range refused
  strong_concrete.f_c_Pa = 22.6e6;
  EXPECT_DOUBLE_EQ(dynamic_cast<const BilinearCohesiveLaw&>(*make_cohesive_law("bilinear", strong_concrete)).beta_t(), 0.25);
  for (double f_c : {0.0, -5e6, 200e6}) {
    strong_concrete.f_c_Pa = f_c;
    EXPECT_NE(test::input_error_of([&] { make_cohesive_law("bilinear", strong_concrete); }).find("f_c (" + format_number(f_c * 1e-6) + " MPa)"),
              std::string::npos);
  }
  // the exponential law has no use for f_c and takes it (a lab-data file gives it for either law)
  EXPECT_EQ(make_cohesive_law("exponential", strong_concrete)->parameters(), (std::map<std::string, double>{{"alpha", 2.0}}));
  EXPECT_NE(test::input_error_of([] { make_cohesive_law("bilinear", beam({{"f_c_Pa", 50e6}})); }).find("unknown key f_c_Pa"),
            std::string::npos);
}

TEST(CohesiveLaw, TangentsAgainstFiniteDifferences) {
  for (const char* name : {"exponential", "bilinear"}) {
    auto law = make_cohesive_law(name, beam());
    for (double s : {0.01, 0.1, 0.3, 0.6, 0.9}) {
      const double w = s * law->w_max_m(), h = 1e-7 * law->w_max_m();
      const double fd = (law->traction_Pa(w + h) - law->traction_Pa(w - h)) / (2 * h);
      EXPECT_NEAR(law->tangent_Pa_per_m(w), fd, 1e-6 * std::abs(fd)) << name << " " << s;
    }
  }
}

TEST(CohesiveLaw, UnloadingIsSecantToTheOrigin) {
  auto law = make_cohesive_law("exponential", beam());
  const double w_max = law->w_max_m(), w0 = initial_opening_fraction * w_max;
  // untouched segment: the stiff secant f_t(w0)/w0 ties the faces
  auto r = cohesive_response(*law, 0.5 * w0, w0, w0);
  EXPECT_FALSE(r.loading);
  EXPECT_NEAR(r.traction_Pa, 0.5 * law->traction_Pa(w0), 1e-6);
  // on the envelope
  r = cohesive_response(*law, 0.4 * w_max, 0.3 * w_max, w0);
  EXPECT_TRUE(r.loading);
  EXPECT_DOUBLE_EQ(r.traction_Pa, law->traction_Pa(0.4 * w_max));
  EXPECT_DOUBLE_EQ(r.tangent_Pa_per_m, law->tangent_Pa_per_m(0.4 * w_max));
  // unloading from w_hist = 0.4 w_max to a quarter of it: a quarter of the stress there
  r = cohesive_response(*law, 0.1 * w_max, 0.4 * w_max, w0);
  EXPECT_FALSE(r.loading);
  EXPECT_NEAR(r.traction_Pa, 0.25 * law->traction_Pa(0.4 * w_max), 1e-6);
  EXPECT_NEAR(r.tangent_Pa_per_m, law->traction_Pa(0.4 * w_max) / (0.4 * w_max), 1e-3);
  // reloading along the same secant meets the envelope at w_hist (continuous there)
  EXPECT_NEAR(cohesive_response(*law, 0.4 * w_max * (1 - 1e-12), 0.4 * w_max, w0).traction_Pa,
              law->traction_Pa(0.4 * w_max), 1e-3);
  // fully opened: traction-free whatever the opening
  EXPECT_EQ(cohesive_response(*law, 0.5 * w_max, 1.1 * w_max, w0).traction_Pa, 0);
  // closed faces: the penalty of slope f_t / w0, compressive
  r = cohesive_response(*law, -w0, 0.5 * w_max, w0);
  EXPECT_NEAR(r.traction_Pa, -f_t, 1e-6);
  EXPECT_NEAR(r.tangent_Pa_per_m, f_t / w0, 1e-3);
  // the energy lost to the initial secant: f_t w0 / 2 against the envelope's f_t w0 (to first order)
  const double lost = integrate([&](double w) { return law->traction_Pa(w); }, 0, w0, 4) - law->traction_Pa(w0) * w0 / 2;
  EXPECT_NEAR(lost / G_f, initial_opening_fraction * (1 + 2.0) / 2, 1e-5);
}

}  // namespace
}  // namespace mesowave::efg
