// The dynamic increase factors against values computed independently from the published formulas
// (python3, digits below; f_cm = 30 MPa):
//   a = 1/(5+9*3); g = 10**(6.156*a-2); d = 1/(10+6*3); b = 10**(7.11*d-2.33); dm = 1/(1+8*3); bm = 10**(6*dm-2)
//   compression (r/30e-6)**(1.026*a) (r <= 30), g*(r/30e-6)**(1/3); tension (r/3e-6)**(1.016*d), b*(r/3e-6)**(1/3);
//   Malvar & Ross (r/1e-6)**dm (r <= 1), bm*(r/1e-6)**(1/3)
// the behaviour at the transitions, the static floor, the cap, the principal rates and bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/efg/strain_rate.hpp"
#include "support/input_error.hpp"

namespace mesowave::efg {
namespace {

StrainRateParameters concrete(TensileDifLaw law = TensileDifLaw::ceb_fip_1990, double cap = 1e9) {
  StrainRateParameters p;
  p.f_cm_Pa = 30e6;
  p.max_strain_rate_1_s = cap;
  p.tension = law;
  return p;
}

TEST(StrainRate, CebFip1990CompressionAgainstTheFormula) {
  const auto p = concrete();
  EXPECT_NEAR(compressive_dif(1e-3, p), 1.118992819683182, 1e-14);
  EXPECT_NEAR(compressive_dif(1, p), 1.3964159469321973, 1e-14);
  EXPECT_NEAR(compressive_dif(30, p), 1.5573097405457441, 1e-14);
  EXPECT_NEAR(compressive_dif(50, p), 1.8463948630547704, 1e-14);
  EXPECT_NEAR(compressive_dif(100, p), 2.326311754380467, 1e-14);
  // 6.156 = 6 x 1.026: the two branches meet at 30 1/s
  EXPECT_NEAR(compressive_dif(30 * (1 + 1e-12), p) / compressive_dif(30, p), 1, 1e-11);
}

TEST(StrainRate, CebFip1990TensionAgainstTheFormula) {
  const auto p = concrete();
  EXPECT_NEAR(tensile_dif(1e-3, p), 1.2346516960235343, 1e-14);
  EXPECT_NEAR(tensile_dif(10, p), 1.7245957617438217, 1e-14);
  EXPECT_NEAR(tensile_dif(30, p), 1.7947336268325265, 1e-14);
  EXPECT_NEAR(tensile_dif(100, p), 2.7011880507012767, 1e-14);
  // the printed 7.11 and 2.33 (7.112 and 7/3 would be continuous): a jump of 10^(1/300 - 0.002 delta_s) - 1
  const double delta_s = 1.0 / 28;
  const double jump = tensile_dif(30 * (1 + 1e-12), p) / tensile_dif(30, p) - 1;
  EXPECT_NEAR(jump, std::pow(10.0, 1.0 / 300 - 0.002 * delta_s) - 1, 1e-10);
  EXPECT_NEAR(jump, 0.007539090187447028, 1e-10);
}

TEST(StrainRate, MalvarRoss1998TensionAgainstTheFormula) {
  const auto p = concrete(TensileDifLaw::malvar_ross_1998);
  EXPECT_NEAR(tensile_dif(1e-3, p), 1.318256738556407, 1e-14);
  EXPECT_NEAR(tensile_dif(1, p), 1.7378008287493756, 1e-14);
  EXPECT_NEAR(tensile_dif(10, p), 3.7439783898238104, 1e-14);
  EXPECT_NEAR(tensile_dif(100, p), 8.066156921766131, 1e-13);
  EXPECT_NEAR(tensile_dif(1 + 1e-12, p) / tensile_dif(1, p), 1, 1e-11);  // log beta = 6 delta - 2
  EXPECT_EQ(compressive_dif(1, p), compressive_dif(1, concrete()));  // compression stays CEB
}

TEST(StrainRate, StaticFloorAndTheCap) {
  const auto p = concrete();
  EXPECT_EQ(compressive_dif(0, p), 1.0);
  EXPECT_EQ(compressive_dif(30e-6, p), 1.0);
  EXPECT_EQ(compressive_dif(1e-5, p), 1.0);  // below the reference rate the formula would give < 1
  EXPECT_EQ(tensile_dif(2e-6, p), 1.0);
  EXPECT_EQ(tensile_dif(5e-7, concrete(TensileDifLaw::malvar_ross_1998)), 1.0);
  // the default cap of 100 1/s: blasting rates (1e6 1/s) get the factor at 100 1/s
  StrainRateParameters capped;
  capped.f_cm_Pa = 30e6;
  EXPECT_EQ(capped.max_strain_rate_1_s, 100);
  EXPECT_NEAR(compressive_dif(1e6, capped), 2.326311754380467, 1e-14);
  EXPECT_NEAR(tensile_dif(1e6, capped), 2.7011880507012767, 1e-14);
  EXPECT_EQ(compressive_dif(50, capped), compressive_dif(50, p));  // below the cap: untouched
  // uncapped, CEB grows as the cube root: 10^(4/3) = 21.5 times more at 1e6 than at 100 1/s
  EXPECT_NEAR(compressive_dif(1e6, p) / compressive_dif(100, p), std::pow(1e4, 1.0 / 3), 1e-10);
}

TEST(StrainRate, PrincipalRates) {
  // uniaxial stretching and shortening
  PrincipalStrainRates r = principal_strain_rates(Eigen::Vector3d(5, 0, 0));
  EXPECT_EQ(r.tension_1_s, 5);
  EXPECT_EQ(r.compression_1_s, 0);
  r = principal_strain_rates(Eigen::Vector3d(-3, -1, 0));
  EXPECT_EQ(r.tension_1_s, 0);
  EXPECT_EQ(r.compression_1_s, 3);
  // pure shear gamma = 2: principal rates +-1
  r = principal_strain_rates(Eigen::Vector3d(0, 0, 2));
  EXPECT_DOUBLE_EQ(r.tension_1_s, 1);
  EXPECT_DOUBLE_EQ(r.compression_1_s, 1);
  // a general one against the eigenvalues of [[2, 1.5], [1.5, -1]]: 0.5 +- sqrt(1.5^2 + 1.5^2)
  r = principal_strain_rates(Eigen::Vector3d(2, -1, 3));
  EXPECT_NEAR(r.tension_1_s, 0.5 + std::sqrt(4.5), 1e-15);
  EXPECT_NEAR(r.compression_1_s, std::sqrt(4.5) - 0.5, 1e-15);
}

TEST(StrainRate, BadInputOneLineEach) {
  StrainRateParameters p;  // f_cm missing
  EXPECT_EQ(test::input_error_of([&] { compressive_dif(1, p); }),
            "compressive strength f_cm (0 MPa) must lie in (0, 200] MPa, the range the DIF formulas were fitted to");
  p.f_cm_Pa = 30e6;
  p.max_strain_rate_1_s = 1e-6;
  EXPECT_EQ(test::input_error_of([&] { tensile_dif(1, p); }),
            "DIF cap max_strain_rate (1e-06 1/s) must be finite and at least the static reference rate 30e-6 1/s");
  p.max_strain_rate_1_s = 100;
  EXPECT_EQ(test::input_error_of([&] { tensile_dif(-1, p); }), "strain rate (-1 1/s) must be >= 0 and finite");
  EXPECT_EQ(test::input_error_of([&] { compressive_dif(NAN, p); }), "strain rate (nan 1/s) must be >= 0 and finite");
  EXPECT_EQ(test::input_error_of([] { parse_tensile_dif_law("ceb"); }),
            "tensile DIF law 'ceb' must be ceb-fip-1990 or malvar-ross-1998");
  EXPECT_EQ(parse_tensile_dif_law("malvar-ross-1998"), TensileDifLaw::malvar_ross_1998);
  EXPECT_EQ(to_string(TensileDifLaw::ceb_fip_1990), "ceb-fip-1990");
  EXPECT_NE(test::input_error_of([] { principal_strain_rates(Eigen::Vector3d(0, INFINITY, 0)); }), "");
}

}  // namespace
}  // namespace mesowave::efg
