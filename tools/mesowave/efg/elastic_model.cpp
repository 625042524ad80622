#include "mesowave/efg/elastic_model.hpp"

#include <Eigen/LU>
#include <omp.h>
#include <algorithm>
#include <cmath>
#include <string>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::efg {

namespace {

// B of Eq. (17) for the support of one point: 3 x 2n, columns (u_x, u_y) per support node.
Eigen::MatrixXd strain_matrix(const ShapeFunctions& sf) {
  const auto n = Eigen::Index(sf.nodes.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(3, 2 * n);
  for (Eigen::Index a = 0; a < n; ++a) {
    const double dx = sf.dphi_dx[std::size_t(a)], dy = sf.dphi_dy[std::size_t(a)];
    B(0, 2 * a) = dx;
    B(1, 2 * a + 1) = dy;
    B(2, 2 * a) = dy;
    B(2, 2 * a + 1) = dx;
  }
  return B;
}

// Position of row `row` in column `col` of a compressed column matrix (the row is in the pattern).
Eigen::Index position(const Eigen::SparseMatrix<double>& m, Eigen::Index col, Eigen::Index row) {
  const int* begin = m.innerIndexPtr() + m.outerIndexPtr()[col];
  const int* end = m.innerIndexPtr() + m.outerIndexPtr()[col + 1];
  return Eigen::Index(std::lower_bound(begin, end, int(row)) - m.innerIndexPtr());
}

std::string point_text(const Vec2& x) {
  return "(" + format_number(x.x()) + ", " + format_number(x.y()) + ") m";
}

}  // namespace

Eigen::Vector3d strain_of(const ShapeFunctions& sf, const Eigen::VectorXd& u) {
  Eigen::Vector3d eps = Eigen::Vector3d::Zero();
  for (std::size_t a = 0; a < sf.nodes.size(); ++a) {
    const double ux = u[2 * Eigen::Index(sf.nodes[a])], uy = u[2 * Eigen::Index(sf.nodes[a]) + 1];
    eps[0] += sf.dphi_dx[a] * ux;
    eps[1] += sf.dphi_dy[a] * uy;
    eps[2] += sf.dphi_dy[a] * ux + sf.dphi_dx[a] * uy;
  }
  return eps;
}

Eigen::Vector2d displacement_of(const ShapeFunctions& sf, const Eigen::VectorXd& u) {
  Eigen::Vector2d d = Eigen::Vector2d::Zero();
  for (std::size_t a = 0; a < sf.nodes.size(); ++a)
    d += sf.phi[a] * u.segment<2>(2 * Eigen::Index(sf.nodes[a]));
  return d;
}

ElasticModel::ElasticModel(const Discretisation& disc, ElasticMaterial2D material, const MlsApproximation& mls)
    : disc_(disc), material_(material), D_(material.D()), mls_(&mls) {
  if (disc_.nodes.size() != mls.node_count())
    throw InputError("the discretisation has " + std::to_string(disc_.nodes.size()) + " nodes, the MLS approximation " +
                     std::to_string(mls.node_count()) + ": they must be the same nodes");
  update_shape_functions();
}

void ElasticModel::update_shape_functions() {
  const std::uint64_t version = mls_->cracks() ? mls_->cracks()->version() : 0;
  if (have_shape_ && version == crack_version_) return;
  std::vector<ShapeFunctions> shape(disc_.points.size());
  // evaluate() is const and independent per point; an InputError is carried out of the loop.
  std::string error;
  const auto n = std::int64_t(disc_.points.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t p = 0; p < n; ++p) {
    const GaussPoint& g = disc_.points[std::size_t(p)];
    try {
      shape[std::size_t(p)] =
          mls_->evaluate(g.x, "Gauss point " + std::to_string(p) + " of cell " + std::to_string(g.cell));
    } catch (const InputError& e) {
#pragma omp critical(efg_shape_error)
      if (error.empty()) error = e.what();
    }
  }
  if (!error.empty()) throw InputError(error);
  shape_ = std::move(shape);
  crack_version_ = version;
  have_shape_ = true;
  build_pattern();
}

void ElasticModel::build_pattern() {
  // Node I couples with node J when a Gauss point has both in its support: per node, the points
  // whose support holds it, their nodes gathered once each (a stamp per node), then sorted.
  const std::size_t nodes = mls_->node_count();
  std::vector<std::vector<std::int32_t>> points_of(nodes);
  for (std::size_t p = 0; p < shape_.size(); ++p)
    for (std::int32_t i : shape_[p].nodes) points_of[std::size_t(i)].push_back(std::int32_t(p));
  std::vector<std::vector<std::int32_t>> neighbours(nodes);
  std::vector<std::int64_t> stamp(nodes, -1);
  for (std::size_t j = 0; j < nodes; ++j) {
    for (std::int32_t p : points_of[j])
      for (std::int32_t i : shape_[std::size_t(p)].nodes)
        if (stamp[std::size_t(i)] != std::int64_t(j)) {
          stamp[std::size_t(i)] = std::int64_t(j);
          neighbours[j].push_back(i);
        }
    std::sort(neighbours[j].begin(), neighbours[j].end());
  }
  // The compressed arrays written directly (columns 2j, 2j+1 hold rows 2i, 2i+1 of every neighbour i,
  // ascending): the same pattern as inserting entry by entry, which took a quarter of a cracked run's time.
  std::vector<int> outer(2 * nodes + 1, 0), inner;
  for (std::size_t j = 0; j < nodes; ++j)
    for (int c = 0; c < 2; ++c) {
      for (std::int32_t i : neighbours[j]) inner.push_back(2 * i), inner.push_back(2 * i + 1);
      outer[2 * j + std::size_t(c) + 1] = int(inner.size());
    }
  const std::vector<double> zeros(inner.size(), 0.0);
  pattern_ = Eigen::Map<const Eigen::SparseMatrix<double>>(Eigen::Index(2 * nodes), Eigen::Index(2 * nodes),
                                                           Eigen::Index(inner.size()), outer.data(), inner.data(), zeros.data());
}

Eigen::SparseMatrix<double> ElasticModel::stiffness() const {
  Eigen::SparseMatrix<double> K = pattern_;
  double* values = K.valuePtr();
  const int* outer = K.outerIndexPtr();
  const double t = material_.thickness_m;
  const auto nodes = std::int64_t(mls_->node_count());
  // Blocks of a chunk of points in parallel; then each thread adds them, in point order, to the
  // columns of its own range of nodes: every entry is summed in point order (the same bits for any
  // thread count) and no two threads write one entry.
  constexpr std::size_t chunk = 1024;
  std::vector<Eigen::MatrixXd> blocks(std::min(chunk, shape_.size()));
#pragma omp parallel
  {
    const std::int64_t threads = omp_get_num_threads(), me = omp_get_thread_num();
    const std::int64_t lo = nodes * me / threads, hi = nodes * (me + 1) / threads;
    for (std::size_t p0 = 0; p0 < shape_.size(); p0 += chunk) {
      const std::size_t p1 = std::min(shape_.size(), p0 + chunk);
#pragma omp for schedule(static)
      for (std::int64_t p = std::int64_t(p0); p < std::int64_t(p1); ++p) {
        const Eigen::MatrixXd B = strain_matrix(shape_[std::size_t(p)]);
        blocks[std::size_t(p) - p0].noalias() = B.transpose() * (D_ * B) * (t * disc_.points[std::size_t(p)].weight_m2);
      }
      for (std::size_t p = p0; p < p1; ++p) {
        const ShapeFunctions& sf = shape_[p];
        const Eigen::MatrixXd& k = blocks[p - p0];
        for (std::size_t b = 0; b < sf.nodes.size(); ++b) {
          const std::int64_t J = sf.nodes[b];
          if (J < lo || J >= hi) continue;
          // columns 2J and 2J+1 have the same rows: one search finds the 2 x 2 block in both
          const Eigen::Index next = outer[2 * J + 1] - outer[2 * J];
          for (std::size_t a = 0; a < sf.nodes.size(); ++a) {
            const Eigen::Index pos = position(K, 2 * J, 2 * Eigen::Index(sf.nodes[a]));
            const Eigen::Index ra = 2 * Eigen::Index(a), cb = 2 * Eigen::Index(b);
            values[pos] += k(ra, cb);
            values[pos + 1] += k(ra + 1, cb);
            values[pos + next] += k(ra, cb + 1);
            values[pos + next + 1] += k(ra + 1, cb + 1);
          }
        }
      }
#pragma omp barrier
    }
  }
  return K;
}

Eigen::VectorXd ElasticModel::internal_force(const Eigen::VectorXd& u) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(Eigen::Index(dof_count()));
  const double t = material_.thickness_m;
  for (std::size_t p = 0; p < shape_.size(); ++p) {
    const ShapeFunctions& sf = shape_[p];
    const Eigen::Vector3d s = D_ * strain_of(sf, u) * (t * disc_.points[p].weight_m2);  // sigma t w
    for (std::size_t a = 0; a < sf.nodes.size(); ++a) {  // B^T sigma t w
      const Eigen::Index i = 2 * Eigen::Index(sf.nodes[a]);
      f[i] += sf.dphi_dx[a] * s[0] + sf.dphi_dy[a] * s[2];
      f[i + 1] += sf.dphi_dy[a] * s[1] + sf.dphi_dx[a] * s[2];
    }
  }
  return f;
}

