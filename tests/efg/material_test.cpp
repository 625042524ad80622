// The plane-stress and plane-strain D of Eqs. (14)-(18) against independent references: the
// inverse of the plane-stress compliance and the 3D Lame stiffness restricted to eps_zz = 0.
#include <gtest/gtest.h>

#include <Eigen/LU>

#include "mesowave/efg/material.hpp"
#include "mesowave/wave/elastic.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

namespace {

ElasticMaterial2D concrete(PlaneState state) { return {20e9, 0.2, 0.1, 2400, state}; }

}  // namespace

TEST(Material, PlaneStressIsTheInverseOfTheCompliance) {
  const ElasticMaterial2D m = concrete(PlaneState::plane_stress);
  Eigen::Matrix3d S;  // eps = S sigma with sigma_zz = 0
  S << 1, -m.nu, 0, -m.nu, 1, 0, 0, 0, 2 * (1 + m.nu);
  S /= m.E_Pa;
  EXPECT_LT((m.D() - S.inverse()).norm() / m.D().norm(), 1e-14);
}

TEST(Material, PlaneStrainIsTheLameStiffnessWithoutEzz) {
  const ElasticMaterial2D m = concrete(PlaneState::plane_strain);
  const wave::IsotropicMaterial iso{m.E_Pa, m.nu, m.density_kg_m3};
  const double lambda = wave::lame_lambda(iso), mu = wave::lame_mu(iso);
  Eigen::Matrix3d D;
  D << lambda + 2 * mu, lambda, 0, lambda, lambda + 2 * mu, 0, 0, 0, mu;
  EXPECT_LT((m.D() - D).norm() / D.norm(), 1e-14);
}

TEST(Material, ParsesTheStateByName) {
  EXPECT_EQ(parse_plane_state("plane-stress"), PlaneState::plane_stress);
  EXPECT_EQ(parse_plane_state("plane-strain"), PlaneState::plane_strain);
  EXPECT_EQ(parse_plane_state(to_string(PlaneState::plane_strain)), PlaneState::plane_strain);
  EXPECT_NE(test::input_error_of([] { parse_plane_state("axisymmetric"); }).find("'axisymmetric'"), std::string::npos);
}

TEST(Material, BadValuesAreOneLineNamingTheValue) {
  ElasticMaterial2D m = concrete(PlaneState::plane_strain);
  m.nu = 0.5;
  EXPECT_NE(test::input_error_of([&] { m.validate(); }).find("nu (0.5)"), std::string::npos);
  EXPECT_NE(test::input_error_of([&] { m.D(); }).find("nu (0.5)"), std::string::npos);
  m = concrete(PlaneState::plane_stress);
  m.E_Pa = -1;
  EXPECT_NE(test::input_error_of([&] { m.validate(); }).find("Young's modulus E"), std::string::npos);
  m = concrete(PlaneState::plane_stress);
  m.thickness_m = 0;
  EXPECT_NE(test::input_error_of([&] { m.validate(); }).find("thickness"), std::string::npos);
  m = concrete(PlaneState::plane_stress);
  m.density_kg_m3 = -1;
  EXPECT_NE(test::input_error_of([&] { m.validate(); }).find("density"), std::string::npos);
  EXPECT_EQ(test::input_error_of([] { concrete(PlaneState::plane_stress).validate(); }), "");
}
