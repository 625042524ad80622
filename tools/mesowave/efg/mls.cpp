#include "mesowave/efg/mls.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::efg {

Basis parse_basis(std::string_view name) {
  if (name == "linear") return Basis::linear;
  if (name == "quadratic") return Basis::quadratic;
  throw InputError("MLS basis '" + std::string(name) + "' unknown (linear | quadratic)");
}

WeightKind parse_weight_kind(std::string_view name) {
  if (name == "quartic-spline" || name == "quartic") return WeightKind::quartic_spline;
  if (name == "cubic-spline" || name == "cubic") return WeightKind::cubic_spline;
  throw InputError("MLS weight '" + std::string(name) + "' unknown (quartic-spline | cubic-spline)");
}

std::string_view to_string(Basis basis) { return basis == Basis::linear ? "linear" : "quadratic"; }
std::string_view to_string(WeightKind kind) {
  return kind == WeightKind::quartic_spline ? "quartic-spline" : "cubic-spline";
}

int basis_size(Basis basis) { return basis == Basis::linear ? 3 : 6; }

std::pair<double, double> weight(WeightKind kind, double s) {
  if (!(s < 1)) return {0.0, 0.0};
  if (kind == WeightKind::quartic_spline) {  // Eq. (12), factored: no cancellation (w < 0) near s = 1
    const double t = 1 - s;
    return {t * t * t * (1 + 3 * s), -12 * s * t * t};
  }
  if (s <= 0.5) return {1 - 6 * s * s + 6 * s * s * s, -12 * s + 18 * s * s};
  const double t = 1 - s;
  return {2 * t * t * t, -6 * t * t};
}

namespace {

std::string point_text(const Vec2& x, std::string_view where) {
  std::string s = "MLS shape functions at x = (" + format_number(x.x()) + ", " + format_number(x.y()) + ") m";
  if (!where.empty()) s += " (" + std::string(where) + ")";
  return s;
}

double validated_max_radius(const std::vector<Vec2>& nodes, const std::vector<double>& radius) {
  if (nodes.size() != radius.size())
    throw InputError("MLS: " + std::to_string(nodes.size()) + " nodes but " + std::to_string(radius.size()) +
                     " support radii");
  if (nodes.empty()) throw InputError("MLS: no nodes");
  double max_radius = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    require_positive("MLS: support radius of node " + std::to_string(i), radius[i], "m");
    max_radius = std::max(max_radius, radius[i]);
  }
  return max_radius;
}

// A typical spacing of the nodes: the side of the square each would own in their bounding box.
double typical_spacing(const std::vector<Vec2>& nodes) {
  Vec2 lo = nodes.front(), hi = nodes.front();
  for (const auto& p : nodes) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec2 size = hi - lo;
  const double n = double(nodes.size());
  const double by_area = std::sqrt(size.x() * size.y() / n), by_length = size.norm() / n;
  return std::max(by_area, by_length);
}

}  // namespace

std::vector<double> support_radii_by_count(const std::vector<Vec2>& nodes, int count, double factor) {
  if (count < 1 || std::size_t(count) >= nodes.size())
    throw InputError("support radius by count: count " + std::to_string(count) + " must be in [1, " +
                     std::to_string(nodes.size()) + ") for " + std::to_string(nodes.size()) + " nodes");
  require_positive("support radius by count: factor", factor);
  const double spacing = typical_spacing(nodes);
  if (!(spacing > 0)) throw InputError("support radius by count: all nodes coincide");
  const NodeGrid grid(nodes, spacing);
  std::vector<double> radius(nodes.size());
  std::vector<std::int32_t> near;
  std::vector<double> distance;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    // Grow the search circle until it holds `count` other nodes: the count-th nearest is then inside.
    for (double r = spacing;; r *= 2) {
      grid.within(nodes[i], r, near);
      if (near.size() < std::size_t(count) + 1) continue;
      distance.clear();
      for (const auto j : near)
        if (std::size_t(j) != i) distance.push_back((nodes[std::size_t(j)] - nodes[i]).norm());
      std::nth_element(distance.begin(), distance.begin() + (count - 1), distance.end());
      radius[i] = factor * distance[std::size_t(count - 1)];
      break;
    }
    if (!(radius[i] > 0))
      throw InputError("support radius by count: node " + std::to_string(i) + " coincides with its " +
                       std::to_string(count) + " nearest nodes");
  }
  return radius;
}

std::vector<double> support_radii_by_spacing(const std::vector<Vec2>& nodes, double spacing_m, double scale) {
  require_positive("support radius by spacing: spacing", spacing_m, "m");
  require_positive("support radius by spacing: scale", scale);
  return std::vector<double>(nodes.size(), scale * spacing_m);
}

MlsApproximation::MlsApproximation(std::vector<Vec2> nodes, std::vector<double> support_radius_m,
                                   MlsOptions options, const CrackSet* cracks)
    : nodes_(std::move(nodes)),
      radius_(std::move(support_radius_m)),
      options_(options),
      cracks_(cracks),
      max_radius_(validated_max_radius(nodes_, radius_)),
      grid_(nodes_, max_radius_) {
  if (!(options_.max_condition_number > 1))
    throw InputError("MLS: max condition number (" + format_number(options_.max_condition_number) + ") must be > 1");
}