Eigen::Vector3d ElasticModel::strain(const Vec2& x, const Eigen::VectorXd& u) const {
  return strain_of(mls_->evaluate(x, "strain point"), u);
}

Eigen::Vector3d ElasticModel::stress(const Vec2& x, const Eigen::VectorXd& u) const { return D_ * strain(x, u); }

Eigen::Vector2d ElasticModel::displacement(const Vec2& x, const Eigen::VectorXd& u) const {
  return displacement_of(mls_->evaluate(x, "displacement point"), u);
}

Eigen::Vector3d ElasticModel::strain_at_point(std::size_t p, const Eigen::VectorXd& u) const {
  return strain_of(shape_.at(p), u);
}

std::size_t ElasticModel::dof_count() const { return 2 * mls_->node_count(); }

Eigen::VectorXd ElasticModel::traction_load(const Segment& edge, const std::function<Eigen::Vector2d(const Vec2&)>& t,
                                            int gauss) const {
  const GaussRule rule = gauss_legendre(gauss);
  const double length = (edge.b - edge.a).norm();
  if (!std::isfinite(length) || length <= 0)
    throw InputError("traction edge " + point_text(edge.a) + " - " + point_text(edge.b) + " has no length");
  const int pieces = std::max(1, int(std::ceil(length / disc_.spacing_m - 1e-9)));
  Eigen::VectorXd f = Eigen::VectorXd::Zero(Eigen::Index(dof_count()));
  for (int k = 0; k < pieces; ++k)
    for (std::size_t q = 0; q < rule.x.size(); ++q) {
      const double s = (k + 0.5 * (rule.x[q] + 1.0)) / pieces;  // in [0, 1] along a -> b
      const Vec2 x = edge.a + s * (edge.b - edge.a);
      const double w = rule.w[q] * 0.5 * length / pieces * material_.thickness_m;
      const Eigen::Vector2d tx = t(x) * w;
      const ShapeFunctions sf = mls_->evaluate(x, "traction point on the edge " + point_text(edge.a) + " - " + point_text(edge.b));
      for (std::size_t a = 0; a < sf.nodes.size(); ++a) f.segment<2>(2 * Eigen::Index(sf.nodes[a])) += sf.phi[a] * tx;
    }
  return f;
}

