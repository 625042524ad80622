#include "mesowave/efg/constraints.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::efg {

namespace {

std::string describe(const PointConstraint& c, std::size_t k) {
  return "constraint " + std::to_string(k) + (c.name.empty() ? "" : " '" + c.name + "'") + " (u_" +
         (c.component == 0 ? "x" : c.component == 1 ? "y" : std::to_string(c.component)) + " at (" +
         format_number(c.x.x()) + ", " + format_number(c.x.y()) + ") m)";
}

}  // namespace

ConstraintSet::ConstraintSet(const ElasticModel& model, std::vector<PointConstraint> constraints,
                             std::vector<EdgeConstraint> edges)
    : constraints_(std::move(constraints)) {
  const auto n = Eigen::Index(model.dof_count());
  // Each row as (node, coefficient) pairs on one component, its value and its name.
  struct Row {
    std::vector<std::pair<std::int32_t, double>> terms;
    double value = 0;
    int component = 0;
    std::string name;
  };
  std::vector<Row> rows;
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const PointConstraint& c = constraints_[k];
    const std::string name = describe(c, k);
    if (c.component != 0 && c.component != 1) throw InputError(name + ": the component must be 0 (x) or 1 (y)");
    if (!std::isfinite(c.value_m)) throw InputError(name + ": the value " + format_number(c.value_m) + " is not finite");
    const ShapeFunctions sf = model.mls().evaluate(c.x, name);
    Row row{{}, c.value_m, c.component, name};
    for (std::size_t a = 0; a < sf.nodes.size(); ++a) row.terms.emplace_back(sf.nodes[a], sf.phi[a]);
    rows.push_back(std::move(row));
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const EdgeConstraint& c = edges[e];
    const std::string name = "edge constraint " + std::to_string(e) + (c.name.empty() ? "" : " '" + c.name + "'") +
                             " (u_" + (c.component == 0 ? "x" : "y") + " on (" + format_number(c.edge.a.x()) + ", " +
                             format_number(c.edge.a.y()) + ") - (" + format_number(c.edge.b.x()) + ", " +
                             format_number(c.edge.b.y()) + ") m)";
    if (c.component != 0 && c.component != 1) throw InputError(name + ": the component must be 0 (x) or 1 (y)");
    if (!c.value_m) throw InputError(name + ": no value function");
    const double length = (c.edge.b - c.edge.a).norm();
    if (!std::isfinite(length) || length <= 0) throw InputError(name + ": the segment has no length");
    const int pieces = c.pieces > 0 ? c.pieces : std::max(1, int(std::ceil(length / model.discretisation().spacing_m - 1e-9)));
    const GaussRule rule = gauss_legendre(c.gauss);
    const std::size_t first = rows.size();
    for (int k = 0; k <= pieces; ++k) rows.push_back({{}, 0.0, c.component, name + " hat " + std::to_string(k)});
    std::vector<double> hat_integral(std::size_t(pieces) + 1, 0.0);
    for (int piece = 0; piece < pieces; ++piece)
      for (std::size_t q = 0; q < rule.x.size(); ++q) {
        const double xi = 0.5 * (rule.x[q] + 1.0), w = 0.5 * rule.w[q] * length / pieces;
        const Vec2 x = c.edge.a + (piece + xi) / pieces * (c.edge.b - c.edge.a);
        const double value = c.value_m(x);
        if (!std::isfinite(value)) throw InputError(name + ": the value " + format_number(value) + " is not finite");
        const ShapeFunctions sf = model.mls().evaluate(x, name);
        for (int side = 0; side < 2; ++side) {  // the hats at the piece's two ends
          const double N = side == 0 ? 1.0 - xi : xi;
          Row& row = rows[first + std::size_t(piece + side)];
          for (std::size_t a = 0; a < sf.nodes.size(); ++a) row.terms.emplace_back(sf.nodes[a], w * N * sf.phi[a]);
          row.value += w * N * value;
          hat_integral[std::size_t(piece + side)] += w * N;
        }
      }
    for (int k = 0; k <= pieces; ++k) {  // an average: the coefficients sum to 1, R_k is a force
      Row& row = rows[first + std::size_t(k)];
      for (auto& term : row.terms) term.second /= hat_integral[std::size_t(k)];
      row.value /= hat_integral[std::size_t(k)];
    }
    edge_rows_.emplace_back(first, rows.size());
  }
  const auto m = Eigen::Index(rows.size());
  if (m > n) throw InputError(std::to_string(m) + " constraint rows exceed the " + std::to_string(n) + " unknowns");

  for (const Row& row : rows)
    for (const auto& term : row.terms) involved_.push_back(2 * Eigen::Index(term.first) + row.component);
  std::sort(involved_.begin(), involved_.end());
  involved_.erase(std::unique(involved_.begin(), involved_.end()), involved_.end());
  std::map<Eigen::Index, Eigen::Index> local;  // dof -> column of C_involved_
  for (std::size_t j = 0; j < involved_.size(); ++j) local[involved_[j]] = Eigen::Index(j);
  const auto ni = Eigen::Index(involved_.size());
  C_involved_ = Eigen::MatrixXd::Zero(m, ni);
  d_ = Eigen::VectorXd(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Row& row = rows[std::size_t(k)];
    for (const auto& term : row.terms) C_involved_(k, local[2 * Eigen::Index(term.first) + row.component]) += term.second;
    d_[k] = row.value;
    names_.push_back(row.name);
    components_.push_back(row.component);
  }
  const Eigen::VectorXd& d = d_;
  std::vector<Eigen::Triplet<double>> c_entries;
  for (Eigen::Index k = 0; k < m; ++k)
    for (Eigen::Index j = 0; j < ni; ++j)
      if (C_involved_(k, j) != 0) c_entries.emplace_back(k, involved_[std::size_t(j)], C_involved_(k, j));
  C_ = Eigen::SparseMatrix<double>(m, n);
  C_.setFromTriplets(c_entries.begin(), c_entries.end());

  // Slaves: Gaussian elimination on the rows in order, pivot = the largest remaining coefficient.
  Eigen::MatrixXd W = C_involved_;
  std::vector<Eigen::Index> slave_local;
  std::vector<char> is_pivot(std::size_t(ni), 0);
  for (Eigen::Index k = 0; k < m; ++k) {
    Eigen::Index best = -1;
    double best_abs = 0;
    for (Eigen::Index j = 0; j < ni; ++j)
      if (!is_pivot[std::size_t(j)] && std::abs(W(k, j)) > best_abs) best = j, best_abs = std::abs(W(k, j));
    if (best < 0 || best_abs <= 1e-10 * C_involved_.row(k).cwiseAbs().maxCoeff())
      throw InputError(names_[std::size_t(k)] + " repeats or contradicts the constraints before it (its row is a combination of theirs)");
    is_pivot[std::size_t(best)] = 1;
    slave_local.push_back(best);
    for (Eigen::Index r = k + 1; r < m; ++r)
      if (W(r, best) != 0) W.row(r) -= (W(r, best) / W(k, best)) * W.row(k);
  }
  std::vector<Eigen::Index> master_local;
  for (Eigen::Index j = 0; j < ni; ++j)
    if (!is_pivot[std::size_t(j)]) master_local.push_back(j);

  // u_S = C_S^-1 (s d - C_M u_M): the slaves' rows of T and g.
  Eigen::MatrixXd CS(m, m), CM(m, Eigen::Index(master_local.size()));
  for (Eigen::Index k = 0; k < m; ++k) CS.col(k) = C_involved_.col(slave_local[std::size_t(k)]);
  for (std::size_t q = 0; q < master_local.size(); ++q) CM.col(Eigen::Index(q)) = C_involved_.col(master_local[q]);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(CS);
  const Eigen::MatrixXd X = lu.solve(CM);
  const Eigen::VectorXd y = lu.solve(d);

  std::vector<char> is_slave(std::size_t(n), 0);
  for (Eigen::Index s : slave_local) is_slave[std::size_t(involved_[std::size_t(s)])] = 1;
  std::vector<Eigen::Index> reduced(std::size_t(n), -1);
  Eigen::Index nr = 0;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!is_slave[std::size_t(i)]) reduced[std::size_t(i)] = nr++;
  std::vector<Eigen::Triplet<double>> t_entries;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!is_slave[std::size_t(i)]) t_entries.emplace_back(i, reduced[std::size_t(i)], 1.0);
  g_ = Eigen::VectorXd::Zero(n);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Eigen::Index dof = involved_[std::size_t(slave_local[std::size_t(k)])];
    g_[dof] = y[k];
    for (std::size_t q = 0; q < master_local.size(); ++q)
      if (X(k, Eigen::Index(q)) != 0)
        t_entries.emplace_back(dof, reduced[std::size_t(involved_[std::size_t(master_local[q])])], -X(k, Eigen::Index(q)));
  }
  T_ = Eigen::SparseMatrix<double>(n, nr);
  T_.setFromTriplets(t_entries.begin(), t_entries.end());
}

