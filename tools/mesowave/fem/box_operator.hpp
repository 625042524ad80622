#pragma once
// K u on a box of identical trilinear hexahedra (box_hexahedra) without the elements: the
// stiffness of isotropic linear elasticity,
//   K_ij^{de} = lambda int d_d N_i d_e N_j + mu int d_e N_i d_d N_j + mu delta_de int grad N_i . grad N_j,
// with tensor-product shape functions N_i(x) = X_a(x) Y_b(y) Z_c(z) on a grid of cells, is a sum of
// Kronecker products of three 1-D matrices of linear elements (the 2 x 2 x 2 Gauss rule of
// hex8_stiffness integrates these products exactly, so the two are the same matrix):
//   K1 = int N_a' N_a'' (stiffness),  M1 = int N_a N_a'' (consistent mass),  C1 = int N_a' N_a''.
//   d = e:  K on axis d, M on the others, times lambda + 2 mu; plus mu (K on axis k, M on the
//           others) for each of the two other axes k;
//   d != e: lambda (C on axis d, C^T on axis e, M on the third) + mu (C^T on axis d, C on axis e, M).
// The free faces are the 1-D operators' end rows (half a cell): nothing else to do at the box's
// surface. Applied as 45 tridiagonal sweeps a node (z, then y, then x; the sums that share an
// x-operator added before it), about 270 flops a node against the 1,152 of the 24 x 24 element
// products, on contiguous rows. Not the element assembly's order of additions: the forces agree
// with it to round-off (tests/fem/box_operator_test.cpp), not to the bit.
#include <array>
#include <cstdint>
#include <vector>

#include "mesowave/wave/elastic.hpp"

namespace mesowave::fem {

/// A box of nx x ny x nz identical cells of size hx x hy x hz, nodes numbered x fastest then y then
/// z, 3 DOFs a node (u_x, u_y, u_z), interleaved.
struct BoxGrid {
  std::array<int, 3> cells{};          ///< (nx, ny, nz); all 0: not a box
  std::array<double, 3> spacing_m{};   ///< (hx, hy, hz)
  bool valid() const { return cells[0] > 0 && cells[1] > 0 && cells[2] > 0; }
};

class BoxOperator {
public:
  BoxOperator(const BoxGrid& grid, const wave::IsotropicMaterial& material);

  /// Scratch planes for one thread.
  struct Workspace {
    std::vector<double> buffer;
  };
  /// f = K u for the node planes z in [plane_begin, plane_end) (reads u on the planes next to
  /// them; writes f on these planes only, so threads with disjoint ranges need no lock).
  void apply(const double* u, double* f, std::int64_t plane_begin, std::int64_t plane_end, Workspace& work) const;
  std::int64_t planes() const { return n_[2] + 1; }

private:
  enum Op { K = 0, M = 1, C = 2, CT = 3 };
  struct Tridiagonal {  // per node of one axis: (lower, diagonal, upper)
    std::vector<double> lower, diagonal, upper;
  };
  // One term of one output component d: coefficient x (X op on x, Y op on y, Z op on z) u_e.
  struct Term {
    int d, e;
    double coefficient;
    Op x, y, z;
  };
  std::array<std::int64_t, 3> n_{};      // cells per axis
  std::array<std::array<Tridiagonal, 4>, 3> ops_;  // [axis][Op]
  std::vector<Term> terms_;
  // Which z-operators act on u_e ([e][Op]) and which x-operators reach f_d ([d][Op]): the sweeps
  // apply() runs, read off terms_.
  std::array<std::array<bool, 4>, 3> z_used_{}, x_used_{};
  std::int64_t row_, plane_;  // padded row length (nx + 1 nodes and a zero at each end) and plane size
};

}  // namespace mesowave::fem
