#include "mesowave/efg/beam_theory.hpp"

#include <string>

#include "mesowave/core/error.hpp"

namespace mesowave::efg {

namespace {

void require_positive(double value, const char* what) {
  if (!(value > 0)) throw InputError(std::string(what) + " = " + std::to_string(value) + " must be > 0");
}

void require_beam(double L_m, double D_m, double t_m, double E_Pa, double nu) {
  require_positive(L_m, "beam length");
  require_positive(D_m, "beam depth");
  require_positive(t_m, "beam thickness");
  require_positive(E_Pa, "Young's modulus");
  // Up to 1, not 0.5: the plane-strain equivalent nu / (1 - nu) of a material with nu < 0.5.
  if (!(nu > -1 && nu < 1))
    throw InputError("Poisson's ratio nu = " + std::to_string(nu) + " must lie in (-1, 1)");
}

}  // namespace

CantileverSolution timoshenko_cantilever(double P_N, double L_m, double D_m, double t_m, double E_Pa, double nu,
                                         const Eigen::Vector2d& x, CantileverClamp clamp) {
  require_beam(L_m, D_m, t_m, E_Pa, nu);
  const double L = L_m, D = D_m, X = x.x(), Y = x.y();
  const double I = t_m * D * D * D / 12.0;
  const double c = P_N / (6.0 * E_Pa * I);
  CantileverSolution s;
  s.u_m.x() = -c * Y * ((6.0 * L - 3.0 * X) * X + (2.0 + nu) * (Y * Y - D * D / 4.0));
  s.u_m.y() = c * (3.0 * nu * Y * Y * (L - X) + (4.0 + 5.0 * nu) * D * D * X / 4.0 + (3.0 * L - X) * X * X);
  // A small rigid rotation omega (u_x += omega y, u_y -= omega x) moves the chord_vertical field to
  // the book's conditions: dv/dx(0,0) = c (4 + 5 nu) D^2 / 4 and du/dy(0,0) = c (2 + nu) D^2 / 4.
  double omega = 0;
  if (clamp == CantileverClamp::axis_horizontal) omega = c * (4.0 + 5.0 * nu) * D * D / 4.0;
  if (clamp == CantileverClamp::section_vertical) omega = -c * (2.0 + nu) * D * D / 4.0;
  s.u_m.x() += omega * Y;
  s.u_m.y() -= omega * X;
  s.stress_Pa = {-P_N * (L - X) * Y / I, 0.0, P_N / (2.0 * I) * (D * D / 4.0 - Y * Y)};
  return s;
}

double three_point_bending_deflection_m(double P_N, double span_m, double depth_m, double t_m, double E_Pa,
                                        double nu) {
  require_beam(span_m, depth_m, t_m, E_Pa, nu);
  constexpr double kappa = 5.0 / 6.0;
  const double I = t_m * depth_m * depth_m * depth_m / 12.0;
  const double A = t_m * depth_m;
  const double G = E_Pa / (2.0 * (1.0 + nu));
  return P_N * span_m * span_m * span_m / (48.0 * E_Pa * I) + P_N * span_m / (4.0 * kappa * G * A);
}

}  // namespace mesowave::efg
