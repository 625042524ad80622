// Lattice (DEM chain) dispersion against the eigenfrequencies of a finite
// periodic chain computed numerically, and the rod paper's Table 1 chains.
#include "mesowave/wave/lattice.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"

using namespace mesowave::wave;

TEST(Lattice, DispersionOfAPeriodicChainMatchesTheClosedForm) {
  // N masses on a ring: the stiffness matrix's eigenvalues are the allowed
  // omega^2 at k = 2 pi j / (N d); compare every one with the closed form.
  const MassSpringChain c{3.358e-3, 3.366e9, 5.253e-3};
  const int N = 64;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N, N);
  for (int i = 0; i < N; ++i) {
    K(i, i) += 2 * c.stiffness_N_m;
    K(i, (i + 1) % N) -= c.stiffness_N_m;
    K(i, (i + N - 1) % N) -= c.stiffness_N_m;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(K / c.mass_kg, Eigen::EigenvaluesOnly);
  std::vector<double> numeric, closed;
  for (int i = 0; i < N; ++i) numeric.push_back(std::sqrt(std::max(0.0, es.eigenvalues()(i))));
  for (int j = 0; j < N; ++j) closed.push_back(lattice_omega(c, 2 * std::numbers::pi * j / (N * c.spacing_m)));
  std::sort(closed.begin(), closed.end());
  for (int i = 1; i < N; ++i) EXPECT_NEAR(numeric[i] / closed[i], 1.0, 1e-10);
}

TEST(Lattice, GroupVelocityIsTheDerivativeAndVanishesAtTheCutoff) {
  const MassSpringChain c{1.0, 4.0, 0.01};
  EXPECT_DOUBLE_EQ(long_wave_speed(c), 0.02);
  EXPECT_DOUBLE_EQ(cutoff_omega(c), 4.0);
  for (double kd : {0.1, 1.0, 2.0, 3.0}) {
    const double k = kd / c.spacing_m, h = 1e-6 / c.spacing_m;
    const double fd = (lattice_omega(c, k + h) - lattice_omega(c, k - h)) / (2 * h);
    EXPECT_NEAR(lattice_group_velocity(c, k), fd, 1e-8);
    const auto p = lattice_at_frequency(c, lattice_omega(c, k));
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->k_rad_m, k, 1e-9 * k);
    EXPECT_NEAR(p->c_group_m_s, lattice_group_velocity(c, k), 1e-12);
  }
  EXPECT_NEAR(lattice_group_velocity(c, std::numbers::pi / c.spacing_m), 0.0, 1e-15);
  EXPECT_FALSE(lattice_at_frequency(c, 4.0));
  EXPECT_FALSE(lattice_at_frequency(c, 5.0));
}

TEST(Lattice, RodPaperChainLongWaveSpeedFollowsFromTable1) {
  // 1.03R: rho_p = 6044.37 kg/m3, K_n column 6.6e11 (the contact modulus E_dem, K_n = E_dem R).
  const double R = 5.1e-3;
  const auto c = dem_chain(R, 6044.37, 6.6e11, 1.03 * R);
  EXPECT_NEAR(c.mass_kg, 6044.37 * 4.0 / 3.0 * std::numbers::pi * R * R * R, 1e-15);
  EXPECT_NEAR(c.stiffness_N_m, 6.6e11 * R, 1e-3);
  // E_DEM of a chain = K d / A with A = pi R^2: Table 1 prints 216.30 GPa for 1.03R.
  EXPECT_NEAR(c.stiffness_N_m * c.spacing_m / (std::numbers::pi * R * R) / 1e9, 216.30, 0.5);
  EXPECT_THROW(dem_chain(R, -1, 6.6e11, R), mesowave::InputError);
}
