#include "mesowave/fem/plane_static.hpp"

#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "mesowave/core/error.hpp"

namespace mesowave::fem {

namespace {

using Vec2 = Eigen::Vector2d;
constexpr double kGauss = 0.57735026918962576;  // 1 / sqrt(3)
constexpr double kXiA[4] = {-1, 1, 1, -1}, kEtaA[4] = {-1, -1, 1, 1};

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Eigen::Vector4d shape(double xi, double eta) {
  Eigen::Vector4d N;
  for (int a = 0; a < 4; ++a) N(a) = 0.25 * (1 + xi * kXiA[a]) * (1 + eta * kEtaA[a]);
  return N;
}

// Strain-displacement matrix B (3 x 8) at (xi, eta) and det J.
std::pair<Eigen::Matrix<double, 3, 8>, double> b_matrix(const std::array<Vec2, 4>& x, double xi, double eta) {
  Eigen::Matrix<double, 2, 4> dN;  // d/dxi, d/deta
  for (int a = 0; a < 4; ++a) {
    dN(0, a) = 0.25 * kXiA[a] * (1 + eta * kEtaA[a]);
    dN(1, a) = 0.25 * kEtaA[a] * (1 + xi * kXiA[a]);
  }
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();  // J(i, j) = d x_j / d xi_i
  for (int a = 0; a < 4; ++a) J += dN.col(a) * x[std::size_t(a)].transpose();
  const Eigen::Matrix<double, 2, 4> dNdx = J.inverse() * dN;
  Eigen::Matrix<double, 3, 8> B = Eigen::Matrix<double, 3, 8>::Zero();
  for (int a = 0; a < 4; ++a) {
    B(0, 2 * a) = dNdx(0, a);
    B(1, 2 * a + 1) = dNdx(1, a);
    B(2, 2 * a) = dNdx(1, a);
    B(2, 2 * a + 1) = dNdx(0, a);
  }
  return {B, J.determinant()};
}

std::array<Vec2, 4> corners(const PlaneMesh& mesh, std::size_t e) {
  std::array<Vec2, 4> x;
  for (std::size_t a = 0; a < 4; ++a) x[a] = mesh.nodes[std::size_t(mesh.quads[e][a])];
  return x;
}

Eigen::Matrix<double, 8, 1> element_dofs(const PlaneMesh& mesh, std::size_t e, const Eigen::VectorXd& u) {
  Eigen::Matrix<double, 8, 1> ue;
  for (int a = 0; a < 4; ++a) {
    const auto n = mesh.quads[e][std::size_t(a)];
    ue(2 * a) = u(2 * n);
    ue(2 * a + 1) = u(2 * n + 1);
  }
  return ue;
}

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double s = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + s * ab)).norm();
}

}  // namespace

