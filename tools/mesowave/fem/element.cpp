#include "mesowave/fem/element.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mesowave::fem {

namespace {

const double g = 1.0 / std::sqrt(3.0);

// Isotropic elasticity in Voigt order (xx, yy, zz, yz, xz, xy), engineering shear.
Eigen::Matrix<double, 6, 6> elasticity_3d(const IsotropicMaterial& m) {
  const double l = lame_lambda(m), mu = lame_mu(m);
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) D(i, j) = l;
    D(i, i) = l + 2 * mu;
    D(i + 3, i + 3) = mu;
  }
  return D;
}

struct Hex8Point {
  Eigen::Matrix<double, 8, 3> dN;  // dN_a / dx_j
  std::array<double, 8> N;
  double detJ;
};

Hex8Point hex8_at(const std::array<std::array<double, 3>, 8>& x, double xi, double eta, double zeta) {
  static const int s[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                              {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  Eigen::Matrix<double, 8, 3> dNl;
  Hex8Point p;
  for (int a = 0; a < 8; ++a) {
    const double fx = 1 + s[a][0] * xi, fy = 1 + s[a][1] * eta, fz = 1 + s[a][2] * zeta;
    p.N[a] = fx * fy * fz / 8;
    dNl(a, 0) = s[a][0] * fy * fz / 8;
    dNl(a, 1) = s[a][1] * fx * fz / 8;
    dNl(a, 2) = s[a][2] * fx * fy / 8;
  }
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();  // J(i, j) = d x_j / d xi_i
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) J(i, j) += dNl(a, i) * x[a][j];
  p.detJ = J.determinant();
  if (!(p.detJ > 0)) throw std::logic_error("hexahedron with a non-positive Jacobian (inverted or degenerate)");
  p.dN = dNl * J.inverse().transpose();
  return p;
}

struct Quad4Point {
  Eigen::Matrix<double, 4, 2> dN;  // d/dr, d/dz
  std::array<double, 4> N;
  double detJ, r;
};

Quad4Point quad4_at(const std::array<std::array<double, 2>, 4>& x, double xi, double eta) {
  static const int s[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  Eigen::Matrix<double, 4, 2> dNl;
  Quad4Point p;
  p.r = 0;
  for (int a = 0; a < 4; ++a) {
    const double fx = 1 + s[a][0] * xi, fy = 1 + s[a][1] * eta;
    p.N[a] = fx * fy / 4;
    dNl(a, 0) = s[a][0] * fy / 4;
    dNl(a, 1) = s[a][1] * fx / 4;
    p.r += p.N[a] * x[a][0];
  }
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) J(i, j) += dNl(a, i) * x[a][j];
  p.detJ = J.determinant();
  if (!(p.detJ > 0)) throw std::logic_error("quadrilateral with a non-positive Jacobian (inverted or degenerate)");
  p.dN = dNl * J.inverse().transpose();
  return p;
}

}  // namespace

std::vector<double> hex8_stiffness(const std::array<std::array<double, 3>, 8>& x, const IsotropicMaterial& m) {
  const auto D = elasticity_3d(m);
  Eigen::Matrix<double, 24, 24> K = Eigen::Matrix<double, 24, 24>::Zero();
  for (double xi : {-g, g})
    for (double eta : {-g, g})
      for (double zeta : {-g, g}) {
        const auto p = hex8_at(x, xi, eta, zeta);
        Eigen::Matrix<double, 6, 24> B = Eigen::Matrix<double, 6, 24>::Zero();
        for (int a = 0; a < 8; ++a) {
          const double dx = p.dN(a, 0), dy = p.dN(a, 1), dz = p.dN(a, 2);
          B(0, 3 * a) = dx;
          B(1, 3 * a + 1) = dy;
          B(2, 3 * a + 2) = dz;
          B(3, 3 * a + 1) = dz;
          B(3, 3 * a + 2) = dy;
          B(4, 3 * a) = dz;
          B(4, 3 * a + 2) = dx;
          B(5, 3 * a) = dy;
          B(5, 3 * a + 1) = dx;
        }
        K += B.transpose() * D * B * p.detJ;
      }
  K = 0.5 * (K + K.transpose());
  return std::vector<double>(K.data(), K.data() + 24 * 24);  // symmetric: column-major equals row-major
}

std::array<double, 8> hex8_lumped_mass(const std::array<std::array<double, 3>, 8>& x, double rho) {
  std::array<double, 8> m{};
  for (double xi : {-g, g})
    for (double eta : {-g, g})
      for (double zeta : {-g, g}) {
        const auto p = hex8_at(x, xi, eta, zeta);
        for (int a = 0; a < 8; ++a) m[a] += rho * p.N[a] * p.detJ;
      }
  return m;
}

std::vector<double> quad4_axisymmetric_stiffness(const std::array<std::array<double, 2>, 4>& x,
                                                 const IsotropicMaterial& m) {
  const double l = lame_lambda(m), mu = lame_mu(m);
  Eigen::Matrix4d D;  // (rr, zz, tt, rz)
  D << l + 2 * mu, l, l, 0, l, l + 2 * mu, l, 0, l, l, l + 2 * mu, 0, 0, 0, 0, mu;
  Eigen::Matrix<double, 8, 8> K = Eigen::Matrix<double, 8, 8>::Zero();
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      const auto p = quad4_at(x, xi, eta);
      Eigen::Matrix<double, 4, 8> B = Eigen::Matrix<double, 4, 8>::Zero();
      for (int a = 0; a < 4; ++a) {
        B(0, 2 * a) = p.dN(a, 0);
        B(1, 2 * a + 1) = p.dN(a, 1);
        B(2, 2 * a) = p.N[a] / p.r;
        B(3, 2 * a) = p.dN(a, 1);
        B(3, 2 * a + 1) = p.dN(a, 0);
      }
      K += B.transpose() * D * B * (2 * std::numbers::pi * p.r * p.detJ);
    }
  K = 0.5 * (K + K.transpose());
  return std::vector<double>(K.data(), K.data() + 64);
}

std::array<double, 4> quad4_axisymmetric_lumped_mass(const std::array<std::array<double, 2>, 4>& x, double rho) {
  std::array<double, 4> m{};
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      const auto p = quad4_at(x, xi, eta);
      for (int a = 0; a < 4; ++a) m[a] += rho * p.N[a] * 2 * std::numbers::pi * p.r * p.detJ;
    }
  return m;
}

double element_max_eigenvalue(const std::vector<double>& K, const std::vector<double>& mass) {
  const int n = int(mass.size());
  Eigen::MatrixXd A(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A(i, j) = K[std::size_t(i) * n + j] / std::sqrt(mass[i] * mass[j]);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(A, Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();
}

}  // namespace mesowave::fem