double MlsApproximation::interpolate(const ShapeFunctions& sf, const std::vector<double>& u) const {
  double sum = 0;
  for (std::size_t k = 0; k < sf.nodes.size(); ++k) sum += sf.phi[k] * u.at(std::size_t(sf.nodes[k]));
  return sum;
}

ShapeFunctions MlsApproximation::evaluate(const Vec2& x, std::string_view where) const {
  using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
  using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
  if (!x.allFinite()) throw InputError(point_text(x, where) + ": the point is not finite");
  const int m = basis_size(options_.basis);
  const bool with_cracks = cracks_ != nullptr && !cracks_->empty();

  // Weights and their gradients, Eq. (10), of every node whose (possibly bent) distance is inside its support.
  // Scratch reused between calls of one thread (evaluate stays safe to call concurrently).
  thread_local std::vector<std::int32_t> candidates;
  thread_local std::vector<double> w, wx, wy;
  grid_.within(x, max_radius_, candidates);
  w.clear();
  wx.clear();
  wy.clear();
  ShapeFunctions sf;
  sf.nodes.reserve(candidates.size());
  double h = 0;
  for (const auto i : candidates) {
    const Vec2& xi = nodes_[std::size_t(i)];
    const double hi = radius_[std::size_t(i)];
    const Vec2 r = x - xi;
    const double s0 = r.norm();
    if (!(s0 < hi)) continue;
    WeightDistance d{s0, s0 > 0 ? Vec2(r / s0) : Vec2::Zero()};
    if (with_cracks)
      d = cracks_->weight_distance_gradient(xi, x, options_.crack_method, options_.diffraction_lambda, hi,
                                            options_.transparency);
    if (d.cut() || !(d.d < hi)) continue;
    const auto [wi, dwi] = weight(options_.weight, d.d / hi);
    if (!(wi > 0)) continue;
    sf.nodes.push_back(i);
    w.push_back(wi);
    wx.push_back(dwi / hi * d.gradient.x());
    wy.push_back(dwi / hi * d.gradient.y());
    h = std::max(h, hi);
  }
  const std::size_t n = sf.nodes.size();
  if (n < std::size_t(m))
    throw InputError(point_text(x, where) + ": " + std::to_string(n) + " nodes reach the point, the " +
                     std::string(to_string(options_.basis)) + " basis needs at least " + std::to_string(m) +
                     " (supports too small near a crack, notch or corner)");

  // Basis in shifted, scaled coordinates (x_I - x) / h: p(x) = (1, 0, ...), p_x = (0, 1/h, 0, ...).
  Eigen::MatrixXd P(m, Eigen::Index(n));
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 xi = (nodes_[std::size_t(sf.nodes[k])] - x) / h;
    P(0, Eigen::Index(k)) = 1;
    P(1, Eigen::Index(k)) = xi.x();
    P(2, Eigen::Index(k)) = xi.y();
    if (m == 6) {
      P(3, Eigen::Index(k)) = xi.x() * xi.x();
      P(4, Eigen::Index(k)) = xi.x() * xi.y();
      P(5, Eigen::Index(k)) = xi.y() * xi.y();
    }
  }
  Mat A = Mat::Zero(m, m), Ax = Mat::Zero(m, m), Ay = Mat::Zero(m, m);  // Eq. (4) and its derivatives
  for (std::size_t k = 0; k < n; ++k) {
    const auto pk = P.col(Eigen::Index(k));
    const Mat ppT = pk * pk.transpose();
    A += w[k] * ppT;
    Ax += wx[k] * ppT;
    Ay += wy[k] * ppT;
  }
  // Cholesky, not Eigen's LDLT: LDLT solves with a pseudo-inverse of D, which hides a singular A
  // (and its rcond then describes the pseudo-inverse). A is symmetric positive definite when it is
  // regular; a non-positive pivot means singular.
  const Eigen::LLT<Mat> llt(A);
  const double rcond = llt.info() == Eigen::Success ? llt.rcond() : 0.0;
  sf.condition_number = rcond > 0 ? 1 / rcond : std::numeric_limits<double>::infinity();
  if (!(sf.condition_number <= options_.max_condition_number)) {
    const std::string why = rcond > 0 ? "condition number " + format_significant(sf.condition_number, 3) + " > " +
                                            format_number(options_.max_condition_number)
                                      : std::string("a Cholesky pivot <= 0");
    throw InputError(point_text(x, where) + ": moment matrix A singular or ill-conditioned (" + why + ") with " +
                     std::to_string(n) + " nodes in reach (nodes collinear or too few around the point)");
  }
  Vec p = Vec::Zero(m), px = Vec::Zero(m), py = Vec::Zero(m);
  p(0) = 1;
  px(1) = 1 / h;
  py(2) = 1 / h;
  const Vec gamma = llt.solve(p);
  const Vec gx = llt.solve(px - Ax * gamma), gy = llt.solve(py - Ay * gamma);
  sf.phi.resize(n);
  sf.dphi_dx.resize(n);
  sf.dphi_dy.resize(n);
  for (std::size_t k = 0; k < n; ++k) {  // Eq. (9) and its derivatives
    const auto pk = P.col(Eigen::Index(k));
    const double gp = gamma.dot(pk);
    sf.phi[k] = w[k] * gp;
    sf.dphi_dx[k] = w[k] * gx.dot(pk) + wx[k] * gp;
    sf.dphi_dy[k] = w[k] * gy.dot(pk) + wy[k] * gp;
  }
  return sf;
}

}  // namespace mesowave::efg
