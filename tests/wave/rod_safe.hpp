#pragma once
// An independent reference for the Pochhammer-Chree tests: the semi-analytical
// finite element (SAFE) method for axisymmetric longitudinal waves in a solid
// rod. With u_r = U(r) cos(kz - wt), u_z = W(r) sin(kz - wt) the averaged energy
// per unit length gives a real symmetric eigenproblem K(k) X = omega^2 M X:
//   strain energy  lambda (U' + U/r + k W)^2 + 2 mu (U'^2 + (U/r)^2 + (k W)^2) + mu (W' - k U)^2
//   kinetic        rho omega^2 (U^2 + W^2),             both weighted by r dr on [0, a],
// U(0) = 0 on the axis, the outer surface traction-free (natural). Quadratic
// elements in r, dense generalized eigen-solution. No Bessel function and no
// root search: what it shares with the library is only the physics.
#include <Eigen/Dense>
#include <cmath>
#include <vector>

namespace mesowave::test {

class RodSafe {
public:
  RodSafe(double E, double nu, double rho, double a, int elements = 40)
      : lambda_(E * nu / ((1 + nu) * (1 - 2 * nu))), mu_(E / (2 * (1 + nu))), rho_(rho), a_(a), ne_(elements) {
    Eigen::setNbThreads(1);  // small dense products: OpenMP threads would only spin on a loaded machine
  }

  /// Angular frequencies omega_n(k), ascending (omega = 0 modes excluded only at k = 0 by the caller).
  std::vector<double> frequencies(double k) const {
    Eigen::MatrixXd K, M;
    assemble(k, K, M);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M, Eigen::EigenvaluesOnly);
    std::vector<double> w;
    for (int i = 0; i < es.eigenvalues().size(); ++i) w.push_back(std::sqrt(std::max(0.0, es.eigenvalues()(i))));
    return w;
  }

  /// Group velocity of mode n (0-based) at k: Hellmann-Feynman,
  /// d(omega^2)/dk = X^T K'(k) X / X^T M X with K' exact (K is quadratic in k).
  double group_velocity(double k, int n) const {
    Eigen::MatrixXd K, M, Kp, Km, dummy;
    assemble(k, K, M);
    const double h = 1e-3 * (std::abs(k) + 1.0 / a_);
    assemble(k + h, Kp, dummy);
    assemble(k - h, Km, dummy);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M);
    const Eigen::VectorXd X = es.eigenvectors().col(n);
    const double dw2 = X.dot((Kp - Km) * X) / (2 * h) / X.dot(M * X);
    return dw2 / (2 * std::sqrt(es.eigenvalues()(n)));
  }

private:
  // dofs: U at nodes 1..2ne (U_0 = 0 removed), W at nodes 0..2ne.
  int u_dof(int node) const { return node - 1; }
  int w_dof(int node) const { return 2 * ne_ + node; }
  int dofs() const { return 2 * ne_ + 2 * ne_ + 1; }

  void assemble(double k, Eigen::MatrixXd& K, Eigen::MatrixXd& M) const {
    K = Eigen::MatrixXd::Zero(dofs(), dofs());
    M = Eigen::MatrixXd::Zero(dofs(), dofs());
    const double he = a_ / ne_;
    const double gp[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
    const double gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    for (int e = 0; e < ne_; ++e) {
      const int nodes[3] = {2 * e, 2 * e + 1, 2 * e + 2};
      for (int g = 0; g < 3; ++g) {
        const double xi = gp[g];
        const double r = he * (e + 0.5 * (xi + 1));
        const double N[3] = {0.5 * xi * (xi - 1), 1 - xi * xi, 0.5 * xi * (xi + 1)};
        const double dN[3] = {(xi - 0.5) * 2 / he, -2 * xi * 2 / he, (xi + 0.5) * 2 / he};
        const double w = gw[g] * he / 2 * r;
        // Rows: dilatation, e_rr, e_tt, e_zz, gamma (coefficients on each dof).
        Eigen::MatrixXd B = Eigen::MatrixXd::Zero(5, dofs());
        Eigen::MatrixXd Nm = Eigen::MatrixXd::Zero(2, dofs());
        for (int i = 0; i < 3; ++i) {
          const int n = nodes[i];
          if (n > 0) {
            const int u = u_dof(n);
            B(0, u) += dN[i] + N[i] / r;
            B(1, u) += dN[i];
            B(2, u) += N[i] / r;
            B(4, u) += -k * N[i];
            Nm(0, u) += N[i];
          }
          const int wd = w_dof(n);
          B(0, wd) += k * N[i];
          B(3, wd) += k * N[i];
          B(4, wd) += dN[i];
          Nm(1, wd) += N[i];
        }
        Eigen::VectorXd D(5);
        D << lambda_, 2 * mu_, 2 * mu_, 2 * mu_, mu_;
        K += w * B.transpose() * D.asDiagonal() * B;
        M += w * rho_ * Nm.transpose() * Nm;
      }
    }
  }

  double lambda_, mu_, rho_, a_;
  int ne_;
};

}  // namespace mesowave::test
