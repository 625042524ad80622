#include "mesowave/fem/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>

#include <Eigen/Dense>

#include "mesowave/core/check.hpp"
#include "mesowave/fem/element.hpp"

namespace mesowave::fem {

namespace {

constexpr double pi = std::numbers::pi;

void check_size(const char* what, double L, double h) {
  require_positive(what, L, "m");
  if (L / h > 1e5) throw InputError(std::string(what) + " over the mesh size gives more than 100000 elements along it");
}

// 2D quadrilateral mesh (counter-clockwise cells) of a cross-section.
struct Mesh2D {
  std::vector<std::array<double, 2>> nodes;
  std::vector<std::array<std::int32_t, 4>> cells;
};

// Greedy colouring: each cell gets the lowest colour not used by a cell sharing a node.
std::vector<int> colour_cells(const Mesh2D& mesh) {
  std::vector<std::vector<int>> node_colours(mesh.nodes.size());
  std::vector<int> colour(mesh.cells.size());
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    std::set<int> used;
    for (auto n : mesh.cells[c])
      for (int k : node_colours[std::size_t(n)]) used.insert(k);
    int k = 0;
    while (used.count(k)) ++k;
    colour[c] = k;
    for (auto n : mesh.cells[c]) node_colours[std::size_t(n)].push_back(k);
  }
  return colour;
}

// Cells equal up to a translation share one type (key: node offsets from node 0, rounded).
std::vector<int> cell_types(const Mesh2D& mesh, double h, int& count) {
  std::map<std::vector<long long>, int> seen;
  std::vector<int> type(mesh.cells.size());
  const double q = h * 1e-9;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    std::vector<long long> key;
    const auto& x0 = mesh.nodes[std::size_t(mesh.cells[c][0])];
    for (auto n : mesh.cells[c])
      for (int d = 0; d < 2; ++d) key.push_back(std::llround((mesh.nodes[std::size_t(n)][d] - x0[d]) / q));
    type[c] = seen.emplace(key, int(seen.size())).first->second;
  }
  count = int(seen.size());
  return type;
}

