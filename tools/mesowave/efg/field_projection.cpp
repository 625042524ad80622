#include "mesowave/efg/field_projection.hpp"

#include <algorithm>
#include <stdexcept>

#include "mesowave/efg/elastic_model.hpp"

namespace mesowave::efg {

namespace {

bool same(const ShapeFunctions& a, const ShapeFunctions& b) {
  return a.nodes == b.nodes && a.phi == b.phi && a.dphi_dx == b.dphi_dx && a.dphi_dy == b.dphi_dy;
}

}  // namespace

ParameterProjection::ParameterProjection(const std::vector<ShapeFunctions>& before, const std::vector<ShapeFunctions>& after,
                                         const std::vector<double>& point_mass_kg, std::size_t node_count) {
  if (before.size() != after.size() || before.size() != point_mass_kg.size())
    throw std::invalid_argument("parameter projection: " + std::to_string(before.size()) + " points before, " +
                                std::to_string(after.size()) + " after, " + std::to_string(point_mass_kg.size()) + " masses");
  local_.assign(node_count, -1);
  std::vector<char> in_a(node_count, 0);
  for (std::size_t g = 0; g < before.size(); ++g) {
    if (same(before[g], after[g])) continue;
    ++changed_;
    for (std::int32_t i : after[g].nodes) in_a[std::size_t(i)] = 1;
  }
  if (changed_ == 0) return;
  for (std::size_t i = 0; i < node_count; ++i)
    if (in_a[i]) {
      local_[i] = std::int32_t(nodes_.size());
      nodes_.push_back(std::int32_t(i));
    }
  for (std::size_t g = 0; g < after.size(); ++g) {
    bool touches = false;
    for (std::int32_t i : after[g].nodes) touches = touches || in_a[std::size_t(i)];
    if (!touches) continue;
    points_.push_back(std::int32_t(g));
    before_.push_back(before[g]);
    after_.push_back(after[g]);
    mass_.push_back(point_mass_kg[g]);
  }
  // N = sum_g m_g phi_A phi_A^T, in point order (setFromTriplets sums duplicates in insertion order)
  std::vector<Eigen::Triplet<double>> triplets;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const ShapeFunctions& sf = after_[k];
    for (std::size_t a = 0; a < sf.nodes.size(); ++a) {
      const std::int32_t la = local_[std::size_t(sf.nodes[a])];
      if (la < 0) continue;
      for (std::size_t b = 0; b < sf.nodes.size(); ++b) {
        const std::int32_t lb = local_[std::size_t(sf.nodes[b])];
        if (lb >= 0) triplets.emplace_back(la, lb, mass_[k] * sf.phi[a] * sf.phi[b]);
      }
    }
  }
  const auto n = Eigen::Index(nodes_.size());
  Eigen::SparseMatrix<double> N(n, n);
  N.setFromTriplets(triplets.begin(), triplets.end());
  ldlt_.compute(N);
  ok_ = ldlt_.info() == Eigen::Success;
  if (ok_) {
    const Eigen::VectorXd d = ldlt_.vectorD();
    ok_ = d.minCoeff() > 1e-12 * d.maxCoeff();
  }
}

Eigen::VectorXd ParameterProjection::fit(const Eigen::VectorXd& u_fixed,
                                         const std::function<Eigen::Vector2d(std::int32_t)>& target) const {
  Eigen::VectorXd out = u_fixed;
  if (changed_ == 0 || !ok_) return out;
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(Eigen::Index(nodes_.size()), 2);
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const ShapeFunctions& sf = after_[k];
    Eigen::Vector2d r = target(points_[k]);  // the target less the fixed nodes' share of the new field
    for (std::size_t a = 0; a < sf.nodes.size(); ++a) {
      const auto i = std::size_t(sf.nodes[a]);
      if (local_[i] < 0) r -= sf.phi[a] * Eigen::Vector2d(u_fixed[Eigen::Index(2 * i)], u_fixed[Eigen::Index(2 * i + 1)]);
    }
    for (std::size_t a = 0; a < sf.nodes.size(); ++a) {
      const std::int32_t la = local_[std::size_t(sf.nodes[a])];
      if (la >= 0) b.row(la) += mass_[k] * sf.phi[a] * r.transpose();
    }
  }
  const Eigen::MatrixXd x = ldlt_.solve(b);
  for (std::size_t l = 0; l < nodes_.size(); ++l) {
    const auto i = Eigen::Index(nodes_[l]);
    out[2 * i] = x(Eigen::Index(l), 0);
    out[2 * i + 1] = x(Eigen::Index(l), 1);
  }
  return out;
}

Eigen::VectorXd ParameterProjection::project(const Eigen::VectorXd& u) const {
  return fit(u, [&](std::int32_t g) {
    const auto k = std::size_t(std::lower_bound(points_.begin(), points_.end(), g) - points_.begin());
    return displacement_of(before_[k], u);
  });
}

double ParameterProjection::relative_misfit(const Eigen::VectorXd& u, const Eigen::VectorXd& u_projected) const {
  double misfit = 0, norm = 0;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const Eigen::Vector2d target = displacement_of(before_[k], u);
    misfit += mass_[k] * (displacement_of(after_[k], u_projected) - target).squaredNorm();
    norm += mass_[k] * target.squaredNorm();
  }
  return norm > 0 ? misfit / norm : 0.0;
}

}  // namespace mesowave::efg