PlaneMesh structured_plane_mesh(const PlaneMeshSpec& spec) {
  if (spec.nx < 1 || spec.ny < 1)
    throw InputError("mesh of " + std::to_string(spec.nx) + " x " + std::to_string(spec.ny) +
                     " elements: both counts must be >= 1");
  if (!(spec.length_m > 0) || !(spec.depth_m > 0))
    throw InputError("body " + num(spec.length_m) + " m x " + num(spec.depth_m) + " m: both sizes must be > 0");
  PlaneMesh mesh;
  mesh.spec = spec;
  mesh.dx_m = spec.length_m / spec.nx;
  mesh.dy_m = spec.depth_m / spec.ny;
  const int nx = spec.nx, ny = spec.ny;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) mesh.nodes.emplace_back(spec.x0_m + i * mesh.dx_m, spec.y0_m + j * mesh.dy_m);
  auto grid = [&](int i, int j) { return std::int32_t(j * (nx + 1) + i); };

  int notch_column = -1, notch_rows = 0;
  if (spec.notch_depth_m != 0) {
    if (!(spec.notch_depth_m > 0) || spec.notch_depth_m >= spec.depth_m)
      throw InputError("notch depth " + num(spec.notch_depth_m) + " m must lie in (0, depth = " +
                       num(spec.depth_m) + " m)");
    const double ci = (spec.notch_x_m - spec.x0_m) / mesh.dx_m, rj = spec.notch_depth_m / mesh.dy_m;
    notch_column = int(std::lround(ci));
    notch_rows = int(std::lround(rj));
    if (notch_column < 1 || notch_column >= nx)
      throw InputError("notch at x = " + num(spec.notch_x_m) + " m lies outside the body's interior (" +
                       num(spec.x0_m) + " m to " + num(spec.x0_m + spec.length_m) + " m)");
    if (std::abs(ci - notch_column) > 1e-6 || std::abs(rj - notch_rows) > 1e-6)
      throw InputError("notch at x = " + num(spec.notch_x_m) + " m, depth " + num(spec.notch_depth_m) +
                       " m is not on the mesh lines (spacing " + num(mesh.dx_m) + " m x " + num(mesh.dy_m) + " m)");
  }
  std::vector<std::int32_t> copy(std::size_t(notch_rows), -1);
  for (int j = 0; j < notch_rows; ++j) {
    copy[std::size_t(j)] = std::int32_t(mesh.nodes.size());
    mesh.nodes.push_back(mesh.nodes[std::size_t(grid(notch_column, j))]);
  }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      std::array<std::int32_t, 4> q = {grid(i, j), grid(i + 1, j), grid(i + 1, j + 1), grid(i, j + 1)};
      if (i == notch_column) {  // right of the slit: its left corners below the tip are the copies
        if (j < notch_rows) q[0] = copy[std::size_t(j)];
        if (j + 1 < notch_rows) q[3] = copy[std::size_t(j + 1)];
      }
      mesh.quads.push_back(q);
    }
  return mesh;
}

std::vector<std::int32_t> PlaneMesh::nodes_on_segment(const Vec2& a, const Vec2& b, double tolerance_m) const {
  const double tol = tolerance_m >= 0 ? tolerance_m : 1e-6 * std::min(dx_m, dy_m);
  std::vector<std::int32_t> out;
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (distance_to_segment(nodes[n], a, b) <= tol) out.push_back(std::int32_t(n));
  return out;
}

std::int32_t PlaneMesh::node_at(const Vec2& x, const std::string& what) const {
  const double tol = 1e-3 * std::min(dx_m, dy_m);
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if ((nodes[n] - x).norm() <= tol) return std::int32_t(n);
  throw InputError(what + " at (" + num(x.x()) + ", " + num(x.y()) + ") m is on no mesh node (spacing " +
                   num(dx_m) + " m x " + num(dy_m) + " m)");
}

std::pair<std::int32_t, Vec2> PlaneMesh::locate(const Vec2& x) const {
  const double fx = (x.x() - spec.x0_m) / dx_m, fy = (x.y() - spec.y0_m) / dy_m;
  const double slack = 1e-9;
  if (fx < -slack || fx > spec.nx + slack || fy < -slack || fy > spec.ny + slack)
    throw InputError("point (" + num(x.x()) + ", " + num(x.y()) + ") m lies outside the body");
  const int i = std::clamp(int(std::floor(fx)), 0, spec.nx - 1), j = std::clamp(int(std::floor(fy)), 0, spec.ny - 1);
  return {std::int32_t(j * spec.nx + i), Vec2(2 * (fx - i) - 1, 2 * (fy - j) - 1)};
}

Eigen::Matrix<double, 8, 8> quad4_plane_stiffness(const std::array<Vec2, 4>& x, const Eigen::Matrix3d& D,
                                                  double thickness_m) {
  Eigen::Matrix<double, 8, 8> K = Eigen::Matrix<double, 8, 8>::Zero();
  for (double xi : {-kGauss, kGauss})
    for (double eta : {-kGauss, kGauss}) {
      const auto [B, detJ] = b_matrix(x, xi, eta);
      K += B.transpose() * D * B * (detJ * thickness_m);
    }
  return K;
}