// Largest eigenvalue of M^-1/2 K M^-1/2 over the free dofs of a (small) model, dense.
double dense_max_eigenvalue(const FemModel& model) {
  const auto dim = std::size_t(model.dim), npe = std::size_t(model.nodes_per_element), N = dim * npe;
  std::vector<std::ptrdiff_t> index(model.dof_count(), -1);
  std::ptrdiff_t n = 0;
  for (std::size_t i = 0; i < model.dof_count(); ++i)
    if (!model.fixed[i]) index[i] = n++;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t e = 0; e < model.element_count(); ++e) {
    const auto& K = model.stiffness[std::size_t(model.element_type[e])];
    for (std::size_t r = 0; r < N; ++r) {
      const std::size_t gr = std::size_t(model.connectivity[e * npe + r / dim]) * dim + r % dim;
      if (index[gr] < 0) continue;
      for (std::size_t c = 0; c < N; ++c) {
        const std::size_t gc = std::size_t(model.connectivity[e * npe + c / dim]) * dim + c % dim;
        if (index[gc] < 0) continue;
        A(index[gr], index[gc]) += K[r * N + c] / std::sqrt(model.mass[gr / dim] * model.mass[gc / dim]);
      }
    }
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(A, Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();
}

constexpr std::size_t max_block_dofs = 2500;  // a dense eigenproblem of this size takes about a second

void set_element_bound(FemModel& model) {
  model.max_eigenvalue_bound = *std::max_element(model.type_max_eigenvalue.begin(), model.type_max_eigenvalue.end());
  model.stable_dt_method = "element bound";
}

// Tightens the bound with blocks (sub-models built like the model); keeps the element bound if smaller.
void use_block_bound(FemModel& model, const std::vector<FemModel>& blocks, const std::string& what) {
  double worst = 0;
  for (const auto& b : blocks) {
    if (b.dof_count() > max_block_dofs) return;
    worst = std::max(worst, dense_max_eigenvalue(b));
  }
  if (worst > 0 && worst < model.max_eigenvalue_bound) {
    model.max_eigenvalue_bound = worst;
    model.stable_dt_method = "block bound (" + what + ")";
  }
}

// Extrudes the cross-section along z: layers of hexahedra, node = layer * n2 + node2d.
FemModel extrude(const Mesh2D& mesh, const IsotropicMaterial& m, double length, int nz, double h) {
  FemModel model;
  model.dim = 3;
  model.nodes_per_element = 8;
  model.material = m;
  model.mesh_size_m = h;
  const std::size_t n2 = mesh.nodes.size(), c2 = mesh.cells.size();
  const double dz = length / nz;
  model.coords.reserve(n2 * std::size_t(nz + 1) * 3);
  for (int l = 0; l <= nz; ++l)
    for (const auto& p : mesh.nodes) model.coords.insert(model.coords.end(), {p[0], p[1], l * dz});
  int ntypes = 0;
  const auto type2 = cell_types(mesh, h, ntypes);
  const auto colour2 = colour_cells(mesh);
  const int ncol2 = *std::max_element(colour2.begin(), colour2.end()) + 1;
  // One stiffness and one lumped mass per type (the first cell of that type, layer 0).
  model.stiffness.resize(std::size_t(ntypes));
  model.type_max_eigenvalue.resize(std::size_t(ntypes));
  std::vector<std::array<double, 8>> type_mass(static_cast<std::size_t>(ntypes));
  std::vector<bool> done(std::size_t(ntypes), false);
  const auto hex_of = [&](std::size_t c) {
    std::array<std::array<double, 3>, 8> x;
    for (int a = 0; a < 4; ++a) {
      const auto& p = mesh.nodes[std::size_t(mesh.cells[c][std::size_t(a)])];
      x[std::size_t(a)] = {p[0], p[1], 0.0};
      x[std::size_t(a) + 4] = {p[0], p[1], dz};
    }
    return x;
  };
  for (std::size_t c = 0; c < c2; ++c) {
    const auto t = std::size_t(type2[c]);
    if (done[t]) continue;
    done[t] = true;
    const auto x = hex_of(c);
    model.stiffness[t] = hex8_stiffness(x, m);
    type_mass[t] = hex8_lumped_mass(x, m.rho_kg_m3);
    std::vector<double> md(24);
    for (std::size_t a = 0; a < 8; ++a) md[3 * a] = md[3 * a + 1] = md[3 * a + 2] = type_mass[t][a];
    model.type_max_eigenvalue[t] = element_max_eigenvalue(model.stiffness[t], md);
  }
  model.mass.assign(n2 * std::size_t(nz + 1), 0.0);
  model.colours.resize(std::size_t(2 * ncol2));
  const std::size_t ne = c2 * std::size_t(nz);
  model.connectivity.reserve(ne * 8);
  model.element_type.reserve(ne);
  for (int l = 0; l < nz; ++l)
    for (std::size_t c = 0; c < c2; ++c) {
      const auto e = std::int32_t(model.element_type.size());
      const auto t = std::size_t(type2[c]);
      for (int layer = 0; layer < 2; ++layer)
        for (int a = 0; a < 4; ++a) {
          const auto node = std::size_t(l + layer) * n2 + std::size_t(mesh.cells[c][std::size_t(a)]);
          model.connectivity.push_back(std::int32_t(node));
          model.mass[node] += type_mass[t][std::size_t(layer * 4 + a)];
        }
      model.element_type.push_back(type2[c]);
      model.colours[std::size_t((l % 2) * ncol2 + colour2[c])].push_back(e);
    }
  model.fixed.assign(model.dof_count(), 0);
  set_element_bound(model);
  return model;
}

}  // namespace

double FemModel::stable_dt() const { return 2.0 / std::sqrt(max_eigenvalue_bound); }

std::array<double, 3> FemModel::position(std::size_t n) const {
  if (dim == 3) return {coords[3 * n], coords[3 * n + 1], coords[3 * n + 2]};
  return {coords[2 * n], 0.0, coords[2 * n + 1]};
}

std::size_t FemModel::nearest_node(const std::array<double, 3>& p) const {
  std::size_t best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  const std::array<double, 3> q = dim == 3 ? p : std::array<double, 3>{std::hypot(p[0], p[1]), 0.0, p[2]};
  for (std::size_t n = 0; n < node_count(); ++n) {
    const auto x = position(n);
    const double d = (x[0] - q[0]) * (x[0] - q[0]) + (x[1] - q[1]) * (x[1] - q[1]) + (x[2] - q[2]) * (x[2] - q[2]);
    if (d < best_d) {
      best_d = d;
      best = n;
    }
  }
  return best;
}

double FemModel::total_mass() const {
  double s = 0;
  for (double v : mass) s += v;
  return s;
}

