#pragma once
// Largest eigenvalue of a symmetric operator by Lanczos iteration with a deterministic start vector:
// the explicit solvers' stable step 2 / sqrt(lambda_max) (dem/engine/time_step for the DEM packing,
// efg/explicit_dynamics for the EFG model). No reorthogonalisation: only the top Ritz value is
// wanted, and it converges first. The residual |beta_k s_k| bounds its distance to an eigenvalue,
// so ritz + residual is an estimate from above (what the solvers' limits use).
#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdint>
#include <vector>

#include "mesowave/core/ordered_dot.hpp"

namespace mesowave {

/// The top Ritz value, its residual norm (ritz + residual: an upper estimate) and the iterations used.
struct LanczosResult {
  double ritz = 0, residual = 0;
  int iterations = 0;
};

/// `apply(x, y)`: y = A x for the symmetric A of size n. Deterministic (fixed start vector).
template <class Apply>
LanczosResult largest_eigenvalue(std::size_t n, const Apply& apply, int max_iterations = 150, double tolerance = 1e-7);

/// The rows of A's vectors one process holds: [first, first + count) of `dimension`.
struct LanczosRows {
  std::size_t dimension = 0, first = 0, count = 0;
};

/// The same with the rows split between processes (dem/parallel, docs/mpi.md): `apply(x, y)`
/// gives this process's rows of A x from its rows of x; `dot(a, b)` is sum_i a_i b_i over every
/// process's rows, added in row order. Each process takes its rows of the one start vector, so
/// the result has the bits of one process holding every row (the overload above).
template <class Apply, class Dot>
LanczosResult largest_eigenvalue(const LanczosRows& rows, const Apply& apply, const Dot& dot, int max_iterations = 150,
                                 double tolerance = 1e-7);

template <class Apply>
LanczosResult largest_eigenvalue(std::size_t n, const Apply& apply, int max_iterations, double tolerance) {
  const auto dot = [n](const double* a, const double* b) { return ordered_dot(a, b, n); };
  return largest_eigenvalue(LanczosRows{n, 0, n}, apply, dot, max_iterations, tolerance);
}

template <class Apply, class Dot>
LanczosResult largest_eigenvalue(const LanczosRows& rows, const Apply& apply, const Dot& dot, int max_iterations,
                                 double tolerance) {
  LanczosResult result;
  if (rows.dimension == 0) return result;
  const std::size_t n = rows.count;
  std::vector<double> q(n), q_prev(n, 0.0), w(n);
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;  // fixed seed: same answer every run
  const auto next = [&state] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / double(1ULL << 53) - 0.5;
  };
  for (std::size_t i = 0; i < rows.first; ++i) next();  // the rows before this process's
  for (std::size_t i = 0; i < n; ++i) q[i] = next();
  const double norm_q = std::sqrt(dot(q.data(), q.data()));
  for (double& v : q) v /= norm_q;
  std::vector<double> alpha, beta;
  double beta_prev = 0, previous_top = -1;
  for (int k = 0; k < max_iterations && std::size_t(k) < rows.dimension; ++k) {
    apply(q.data(), w.data());
    const double a = dot(q.data(), w.data());
    for (std::size_t i = 0; i < n; ++i) w[i] -= a * q[i] + beta_prev * q_prev[i];
    const double b2 = dot(w.data(), w.data());
    alpha.push_back(a);
    const double b = std::sqrt(b2);
    const int m = int(alpha.size());
    Eigen::VectorXd diag = Eigen::Map<Eigen::VectorXd>(alpha.data(), m);
    Eigen::VectorXd sub(std::max(m - 1, 1));
    for (int i = 0; i + 1 < m; ++i) sub[i] = beta[std::size_t(i)];
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> tri;
    tri.computeFromTridiagonal(diag, sub.head(std::max(m - 1, 0)), Eigen::ComputeEigenvectors);
    const double top = tri.eigenvalues()[m - 1];
    const double residual = std::abs(b * tri.eigenvectors()(m - 1, m - 1));
    result = {top, residual, k + 1};
    if (b <= 1e-300 * std::abs(top) || (k > 10 && residual < tolerance * std::abs(top) &&
                                        std::abs(top - previous_top) < tolerance * std::abs(top)))
      break;
    previous_top = top;
    beta.push_back(b);
    beta_prev = b;
    for (std::size_t i = 0; i < n; ++i) {
      q_prev[i] = q[i];
      q[i] = w[i] / b;
    }
  }
  return result;
}

}  // namespace mesowave
