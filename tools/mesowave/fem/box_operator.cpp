#include "mesowave/fem/box_operator.hpp"

#include <algorithm>
#include <stdexcept>

#include "mesowave/core/kernel_clones.hpp"

namespace mesowave::fem {

namespace {

// out[k] = lower[k] in[k - 1] + diagonal[k] in[k] + upper[k] in[k + 1] along a padded row
// (in[-1] and in[count] are the row's zero ends).
MESOWAVE_KERNEL_CLONES void sweep_row(const double* __restrict lower, const double* __restrict diagonal,
                                      const double* __restrict upper, const double* __restrict in, double* __restrict out,
                                      std::int64_t count) {
  for (std::int64_t k = 0; k < count; ++k) out[k] = lower[k] * in[k - 1] + diagonal[k] * in[k] + upper[k] * in[k + 1];
}

// out = a prev + b here + c next over a row (the y and z sweeps: one coefficient a row or plane).
MESOWAVE_KERNEL_CLONES void combine_rows(double a, const double* __restrict prev, double b, const double* __restrict here,
                                         double c, const double* __restrict next, double* __restrict out,
                                         std::int64_t count) {
  for (std::int64_t k = 0; k < count; ++k) out[k] = a * prev[k] + b * here[k] + c * next[k];
}

MESOWAVE_KERNEL_CLONES void add_scaled(double s, const double* __restrict in, double* __restrict out, std::int64_t count) {
  for (std::int64_t k = 0; k < count; ++k) out[k] += s * in[k];
}

// out += s (a prev + b here + c next): a y sweep straight into a term's sum.
MESOWAVE_KERNEL_CLONES void add_combined_rows(double s, double a, const double* __restrict prev, double b,
                                              const double* __restrict here, double c, const double* __restrict next,
                                              double* __restrict out, std::int64_t count) {
  for (std::int64_t k = 0; k < count; ++k) out[k] += s * (a * prev[k] + b * here[k] + c * next[k]);
}

}  // namespace

BoxOperator::BoxOperator(const BoxGrid& grid, const wave::IsotropicMaterial& material) {
  if (!grid.valid()) throw std::logic_error("BoxOperator needs a box grid");
  for (int a = 0; a < 3; ++a) {
    const std::int64_t n = grid.cells[std::size_t(a)];
    const double h = grid.spacing_m[std::size_t(a)];
    n_[std::size_t(a)] = n;
    auto& axis = ops_[std::size_t(a)];
    for (auto& t : axis) t.lower.assign(std::size_t(n + 1), 0.0), t.diagonal = t.upper = t.lower;
    for (std::int64_t i = 0; i <= n; ++i) {
      const auto k = std::size_t(i);
      const bool first = i == 0, last = i == n;
      const double cells = (first ? 0.0 : 1.0) + (last ? 0.0 : 1.0);  // cells the node's hat spans
      // K1 = int N_i' N_j': 1/h per cell on the diagonal, -1/h to each neighbour.
      axis[K].diagonal[k] = cells / h;
      // M1 = int N_i N_j: h/3 per cell on the diagonal, h/6 to each neighbour.
      axis[M].diagonal[k] = cells * h / 3;
      // C1 = int N_i' N_j: -1/2 from the cell on the right, +1/2 from the one on the left.
      axis[C].diagonal[k] = axis[CT].diagonal[k] = (first ? 0.0 : 0.5) - (last ? 0.0 : 0.5);
      if (!first) {
        axis[K].lower[k] = -1 / h;
        axis[M].lower[k] = h / 6;
        axis[C].lower[k] = 0.5;    // C(i, i - 1) = int N_i' N_{i-1} over the left cell
        axis[CT].lower[k] = -0.5;  // C(i - 1, i)
      }
      if (!last) {
        axis[K].upper[k] = -1 / h;
        axis[M].upper[k] = h / 6;
        axis[C].upper[k] = -0.5;
        axis[CT].upper[k] = 0.5;
      }
    }
  }
  const double lambda = wave::lame_lambda(material), mu = wave::lame_mu(material);
  const auto term = [&](int d, int e, double coefficient, std::array<Op, 3> op) {
    terms_.push_back({d, e, coefficient, op[0], op[1], op[2]});
  };
  for (int d = 0; d < 3; ++d)
    for (int e = 0; e < 3; ++e) {
      if (d == e) {
        for (int k = 0; k < 3; ++k) {  // (lambda + mu) d_d d_d + mu grad . grad
          std::array<Op, 3> op{M, M, M};
          op[std::size_t(k)] = K;
          term(d, e, k == d ? lambda + 2 * mu : mu, op);
        }
      } else {
        std::array<Op, 3> a{M, M, M}, b{M, M, M};
        a[std::size_t(d)] = C, a[std::size_t(e)] = CT;  // lambda int d_d N_i d_e N_j
        b[std::size_t(d)] = CT, b[std::size_t(e)] = C;  // mu int d_e N_i d_d N_j
        term(d, e, lambda, a);
        term(d, e, mu, b);
      }
    }
  for (const Term& t : terms_) {
    z_used_[std::size_t(t.e)][std::size_t(t.z)] = true;
    x_used_[std::size_t(t.d)][std::size_t(t.x)] = true;
  }
  row_ = n_[0] + 3;
  plane_ = (n_[1] + 3) * row_;
}

void BoxOperator::apply(const double* u, double* f, std::int64_t plane_begin, std::int64_t plane_end, Workspace& work) const {
  const std::int64_t nx = n_[0] + 1, ny = n_[1] + 1, nz = n_[2] + 1, node_plane = nx * ny;
  // Padded planes (a zero border: the 1-D operators' missing neighbours): u on the three planes
  // around c, deinterleaved (3 components x 3 planes, a ring: each plane is read from u once); 4
  // z-fields; 12 sums before the x-operator, one per (X op, d); two output rows.
  const std::size_t size = std::size_t(plane_);
  const std::size_t need = size * 25 + 2 * std::size_t(row_);
  if (work.buffer.size() != need) work.buffer.assign(need, 0.0);
  double* ring = work.buffer.data();  // [plane % 3][component]
  double* zf = ring + 9 * size;
  double* pre = zf + 4 * size;
  double* row_out = pre + 12 * size;
  double* row_sum = row_out + row_;
  const std::int64_t first_row = row_ + 1;                 // node (0, 0) in a padded plane
  const std::int64_t span = (ny - 1) * row_ + nx;          // from node (0, 0) to node (nx - 1, ny - 1)
  const auto at = [&](double* plane, std::int64_t i, std::int64_t j) { return plane + (j + 1) * row_ + (i + 1); };
  const auto slab = [&](std::int64_t plane, int e) { return ring + std::size_t(3 * (plane % 3) + e) * size; };
  const auto load = [&](std::int64_t plane) {
    for (int e = 0; e < 3; ++e)
      for (std::int64_t j = 0; j < ny; ++j) {
        const double* src = u + 3 * (plane * node_plane + j * nx) + e;
        double* dst = at(slab(plane, e), 0, j);
        for (std::int64_t i = 0; i < nx; ++i) dst[i] = src[3 * i];
      }
  };
  // out += s (a y-operator on in) over a whole plane: its first and last rows, and the rows between
  // at once (the operators' interior rows are alike).
  const auto sweep_y = [&](double s, const Tridiagonal& t, const double* in, double* out) {
    const auto rows = [&](std::int64_t j0, std::int64_t count) {
      const std::int64_t offset = first_row + j0 * row_, length = (count - 1) * row_ + nx;
      add_combined_rows(s, t.lower[std::size_t(j0)], in + offset - row_, t.diagonal[std::size_t(j0)], in + offset,
                        t.upper[std::size_t(j0)], in + offset + row_, out + offset, length);
    };
    rows(0, 1);
    if (ny > 2) rows(1, ny - 2);
    if (ny > 1) rows(ny - 1, 1);
  };

  if (plane_begin < plane_end) {
    if (plane_begin > 0) load(plane_begin - 1);
    load(plane_begin);
  }
  for (std::int64_t c = plane_begin; c < plane_end; ++c) {
    if (c + 1 < nz) load(c + 1);
    std::fill(pre, pre + 12 * size, 0.0);
    for (int e = 0; e < 3; ++e) {
      const double* here = slab(c, e);
      const double* prev = c > 0 ? slab(c - 1, e) : here;      // weight 0 where the plane is missing
      const double* next = c + 1 < nz ? slab(c + 1, e) : here;
      for (int z = K; z <= CT; ++z) {
        if (!z_used_[std::size_t(e)][std::size_t(z)]) continue;
        // z: the operator's row c over the planes c - 1, c, c + 1.
        const Tridiagonal& tz = ops_[2][std::size_t(z)];
        double* out = zf + std::size_t(z) * size;
        combine_rows(tz.lower[std::size_t(c)], prev + first_row, tz.diagonal[std::size_t(c)], here + first_row,
                     tz.upper[std::size_t(c)], next + first_row, out + first_row, span);
        // y: each term's y-operator after this z-operator, straight into its (X op, d) sum.
        for (const Term& t : terms_)
          if (t.e == e && t.z == z) sweep_y(t.coefficient, ops_[1][std::size_t(t.y)], out, pre + std::size_t(3 * t.x + t.d) * size);
      }
    }
    // x: each sum through its x-operator, the x-operators added in a fixed order, into f (interleaved).
    for (int d = 0; d < 3; ++d)
      for (std::int64_t j = 0; j < ny; ++j) {
        bool first = true;
        for (int x = K; x <= CT; ++x) {
          if (!x_used_[std::size_t(d)][std::size_t(x)]) continue;
          const Tridiagonal& tx = ops_[0][std::size_t(x)];
          sweep_row(tx.lower.data(), tx.diagonal.data(), tx.upper.data(), at(pre + std::size_t(3 * x + d) * size, 0, j),
                    first ? row_sum : row_out, nx);
          if (!first) add_scaled(1.0, row_out, row_sum, nx);
          first = false;
        }
        double* fo = f + 3 * (c * node_plane + j * nx) + d;
        for (std::int64_t i = 0; i < nx; ++i) fo[3 * i] = row_sum[i];
      }
  }
}

}  // namespace mesowave::fem
