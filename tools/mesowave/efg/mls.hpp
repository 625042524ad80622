#pragma once
// Moving least squares (MLS) shape functions of the element-free Galerkin method, Eqs. (1)-(12) of
// Larcher and Stempniewski (seed 004, Section 2.1), after Belytschko, Lu and Gu (1994, "Element-free
// Galerkin methods", IJNME 37: 229-256):
//   u^h(x) = sum_I phi_I(x) u_I,  phi_I(x) = p^T(x) A^-1(x) w_I(x) p(x_I)          Eqs. (1), (9)
//   A(x) = sum_I w_I(x) p(x_I) p^T(x_I) = P^T W P                                  Eq. (4)
//   w_I(x) = w(s), s = d_I(x) / h_I                                                 Eq. (10)
// with d_I = |x - x_I| away from cracks, and the distance a CrackSet bends or cuts near them, Eq. (13).
// Derivatives (Belytschko, Krongauz, Organ, Fleming and Krysl 1996, "Meshless methods: an overview
// and recent developments", CMAME 139: 3-47): with A gamma = p,
//   phi_I = w_I gamma^T p_I,  phi_I,x = w_I gamma_x^T p_I + w_I,x gamma^T p_I,
//   A gamma_x = p_x - A_x gamma,  A_x = sum w_I,x p_I p_I^T,  w_I,x = w'(s) d_I,x / h_I.
// Robustness: the basis is evaluated in shifted, scaled coordinates (x_I - x) / h, h the largest
// support radius reaching x. The shape functions do not change (a complete basis spans the same space
// under any affine map), but A's entries become O(1) and its condition number measures the node
// geometry, not the coordinates' units or origin. A is factorised by Cholesky (LLT; a non-positive
// pivot is a singular A); its 1-norm condition number is estimated (Eigen's rcond) and reported.
// Fewer nodes than basis terms, a singular A or one above max_condition_number is an InputError
// naming the point: never a silent wrong answer.
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "mesowave/efg/crack.hpp"
#include "mesowave/efg/geometry.hpp"
#include "mesowave/efg/node_grid.hpp"

namespace mesowave::efg {

enum class Basis { linear, quadratic };  ///< p = (1, x, y) | (1, x, y, x^2, xy, y^2), Eq. (2)
/// Eq. (12) | the cubic spline of Belytschko et al., scaled by 3/2 so that w(0) = 1 as Eq. (11)
/// asks (a constant factor on every weight leaves the shape functions unchanged).
enum class WeightKind { quartic_spline, cubic_spline };
Basis parse_basis(std::string_view name);             ///< "linear" | "quadratic"
WeightKind parse_weight_kind(std::string_view name);  ///< "quartic-spline" | "cubic-spline" (also "quartic" | "cubic")
std::string_view to_string(Basis basis);
std::string_view to_string(WeightKind kind);
/// Number of basis terms m: 3 | 6.
int basis_size(Basis basis);

/// w(s) and dw/ds, Eqs. (10)-(12) (zero for s >= 1). Quartic: 1 - 6 s^2 + 8 s^3 - 3 s^4.
/// Cubic: 1 - 6 s^2 + 6 s^3 for s <= 1/2, 2 (1 - s)^3 above. Both have w'(0) = 0 and w(1) = w'(1) = 0.
std::pair<double, double> weight(WeightKind kind, double s);

struct MlsOptions {
  Basis basis = Basis::linear;
  WeightKind weight = WeightKind::quartic_spline;
  CrackWeightMethod crack_method = CrackWeightMethod::visibility;
  double diffraction_lambda = 2.0;      ///< Organ et al. recommend 1 or 2; 2 keeps dphi continuous
  double max_condition_number = 1e12;   ///< above it a point's moment matrix A is refused
  TransparencyOptions transparency{};   ///< for crack_method = transparency
};

/// Support radii h_i, Eq. (10): the distance to the `count`-th nearest other node times `factor`
/// (the paper: 4 to 10 nodes in a support). With factor 1 that node sits on the support's edge,
/// where w = 0: a factor above 1 (e.g. 1.2) makes it count. InputError: count < 1 or >= the number
/// of nodes, factor <= 0.
std::vector<double> support_radii_by_count(const std::vector<Vec2>& nodes, int count, double factor = 1.0);
/// `scale` times the nodal spacing for every node (the usual choice on a regular grid: 2 to 3 for a
/// linear basis). InputError: spacing or scale <= 0.
std::vector<double> support_radii_by_spacing(const std::vector<Vec2>& nodes, double spacing_m, double scale);

struct ShapeFunctions {
  std::vector<std::int32_t> nodes;            ///< ascending node indices with a nonzero weight at x
  std::vector<double> phi, dphi_dx, dphi_dy;  ///< per entry of `nodes`, Eq. (9) and its derivatives
  double condition_number = 0;                ///< of the moment matrix A(x), Eq. (4) (1-norm estimate, scaled basis)
};

class MlsApproximation {
public:
  /// InputError: sizes differ, a radius not > 0, a node not finite. `cracks` (may be null) must
  /// outlive this object; it is read at every evaluate, so a grown crack takes effect at once.
  MlsApproximation(std::vector<Vec2> nodes, std::vector<double> support_radius_m, MlsOptions options = {},
                   const CrackSet* cracks = nullptr);
  /// Shape functions at x. Throws InputError naming x (and `where`, e.g. "Gauss point 17 of cell 3")
  /// when fewer nodes than basis terms reach x or A(x) is singular / above max_condition_number.
  /// A point ON a crack line: pass it moved off the line by a small distance to the side wanted.
  /// Safe to call from several threads at once (the CrackSet must not change meanwhile).
  ShapeFunctions evaluate(const Vec2& x, std::string_view where = "") const;
  /// u^h(x) = sum phi_I u_I for nodal values u (one per node), Eq. (1).
  double interpolate(const ShapeFunctions& sf, const std::vector<double>& u) const;
  const std::vector<Vec2>& nodes() const { return nodes_; }
  const std::vector<double>& support_radii() const { return radius_; }
  const MlsOptions& options() const { return options_; }
  std::size_t node_count() const { return nodes_.size(); }
  const CrackSet* cracks() const { return cracks_; }

private:
  std::vector<Vec2> nodes_;
  std::vector<double> radius_;
  MlsOptions options_;
  const CrackSet* cracks_;
  double max_radius_ = 0;
  NodeGrid grid_;
};

}  // namespace mesowave::efg