namespace {
FemModel rod_axisymmetric_impl(const IsotropicMaterial& m, double R, double L, double h, bool block) {
  validate(m);
  require_positive("mesh size", h, "m");
  check_size("rod radius", R, h);
  check_size("rod length", L, h);
  const int nr = std::max(1, int(std::ceil(R / h - 1e-9)));
  const int nz = std::max(1, int(std::lround(L / h)));
  const double dr = R / nr, dz = L / nz;
  FemModel model;
  model.dim = 2;
  model.nodes_per_element = 4;
  model.material = m;
  model.mesh_size_m = h;
  model.description = "rod, axisymmetric rings, " + std::to_string(nr) + " across the radius x " +
                      std::to_string(nz) + " layers";
  const auto id = [&](int i, int j) { return std::int32_t(j * (nr + 1) + i); };
  for (int j = 0; j <= nz; ++j)
    for (int i = 0; i <= nr; ++i) model.coords.insert(model.coords.end(), {i * dr, j * dz});
  model.stiffness.resize(std::size_t(nr));
  model.type_max_eigenvalue.resize(std::size_t(nr));
  std::vector<std::array<double, 4>> ring_mass(static_cast<std::size_t>(nr));
  for (int i = 0; i < nr; ++i) {
    const std::array<std::array<double, 2>, 4> x{{{i * dr, 0}, {(i + 1) * dr, 0}, {(i + 1) * dr, dz}, {i * dr, dz}}};
    model.stiffness[std::size_t(i)] = quad4_axisymmetric_stiffness(x, m);
    ring_mass[std::size_t(i)] = quad4_axisymmetric_lumped_mass(x, m.rho_kg_m3);
    std::vector<double> md(8);
    for (std::size_t a = 0; a < 4; ++a) md[2 * a] = md[2 * a + 1] = ring_mass[std::size_t(i)][a];
    model.type_max_eigenvalue[std::size_t(i)] = element_max_eigenvalue(model.stiffness[std::size_t(i)], md);
  }
  model.mass.assign(std::size_t((nr + 1) * (nz + 1)), 0.0);
  model.colours.resize(4);
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nr; ++i) {
      const auto e = std::int32_t(model.element_type.size());
      const std::int32_t nodes[4] = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
      for (int a = 0; a < 4; ++a) {
        model.connectivity.push_back(nodes[a]);
        model.mass[std::size_t(nodes[a])] += ring_mass[std::size_t(i)][std::size_t(a)];
      }
      model.element_type.push_back(i);
      model.colours[std::size_t((j % 2) * 2 + i % 2)].push_back(e);
    }
  model.fixed.assign(model.dof_count(), 0);
  for (int j = 0; j <= nz; ++j) model.fixed[std::size_t(id(0, j)) * 2] = 1;  // u_r = 0 on the axis
  set_element_bound(model);
  if (block) use_block_bound(model, {rod_axisymmetric_impl(m, R, dz, h, false)}, "one layer");
  return model;
}

}  // namespace

FemModel rod_axisymmetric(const IsotropicMaterial& m, double R, double L, double h) {
  return rod_axisymmetric_impl(m, R, L, h, true);
}

