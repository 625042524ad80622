#include "mesowave/efg/discretisation.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::efg {

namespace {

std::string point_text(const Vec2& x) {
  return "(" + format_number(x.x()) + ", " + format_number(x.y()) + ") m";
}

}  // namespace

GaussRule gauss_legendre(int n) {
  if (n < 1 || n > 64) throw InputError("Gauss points per direction (" + std::to_string(n) + ") must lie in [1, 64]");
  // Jacobi matrix of the Legendre recurrence: off-diagonal k / sqrt(4 k^2 - 1).
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  for (int k = 1; k < n; ++k) J(k, k - 1) = J(k - 1, k) = k / std::sqrt(4.0 * k * k - 1.0);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(J);
  GaussRule rule;
  for (int i = 0; i < n; ++i) {
    rule.x.push_back(eig.eigenvalues()(i));
    rule.w.push_back(2.0 * eig.eigenvectors()(0, i) * eig.eigenvectors()(0, i));
  }
  // The rule is symmetric: symmetrise what rounding left, so a symmetric body integrates symmetrically.
  for (int i = 0; i < n / 2; ++i) {
    const double x = 0.5 * (rule.x[std::size_t(n - 1 - i)] - rule.x[std::size_t(i)]);
    const double w = 0.5 * (rule.w[std::size_t(n - 1 - i)] + rule.w[std::size_t(i)]);
    rule.x[std::size_t(i)] = -x, rule.x[std::size_t(n - 1 - i)] = x;
    rule.w[std::size_t(i)] = rule.w[std::size_t(n - 1 - i)] = w;
  }
  if (n % 2 == 1) rule.x[std::size_t(n / 2)] = 0.0;
  return rule;
}

SegmentGauss segment_gauss_points(const Segment& s, int n) {
  SegmentGauss out;
  const Vec2 d = s.b - s.a;
  const double length = d.norm();
  if (!(length > 0)) return out;
  out.normal = Vec2(d.y() / length, -d.x() / length);
  const GaussRule rule = gauss_legendre(n);
  for (std::size_t q = 0; q < rule.x.size(); ++q)
    out.points.push_back({s.a + 0.5 * (1 + rule.x[q]) * d, 0.5 * rule.w[q] * length});
  return out;
}

Discretisation rectangular_grid(const Rect& body, int nx, int ny, int gauss, std::vector<Vec2> extra_nodes,
                                const std::function<bool(const Rect& cell)>& keep_cell) {
  if (!(std::isfinite(body.x0) && std::isfinite(body.x1) && std::isfinite(body.y0) && std::isfinite(body.y1)) ||
      !(body.x1 > body.x0) || !(body.y1 > body.y0))
    throw InputError("body [" + format_number(body.x0) + ", " + format_number(body.x1) + "] x [" +
                     format_number(body.y0) + ", " + format_number(body.y1) + "] m must have x1 > x0 and y1 > y0");
  if (nx < 1 || ny < 1)
    throw InputError("cells (" + std::to_string(nx) + " x " + std::to_string(ny) + ") must be at least 1 x 1");
  const GaussRule rule = gauss_legendre(gauss);
  const double hx = (body.x1 - body.x0) / nx, hy = (body.y1 - body.y0) / ny;

  Discretisation d;
  d.spacing_m = std::max(hx, hy);
  // Corner (i, j) is a node when one of the up to four cells around it is kept.
  std::vector<char> kept(std::size_t(nx) * std::size_t(ny), 1);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Rect cell{body.x0 + i * hx, body.y0 + j * hy, i + 1 == nx ? body.x1 : body.x0 + (i + 1) * hx,
                      j + 1 == ny ? body.y1 : body.y0 + (j + 1) * hy};
      if (keep_cell && !keep_cell(cell)) {
        kept[std::size_t(j) * std::size_t(nx) + std::size_t(i)] = 0;
        continue;
      }
      const auto c = std::int32_t(d.cells.size());
      d.cells.push_back(cell);
      const double cx = 0.5 * (cell.x0 + cell.x1), cy = 0.5 * (cell.y0 + cell.y1);
      const double jx = 0.5 * (cell.x1 - cell.x0), jy = 0.5 * (cell.y1 - cell.y0);
      for (int b = 0; b < gauss; ++b)
        for (int a = 0; a < gauss; ++a)
          d.points.push_back({Vec2(cx + jx * rule.x[std::size_t(a)], cy + jy * rule.x[std::size_t(b)]),
                              rule.w[std::size_t(a)] * rule.w[std::size_t(b)] * jx * jy, c});
    }
  if (d.cells.empty()) throw InputError("every background cell was dropped: the body has no cell left");
  const auto is_kept = [&](int i, int j) {
    return i >= 0 && j >= 0 && i < nx && j < ny && kept[std::size_t(j) * std::size_t(nx) + std::size_t(i)];
  };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      if (is_kept(i - 1, j - 1) || is_kept(i, j - 1) || is_kept(i - 1, j) || is_kept(i, j))
        d.nodes.emplace_back(i == nx ? body.x1 : body.x0 + i * hx, j == ny ? body.y1 : body.y0 + j * hy);

  // Two nodes at one place have the same shape function: K would be singular.
  const double tol = 1e-9 * d.spacing_m;
  for (const Vec2& x : extra_nodes) {
    if (!x.allFinite() || x.x() < body.x0 - tol || x.x() > body.x1 + tol || x.y() < body.y0 - tol ||
        x.y() > body.y1 + tol)
      throw InputError("extra node " + point_text(x) + " lies outside the body");
    for (const Vec2& y : d.nodes)
      if ((x - y).norm() <= tol) throw InputError("extra node " + point_text(x) + " lies on another node");
    d.nodes.push_back(x);
  }
  return d;
}

}  // namespace mesowave::efg