Eigen::VectorXd ConstraintSet::expand(const Eigen::VectorXd& v, double scale) const { return T_ * v + scale * g_; }

std::size_t ConstraintSet::reduced_size() const { return std::size_t(T_.cols()); }

Eigen::SparseMatrix<double> ConstraintSet::reduce(const Eigen::SparseMatrix<double>& K) const {
  const Eigen::SparseMatrix<double> KT = K * T_;
  return Eigen::SparseMatrix<double>(T_.transpose() * KT);
}

Eigen::VectorXd ConstraintSet::reduce(const Eigen::VectorXd& r) const { return T_.transpose() * r; }

std::vector<double> ConstraintSet::reactions(const Eigen::VectorXd& full_residual) const {
  if (d_.size() == 0) return {};
  Eigen::VectorXd r(Eigen::Index(involved_.size()));
  for (std::size_t j = 0; j < involved_.size(); ++j) r[Eigen::Index(j)] = full_residual[involved_[j]];
  const Eigen::VectorXd R = C_involved_.transpose().colPivHouseholderQr().solve(r);  // C^T R = r
  return {R.data(), R.data() + R.size()};
}

Eigen::VectorXd ConstraintSet::violation(const Eigen::VectorXd& u, double scale) const { return C_ * u - scale * d_; }