Eigen::SparseMatrix<double> plane_stiffness(const PlaneMesh& mesh, const Eigen::Matrix3d& D, double thickness_m) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(mesh.quads.size() * 64);
  for (std::size_t e = 0; e < mesh.quads.size(); ++e) {
    const auto Ke = quad4_plane_stiffness(corners(mesh, e), D, thickness_m);
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b)
        triplets.emplace_back(2 * mesh.quads[e][std::size_t(a / 2)] + a % 2, 2 * mesh.quads[e][std::size_t(b / 2)] + b % 2,
                              Ke(a, b));
  }
  Eigen::SparseMatrix<double> K(Eigen::Index(mesh.dof_count()), Eigen::Index(mesh.dof_count()));
  K.setFromTriplets(triplets.begin(), triplets.end());
  return K;
}

Eigen::VectorXd plane_load(const PlaneStaticProblem& problem) {
  const PlaneMesh& mesh = problem.mesh;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(Eigen::Index(mesh.dof_count()));
  for (const auto& load : problem.point_loads) {
    const auto [e, xi] = mesh.locate(load.x);
    const Eigen::Vector4d N = shape(xi.x(), xi.y());
    for (std::size_t a = 0; a < 4; ++a) f.segment<2>(2 * mesh.quads[std::size_t(e)][a]) += N(Eigen::Index(a)) * load.force_N;
  }
  // Boundary edges from the elements' own corners, so the notch's faces (inside) are never loaded.
  const int nx = mesh.spec.nx, ny = mesh.spec.ny;
  const double tol = 1e-6 * std::min(mesh.dx_m, mesh.dy_m);
  for (const auto& load : problem.edge_loads) {
    bool any = false;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const auto& q = mesh.quads[std::size_t(j * nx + i)];
        const std::pair<int, int> sides[4] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
        const bool outer[4] = {j == 0, i == nx - 1, j == ny - 1, i == 0};
        for (int s = 0; s < 4; ++s) {
          if (!outer[s]) continue;
          const auto na = q[std::size_t(sides[s].first)], nb = q[std::size_t(sides[s].second)];
          const Vec2 &xa = mesh.nodes[std::size_t(na)], &xb = mesh.nodes[std::size_t(nb)];
          if (distance_to_segment(xa, load.a, load.b) > tol || distance_to_segment(xb, load.a, load.b) > tol) continue;
          any = true;
          const double half = 0.5 * (xb - xa).norm() * problem.thickness_m;
          for (double g : {-kGauss, kGauss}) {
            const Vec2 t = load.traction_Pa(0.5 * (xa + xb) + 0.5 * g * (xb - xa));
            f.segment<2>(2 * na) += 0.5 * (1 - g) * half * t;
            f.segment<2>(2 * nb) += 0.5 * (1 + g) * half * t;
          }
        }
      }
    if (!any)
      throw InputError("edge load from (" + num(load.a.x()) + ", " + num(load.a.y()) + ") to (" + num(load.b.x()) +
                       ", " + num(load.b.y()) + ") m covers no boundary edge of the mesh");
  }
  return f;
}

