#include "mesowave/efg/cohesive_crack.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/efg/discretisation.hpp"

namespace mesowave::efg {

CohesiveInterface::CohesiveInterface(const MlsApproximation& mls, std::shared_ptr<const CohesiveLaw> law,
                                     double thickness_m, double face_offset_m, int gauss)
    : mls_(&mls),
      law_(std::move(law)),
      thickness_(thickness_m),
      offset_(face_offset_m),
      w_initial_(initial_opening_fraction * law_->w_max_m()),
      gauss_(gauss) {
  if (!(face_offset_m > 0)) throw InputError("cohesive interface: the face offset must be > 0");
}

void CohesiveInterface::evaluate_point(CohesivePoint& p) const {
  const std::string where = "cohesive point on segment " + std::to_string(p.segment);
  p.plus = mls_->evaluate(p.x + offset_ * p.normal, where + " (+ face)");
  p.minus = mls_->evaluate(p.x - offset_ * p.normal, where + " (- face)");
}

void CohesiveInterface::add_segment(const Segment& s) {
  const SegmentGauss g = segment_gauss_points(s, gauss_);
  if (g.points.empty()) throw InputError("cohesive interface: a segment of zero length");
  for (const SegmentGaussPoint& q : g.points) {
    CohesivePoint p;
    p.x = q.x;
    p.normal = g.normal;
    p.length_weight_m = q.length_weight_m;
    p.w_hist_m = w_initial_;
    p.segment = segments_.size();
    evaluate_point(p);
    points_.push_back(std::move(p));
  }
  segments_.push_back(s);
}

void CohesiveInterface::update_shape_functions() {
  for (auto& p : points_) evaluate_point(p);
}

namespace {

/// [u] = sum (phi+ - phi-) u_I over the union of both faces' nodes, through a visitor on (node, coefficient).
template <class F>
void for_jump(const CohesivePoint& p, F f) {
  for (std::size_t i = 0; i < p.plus.nodes.size(); ++i) f(p.plus.nodes[i], p.plus.phi[i]);
  for (std::size_t i = 0; i < p.minus.nodes.size(); ++i) f(p.minus.nodes[i], -p.minus.phi[i]);
}

}  // namespace

double CohesiveInterface::opening_m(std::size_t k, const Eigen::VectorXd& u) const {
  const auto& p = points_[k];
  Vec2 jump = Vec2::Zero();
  for_jump(p, [&](std::int32_t node, double c) { jump += c * Vec2(u[2 * node], u[2 * node + 1]); });
  return jump.dot(p.normal);
}

void CohesiveInterface::assemble(const Eigen::VectorXd& u, Eigen::VectorXd& force,
                                 std::vector<Eigen::Triplet<double>>* triplets) const {
  std::vector<std::pair<std::int32_t, double>> coeff;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const auto& p = points_[k];
    const auto c = cohesive_response(*law_, opening_m(k, u), p.w_hist_m, w_initial_);
    const double tw = thickness_ * p.length_weight_m;
    coeff.clear();
    for_jump(p, [&](std::int32_t node, double c_node) { coeff.emplace_back(node, c_node); });
    for (const auto& [node, ci] : coeff) {
      force[2 * node] += ci * p.normal.x() * c.traction_Pa * tw;
      force[2 * node + 1] += ci * p.normal.y() * c.traction_Pa * tw;
    }
    if (!triplets) continue;
    const double k_tw = c.tangent_Pa_per_m * tw;
    for (const auto& [a, ca] : coeff)
      for (const auto& [b, cb] : coeff)
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j)
            triplets->emplace_back(2 * a + i, 2 * b + j, ca * cb * p.normal[i] * p.normal[j] * k_tw);
  }
}

std::vector<CohesivePointState> CohesiveInterface::point_states(const Eigen::VectorXd& u) const {
  std::vector<CohesivePointState> out;
  out.reserve(points_.size());
  for (std::size_t k = 0; k < points_.size(); ++k) {
    CohesivePointState s;
    s.opening_m = opening_m(k, u);
    s.traction_Pa = cohesive_response(*law_, s.opening_m, points_[k].w_hist_m, w_initial_).traction_Pa;
    const double reached = std::max(points_[k].w_hist_m, s.opening_m);
    s.damage = reached <= w_initial_ ? 0.0 : 1.0 - law_->traction_Pa(reached) / law_->f_t_Pa();
    out.push_back(s);
  }
  return out;
}