Eigen::VectorXd ElasticModel::point_load(const Vec2& x, const Eigen::Vector2d& force_N) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(Eigen::Index(dof_count()));
  const ShapeFunctions sf = mls_->evaluate(x, "point load");
  for (std::size_t a = 0; a < sf.nodes.size(); ++a) f.segment<2>(2 * Eigen::Index(sf.nodes[a])) += sf.phi[a] * force_N;
  return f;
}

Eigen::VectorXd ElasticModel::body_load(const Eigen::Vector2d& b_N_m3) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(Eigen::Index(dof_count()));
  for (std::size_t p = 0; p < shape_.size(); ++p) {
    const ShapeFunctions& sf = shape_[p];
    const Eigen::Vector2d bw = b_N_m3 * (material_.thickness_m * disc_.points[p].weight_m2);
    for (std::size_t a = 0; a < sf.nodes.size(); ++a) f.segment<2>(2 * Eigen::Index(sf.nodes[a])) += sf.phi[a] * bw;
  }
  return f;
}

ErrorNorms relative_error(const std::vector<GaussPoint>& quadrature, const Eigen::Matrix3d& D, const ElasticFieldAt& approx,
                          const ElasticFieldAt& exact) {
  const Eigen::Matrix3d C = D.inverse();  // compliance
  double du = 0, uu = 0, de = 0, ee = 0;
  for (const GaussPoint& g : quadrature) {
    const auto [u_h, s_h] = approx(g.x);
    const auto [u_exact, s_exact] = exact(g.x);
    const Eigen::Vector3d e_s = s_h - s_exact;
    du += g.weight_m2 * (u_h - u_exact).squaredNorm();
    uu += g.weight_m2 * u_exact.squaredNorm();
    de += g.weight_m2 * e_s.dot(C * e_s);
    ee += g.weight_m2 * s_exact.dot(C * s_exact);
  }
  return {std::sqrt(du / uu), std::sqrt(de / ee)};
}

ErrorNorms relative_error(const ElasticModel& model, const Eigen::VectorXd& u, const std::vector<GaussPoint>& quadrature,
                          const ElasticFieldAt& exact) {
  return relative_error(quadrature, model.D(), [&](const Vec2& x) {
    const ShapeFunctions sf = model.mls().evaluate(x, "error quadrature point");
    return std::pair<Eigen::Vector2d, Eigen::Vector3d>{displacement_of(sf, u), model.D() * strain_of(sf, u)};
  }, exact);
}

}  // namespace mesowave::efg