namespace {
FemModel rod_hexahedra_impl(const IsotropicMaterial& m, double R, double L, double h, bool block) {
  validate(m);
  require_positive("mesh size", h, "m");
  check_size("rod radius", R, h);
  check_size("rod length", L, h);
  // O-grid: inner square of half-width s = 0.55 R with n x n cells (n even), four
  // blocks of n x nb cells between its sides and the circle.
  const double s = 0.55 * R;
  const int n = 2 * std::max(1, int(std::lround(s / h)));
  const int nb = std::max(1, int(std::lround((R - s) / h)));
  Mesh2D mesh;
  std::map<std::pair<long long, long long>, std::int32_t> index;
  const double q = R * 1e-9;
  const auto node = [&](double x, double y) {
    const auto key = std::make_pair(std::llround(x / q), std::llround(y / q));
    const auto it = index.find(key);
    if (it != index.end()) return it->second;
    const auto id = std::int32_t(mesh.nodes.size());
    mesh.nodes.push_back({x, y});
    index.emplace(key, id);
    return id;
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x0 = -s + 2 * s * i / n, x1 = -s + 2 * s * (i + 1) / n;
      const double y0 = -s + 2 * s * j / n, y1 = -s + 2 * s * (j + 1) / n;
      mesh.cells.push_back({node(x0, y0), node(x1, y0), node(x1, y1), node(x0, y1)});
    }
  // Block b: the square side at angle phi = b pi/2 (right, top, left, bottom), points
  // along it counter-clockwise, blended radially to the arc of the same angles.
  // The boundary is a polygon of 4n chords; its vertices sit at R' > R so that the
  // polygon's area (hence mass and axial stiffness) is exactly pi R^2.
  const double Rv = R * std::sqrt(2 * pi / (4.0 * n * std::sin(2 * pi / (4.0 * n))));
  for (int b = 0; b < 4; ++b) {
    const double phi = b * pi / 2;
    const double c = std::cos(phi), sn = std::sin(phi);
    const auto point = [&](int i, int k) {
      const double t = -1 + 2.0 * i / n;                    // along the side, -1..1
      const double sx = s, sy = s * t;                       // on the right side before rotation
      const double th = t * pi / 4;                          // matching angle on the arc
      const double cx = Rv * std::cos(th), cy = Rv * std::sin(th);
      const double w = double(k) / nb;
      const double x = sx + w * (cx - sx), y = sy + w * (cy - sy);
      return std::array<double, 2>{c * x - sn * y, sn * x + c * y};
    };
    for (int k = 0; k < nb; ++k)
      for (int i = 0; i < n; ++i) {
        const auto p00 = point(i, k), p10 = point(i + 1, k), p11 = point(i + 1, k + 1), p01 = point(i, k + 1);
        // counter-clockwise: outward (k) then along (i) is clockwise, so order (k, i) pairs accordingly
        mesh.cells.push_back({node(p00[0], p00[1]), node(p01[0], p01[1]), node(p11[0], p11[1]), node(p10[0], p10[1])});
      }
  }
  const int nz = std::max(1, int(std::lround(L / h)));
  FemModel model = extrude(mesh, m, L, nz, h);
  model.description = "rod, 3D hexahedra (O-grid), " + std::to_string(mesh.cells.size()) +
                      " cells per cross-section x " + std::to_string(nz) + " layers";
  if (block) use_block_bound(model, {rod_hexahedra_impl(m, R, L / nz, h, false)}, "one layer");
  return model;
}
}  // namespace

FemModel rod_hexahedra(const IsotropicMaterial& m, double R, double L, double h) {
  return rod_hexahedra_impl(m, R, L, h, true);
}

namespace {
FemModel box_grid(const IsotropicMaterial& m, const std::array<double, 3>& size, const std::array<int, 3>& cells,
                  bool block) {
  const int nx = cells[0], ny = cells[1], nz = cells[2];
  const double h = std::max({size[0] / nx, size[1] / ny, size[2] / nz});
  Mesh2D mesh;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) mesh.nodes.push_back({size[0] * i / nx, size[1] * j / ny});
  const auto id = [&](int i, int j) { return std::int32_t(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) mesh.cells.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  FemModel model = extrude(mesh, m, size[2], nz, h);
  model.description = "box, 3D hexahedra, " + std::to_string(nx) + " x " + std::to_string(ny) + " x " +
                      std::to_string(nz);
  if (block) {
    // Blocks of 2 cells per side; an odd count leaves one block of 3 in that direction.
    const int n[3] = {nx, ny, nz};
    std::vector<int> widths[3];
    for (int d = 0; d < 3; ++d) {
      if (n[d] == 1) widths[d] = {1};
      else if (n[d] % 2 == 0) widths[d] = {2};
      else widths[d] = {2, 3};
      if (n[d] == 3) widths[d] = {3};
    }
    std::vector<FemModel> blocks;
    for (int a : widths[0])
      for (int b : widths[1])
        for (int c : widths[2])
          blocks.push_back(box_grid(m, {size[0] / nx * a, size[1] / ny * b, size[2] / nz * c}, {a, b, c}, false));
    use_block_bound(model, blocks, "2 x 2 x 2 cells");
  }
  return model;
}
}  // namespace

FemModel box_hexahedra(const IsotropicMaterial& m, const std::array<double, 3>& size, double h) {
  validate(m);
  require_positive("mesh size", h, "m");
  for (double L : size) check_size("box side", L, h);
  std::array<int, 3> cells;
  for (int d = 0; d < 3; ++d) cells[std::size_t(d)] = std::max(1, int(std::lround(size[std::size_t(d)] / h)));
  const double cells_total = double(cells[0]) * cells[1] * cells[2];
  if (cells_total > 3e7) throw InputError("box mesh would have " + format_number(cells_total) + " hexahedra (limit 3e7)");
  FemModel model = box_grid(m, size, cells, true);
  model.box = {cells, {size[0] / cells[0], size[1] / cells[1], size[2] / cells[2]}};
  return model;
}