PlaneStaticSolution solve_plane_static(const PlaneStaticProblem& problem) {
  const auto t0 = std::chrono::steady_clock::now();
  const PlaneMesh& mesh = problem.mesh;
  const Eigen::Index n = Eigen::Index(mesh.dof_count());
  const Eigen::SparseMatrix<double> K = plane_stiffness(mesh, problem.D, problem.thickness_m);
  const Eigen::VectorXd f = plane_load(problem);

  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  std::vector<std::int8_t> held(std::size_t(n), 0);
  std::vector<Eigen::Index> constraint_dof;
  for (const auto& c : problem.constraints) {
    if (c.component != 0 && c.component != 1)
      throw InputError("constraint " + c.name + ": component " + std::to_string(c.component) + " must be 0 (x) or 1 (y)");
    const Eigen::Index dof = 2 * mesh.node_at(c.x, "constraint " + c.name) + c.component;
    if (held[std::size_t(dof)] && u(dof) != c.value_m)
      throw InputError("constraint " + c.name + " prescribes " + num(c.value_m) + " m where another prescribes " +
                       num(u(dof)) + " m");
    held[std::size_t(dof)] = 1;
    u(dof) = c.value_m;
    constraint_dof.push_back(dof);
  }
  std::vector<Eigen::Index> free_index(std::size_t(n), -1);
  Eigen::Index free = 0;
  for (Eigen::Index d = 0; d < n; ++d)
    if (!held[std::size_t(d)]) free_index[std::size_t(d)] = free++;

  // K_ff u_f = f_f - K_fc u_c.
  Eigen::VectorXd rhs(free);
  for (Eigen::Index d = 0; d < n; ++d)
    if (free_index[std::size_t(d)] >= 0) rhs(free_index[std::size_t(d)]) = f(d);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(std::size_t(K.nonZeros()));
  for (Eigen::Index col = 0; col < K.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, col); it; ++it) {
      const auto fr = free_index[std::size_t(it.row())], fc = free_index[std::size_t(it.col())];
      if (fr >= 0 && fc >= 0) triplets.emplace_back(fr, fc, it.value());
      else if (fr >= 0) rhs(fr) -= it.value() * u(it.col());
    }
  Eigen::SparseMatrix<double> Kff(free, free);
  Kff.setFromTriplets(triplets.begin(), triplets.end());

  PlaneStaticSolution out;
  out.assembly_s = seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(Kff);
  // A rigid motion left free shows as a zero pivot, or one rounding makes tiny against the rest.
  const Eigen::VectorXd pivots = ldlt.info() == Eigen::Success ? ldlt.vectorD() : Eigen::VectorXd();
  if (pivots.size() == 0 || pivots.minCoeff() <= 1e-10 * pivots.cwiseAbs().maxCoeff())
    throw InputError("the " + std::to_string(problem.constraints.size()) +
                     " constraints leave a rigid-body motion of the mesh free (the stiffness is singular)");
  const Eigen::VectorXd uf = ldlt.solve(rhs);
  out.solve_s = seconds_since(t1);
  for (Eigen::Index d = 0; d < n; ++d)
    if (free_index[std::size_t(d)] >= 0) u(d) = uf(free_index[std::size_t(d)]);
  const Eigen::VectorXd r = K * u - f;
  for (auto dof : constraint_dof) out.reactions_N.push_back(r(dof));
  out.u_m = std::move(u);
  out.free_dofs = std::size_t(free);
  out.stiffness_nonzeros = std::size_t(Kff.nonZeros());
  out.factor_nonzeros = std::size_t(ldlt.matrixL().nestedExpression().nonZeros());
  return out;
}

Vec2 plane_displacement(const PlaneMesh& mesh, const Eigen::VectorXd& u, const Vec2& x) {
  const auto [e, xi] = mesh.locate(x);
  const Eigen::Vector4d N = shape(xi.x(), xi.y());
  Vec2 out = Vec2::Zero();
  for (std::size_t a = 0; a < 4; ++a) out += N(Eigen::Index(a)) * u.segment<2>(2 * mesh.quads[std::size_t(e)][a]);
  return out;
}

Eigen::Vector3d plane_stress(const PlaneMesh& mesh, const Eigen::Matrix3d& D, const Eigen::VectorXd& u, const Vec2& x) {
  const auto [e, xi] = mesh.locate(x);
  const auto [B, detJ] = b_matrix(corners(mesh, std::size_t(e)), xi.x(), xi.y());
  return D * B * element_dofs(mesh, std::size_t(e), u);
}

std::vector<Eigen::Vector3d> plane_nodal_stress(const PlaneMesh& mesh, const Eigen::Matrix3d& D, const Eigen::VectorXd& u) {
  std::vector<Eigen::Vector3d> sum(mesh.nodes.size(), Eigen::Vector3d::Zero());
  std::vector<int> count(mesh.nodes.size(), 0);
  for (std::size_t e = 0; e < mesh.quads.size(); ++e) {
    const auto x = corners(mesh, e);
    const auto ue = element_dofs(mesh, e, u);
    for (std::size_t a = 0; a < 4; ++a) {
      const auto [B, detJ] = b_matrix(x, kXiA[a], kEtaA[a]);
      sum[std::size_t(mesh.quads[e][a])] += D * B * ue;
      ++count[std::size_t(mesh.quads[e][a])];
    }
  }
  for (std::size_t n = 0; n < sum.size(); ++n) sum[n] /= std::max(count[n], 1);
  return sum;
}

}  // namespace mesowave::fem