LinearSolution solve_linear(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& f, const ConstraintSet& c,
                            double scale) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const Eigen::VectorXd g = c.g(scale);
  const Eigen::SparseMatrix<double> Kr = c.reduce(K);
  const Eigen::VectorXd fr = c.reduce(Eigen::VectorXd(f - K * g));
  const auto factor_start = clock::now();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(Kr);
  const double factorise_s = std::chrono::duration<double>(clock::now() - factor_start).count();
  const Eigen::VectorXd D = ldlt.info() == Eigen::Success ? Eigen::VectorXd(ldlt.vectorD()) : Eigen::VectorXd();
  if (D.size() == 0 || !(D.minCoeff() > 1e-12 * D.cwiseAbs().maxCoeff()))
    throw InputError("the reduced stiffness T^T K T (" + std::to_string(Kr.rows()) +
                     " unknowns) is not positive definite: the constraints leave a rigid-body motion free");
  LinearSolution s;
  s.u = c.expand(ldlt.solve(fr), scale);
  s.reactions_N = c.reactions(Eigen::VectorXd(K * s.u - f));
  s.solver = "Eigen::SimplicialLDLT (AMD ordering) on the reduced T^T K T";
  s.factorise_s = factorise_s;
  s.reduced_nonzeros = std::size_t(Kr.nonZeros());
  s.factor_nonzeros = std::size_t(ldlt.matrixL().nestedExpression().nonZeros());
  s.wall_s = std::chrono::duration<double>(clock::now() - start).count();
  return s;
}

}  // namespace mesowave::efg