std::vector<std::pair<std::size_t, double>> surface_patch(const FemModel& model, int axis, double value,
                                                          const std::array<double, 3>& centre, double radius) {
  std::map<std::size_t, double> weights;
  const double tol = model.mesh_size_m * 1e-6;
  const auto on_plane = [&](std::size_t n) { return std::abs(model.position(n)[std::size_t(axis)] - value) <= tol; };
  const auto npe = std::size_t(model.nodes_per_element);
  const double g = 1 / std::sqrt(3.0);
  for (std::size_t e = 0; e < model.element_count(); ++e) {
    const std::int32_t* nd = &model.connectivity[e * npe];
    std::vector<std::size_t> face;
    for (std::size_t a = 0; a < npe; ++a)
      if (on_plane(std::size_t(nd[a]))) face.push_back(std::size_t(nd[a]));
    if (model.dim == 3 && face.size() == 4) {
      // Order the 4 nodes around the face: hex faces keep the element's cyclic order
      // in the extrusion (axis z), or come from one side of the cell (x or y); sort by angle.
      std::array<double, 3> c{};
      for (auto n : face)
        for (int d = 0; d < 3; ++d) c[std::size_t(d)] += model.position(n)[std::size_t(d)] / 4;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      std::sort(face.begin(), face.end(), [&](std::size_t a, std::size_t b) {
        const auto pa = model.position(a), pb = model.position(b);
        return std::atan2(pa[std::size_t(v)] - c[std::size_t(v)], pa[std::size_t(u)] - c[std::size_t(u)]) <
               std::atan2(pb[std::size_t(v)] - c[std::size_t(v)], pb[std::size_t(u)] - c[std::size_t(u)]);
      });
      if (std::hypot(c[0] - centre[0], c[1] - centre[1], c[2] - centre[2]) > radius) continue;
      // Bilinear face: weight_a = integral of N_a dA (2 x 2 Gauss).
      for (double xi : {-g, g})
        for (double eta : {-g, g}) {
          static const int sg[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
          double dxu[3] = {0, 0, 0}, dxv[3] = {0, 0, 0};
          double N[4];
          for (int a = 0; a < 4; ++a) {
            N[a] = (1 + sg[a][0] * xi) * (1 + sg[a][1] * eta) / 4;
            const auto p = model.position(face[std::size_t(a)]);
            for (int d = 0; d < 3; ++d) {
              dxu[d] += sg[a][0] * (1 + sg[a][1] * eta) / 4 * p[std::size_t(d)];
              dxv[d] += sg[a][1] * (1 + sg[a][0] * xi) / 4 * p[std::size_t(d)];
            }
          }
          const double cx = dxu[1] * dxv[2] - dxu[2] * dxv[1], cy = dxu[2] * dxv[0] - dxu[0] * dxv[2],
                       cz = dxu[0] * dxv[1] - dxu[1] * dxv[0];
          const double dA = std::sqrt(cx * cx + cy * cy + cz * cz);
          for (int a = 0; a < 4; ++a) weights[face[std::size_t(a)]] += N[a] * dA;
        }
    } else if (model.dim == 2 && face.size() == 2 && axis == 2) {
      // Edge of a ring on z = value: weight_a = integral of N_a 2 pi r dr.
      double r1 = model.position(face[0])[0], r2 = model.position(face[1])[0];
      auto n1 = face[0], n2 = face[1];
      if (r1 > r2) {
        std::swap(r1, r2);
        std::swap(n1, n2);
      }
      if (0.5 * (r1 + r2) > radius) continue;  // an axisymmetric patch is a disk centred on the axis
      weights[n1] += 2 * pi * (r2 - r1) * (2 * r1 + r2) / 6;
      weights[n2] += 2 * pi * (r2 - r1) * (r1 + 2 * r2) / 6;
    }
  }
  double total = 0;
  for (const auto& [n, w] : weights) total += w;
  std::vector<std::pair<std::size_t, double>> out;
  for (const auto& [n, w] : weights) out.emplace_back(n, w / total);
  return out;
}

}  // namespace mesowave::fem
