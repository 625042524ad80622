// K u on a box by Kronecker products of 1-D operators (fem/box_operator.hpp) against the element
// assembly it replaces (the 24 x 24 hex8 matrices of fem/element.cpp, element by element), on a box
// whose cells differ along each axis; the rigid motions it must leave unloaded; and the same bits
// whatever the split of its planes between threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "mesowave/fem/box_operator.hpp"
#include "mesowave/fem/model.hpp"

using namespace mesowave;
using namespace mesowave::fem;

namespace {

const IsotropicMaterial concrete{36.67e9, 0.162, 2129.56};  // cube paper: E_d, nu_d, rho

// f = sum over elements of K_e u_e: the element path's sum, in element order.
std::vector<double> element_forces(const FemModel& m, const std::vector<double>& u) {
  std::vector<double> f(u.size(), 0.0);
  for (std::size_t e = 0; e < m.element_count(); ++e) {
    const std::int32_t* nd = &m.connectivity[8 * e];
    const std::vector<double>& K = m.stiffness[std::size_t(m.element_type[e])];
    for (int r = 0; r < 24; ++r) {
      double fr = 0;
      for (int c = 0; c < 24; ++c) fr += K[std::size_t(r * 24 + c)] * u[3 * std::size_t(nd[c / 3]) + std::size_t(c % 3)];
      f[3 * std::size_t(nd[r / 3]) + std::size_t(r % 3)] += fr;
    }
  }
  return f;
}

std::vector<double> box_forces(const FemModel& m, const std::vector<double>& u, std::int64_t split) {
  const BoxOperator op(m.box, m.material);
  std::vector<double> f(u.size(), 0.0);
  BoxOperator::Workspace a, b;
  op.apply(u.data(), f.data(), 0, split, a);
  op.apply(u.data(), f.data(), split, op.planes(), b);
  return f;
}

}  // namespace

TEST(BoxOperator, EqualsTheElementAssemblyOnABoxOfUnequalCells) {
  // 6 x 6 x 4 cells of 1.0 x 0.9167 x 1.05 mm: every face, edge and corner of the 1-D operators.
  const FemModel m = box_hexahedra(concrete, {6e-3, 5.5e-3, 4.2e-3}, 1e-3);
  ASSERT_TRUE(m.box.valid());
  EXPECT_EQ(m.box.cells[1], 6);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<double> u(m.dof_count());
  for (double& x : u) x = 1e-6 * unit(rng);
  const std::vector<double> reference = element_forces(m, u), f = box_forces(m, u, 2);
  double scale = 0, worst = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    scale = std::max(scale, std::abs(reference[i]));
    worst = std::max(worst, std::abs(f[i] - reference[i]));
  }
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(worst / scale, 1e-13) << "largest difference " << worst << " N against " << scale << " N";
}

TEST(BoxOperator, RigidMotionsCarryNoForce) {
  const FemModel m = box_hexahedra(concrete, {5e-3, 4e-3, 3e-3}, 1e-3);
  const std::size_t n = m.node_count();
  for (int motion = 0; motion < 6; ++motion) {
    std::vector<double> u(3 * n);
    for (std::size_t k = 0; k < n; ++k) {
      const auto p = m.position(k);
      if (motion < 3) {
        u[3 * k + std::size_t(motion)] = 1e-6;  // translation
      } else {  // small rotation about axis motion - 3: u = omega x p
        const int a = motion - 3, b = (a + 1) % 3, c = (a + 2) % 3;
        u[3 * k + std::size_t(b)] = -1e-3 * p[std::size_t(c)];
        u[3 * k + std::size_t(c)] = 1e-3 * p[std::size_t(b)];
      }
    }
    const std::vector<double> f = box_forces(m, u, 1);
    double worst = 0;
    for (double x : f) worst = std::max(worst, std::abs(x));
    // Against the forces of a strain of 1e-3 on one node's share of the stiffness (E h).
    EXPECT_LT(worst, 1e-12 * concrete.E_Pa * 1e-3 * 1e-3) << "motion " << motion;
  }
}

TEST(BoxOperator, TheSameBitsWhateverThePlanesEachThreadTakes) {
  const FemModel m = box_hexahedra(concrete, {4e-3, 4e-3, 6e-3}, 1e-3);
  std::vector<double> u(m.dof_count());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = 1e-6 * std::sin(0.37 * double(i));
  const std::vector<double> one = box_forces(m, u, 0), two = box_forces(m, u, 3), other = box_forces(m, u, 6);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, other);
}