void CohesiveInterface::commit(const Eigen::VectorXd& u) {
  for (std::size_t k = 0; k < points_.size(); ++k) points_[k].w_hist_m = std::max(points_[k].w_hist_m, opening_m(k, u));
}

double CohesiveInterface::dissipated_energy_J() const {
  const GaussRule rule = gauss_legendre(8);
  const double s0 = law_->traction_Pa(w_initial_);
  double total = 0;
  for (const auto& p : points_) {
    const double wh = std::min(p.w_hist_m, law_->w_max_m());
    if (wh <= w_initial_) continue;
    // the path: the initial secant to w_initial, the envelope to w_hist; still stored: the secant triangle at w_hist
    double area = 0.5 * s0 * w_initial_;
    const int pieces = 16;
    const double h = (wh - w_initial_) / pieces;
    for (int i = 0; i < pieces; ++i)
      for (std::size_t q = 0; q < rule.x.size(); ++q)
        area += 0.5 * h * rule.w[q] * law_->traction_Pa(w_initial_ + h * (i + 0.5 * (1 + rule.x[q])));
    total += (area - 0.5 * law_->traction_Pa(wh) * wh) * thickness_ * p.length_weight_m;
  }
  return total;
}

double CohesiveInterface::stored_energy_J(const Eigen::VectorXd& u) const {
  double total = 0;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const double w = opening_m(k, u);
    if (w > points_[k].w_hist_m) continue;  // only committed states are asked for
    total += 0.5 * cohesive_response(*law_, w, points_[k].w_hist_m, w_initial_).traction_Pa * w * thickness_ *
             points_[k].length_weight_m;
  }
  return total;
}

// ---- the problem ----

CohesiveCrackProblem::CohesiveCrackProblem(ElasticModel& model, const ConstraintSet& constraints, CohesiveInterface& interface)
    : model_(&model), constraints_(&constraints), interface_(&interface) {
  K_ = model_->stiffness();
  K_reduced_ = constraints_->reduce(K_);
}

void CohesiveCrackProblem::update() {
  model_->update_shape_functions();
  interface_->update_shape_functions();
  K_ = model_->stiffness();
  K_reduced_ = constraints_->reduce(K_);
}

double CohesiveCrackProblem::stored_energy_J(const Eigen::VectorXd& u) const {
  return 0.5 * u.dot(K_ * u) + interface_->stored_energy_J(u);
}

Eigen::VectorXd CohesiveCrackProblem::internal_force(const Eigen::VectorXd& u) const {
  Eigen::VectorXd f = K_ * u;
  interface_->assemble(u, f, nullptr);
  return f;
}

void CohesiveCrackProblem::evaluate(const Eigen::VectorXd& v, double lambda, Eigen::VectorXd& residual,
                                    Eigen::SparseMatrix<double>* tangent, Eigen::VectorXd* load_derivative) {
  const Eigen::VectorXd u = constraints_->expand(v, lambda);
  Eigen::VectorXd f = K_ * u;
  std::vector<Eigen::Triplet<double>> triplets;
  const bool need_tangent = tangent || load_derivative;
  interface_->assemble(u, f, need_tangent ? &triplets : nullptr);
  residual = constraints_->reduce(f);
  if (!need_tangent) return;
  Eigen::SparseMatrix<double> Kc(K_.rows(), K_.cols());
  Kc.setFromTriplets(triplets.begin(), triplets.end());
  if (tangent) *tangent = K_reduced_ + constraints_->reduce(Kc);
  // dr/dlambda = T^T K_t dg/dlambda, g linear in lambda
  if (load_derivative) *load_derivative = constraints_->reduce(Eigen::VectorXd(K_ * constraints_->g(1.0) + Kc * constraints_->g(1.0)));
}

double CohesiveCrackProblem::step_limit(const Eigen::VectorXd&, const Eigen::VectorXd& dv, double) {
  const Eigen::VectorXd du = constraints_->T() * dv;  // at fixed lambda the prescribed part does not move
  double largest = 0;
  for (std::size_t k = 0; k < interface_->points().size(); ++k) largest = std::max(largest, std::abs(interface_->opening_m(k, du)));
  const double allowed = 0.25 * interface_->law().w_max_m();
  return largest > allowed ? allowed / largest : 1.0;
}

void CohesiveCrackProblem::commit(const Eigen::VectorXd& v, double lambda) { interface_->commit(constraints_->expand(v, lambda)); }

}  // namespace mesowave::efg
