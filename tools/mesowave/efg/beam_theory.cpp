#include "mesowave/efg/beam_theory.hpp"

#include <Eigen/LU>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "mesowave/core/check.hpp"
#include "mesowave/efg/discretisation.hpp"
#include "mesowave/efg/elastic_model.hpp"
#include "mesowave/efg/material.hpp"

namespace mesowave::efg {

namespace {

void require_beam(double L_m, double D_m, double t_m, double E_Pa, double nu) {
  require_positive("beam length", L_m, "m");
  require_positive("beam depth", D_m, "m");
  require_positive("beam thickness", t_m, "m");
  require_positive("Young's modulus", E_Pa, "Pa");
  // Up to 1, not 0.5: the plane-strain equivalent nu / (1 - nu) of a material with nu < 0.5.
  if (!(nu > -1 && nu < 1)) throw InputError("Poisson's ratio nu = " + format_number(nu) + " must lie in (-1, 1)");
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

CantileverErrors cantilever_errors(const CantileverBeam& beam,
                                   const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& u_h,
                                   const std::function<Eigen::Vector3d(const Eigen::Vector2d&)>& stress_h,
                                   int cells_x, int cells_y, int gauss) {
  if (cells_x < 1 || cells_y < 1)
    throw InputError("error integration over " + std::to_string(cells_x) + " x " + std::to_string(cells_y) +
                     " cells: both counts must be >= 1");
  const auto cells = rectangular_grid({0, -0.5 * beam.D_m, beam.L_m, 0.5 * beam.D_m}, cells_x, cells_y, gauss);
  const auto e = relative_error(
      cells.points, ElasticMaterial2D{beam.E_Pa, beam.nu, beam.t_m}.D(),  // plane stress
      [&](const Vec2& x) { return std::pair<Eigen::Vector2d, Eigen::Vector3d>{u_h(x), stress_h(x)}; },
      [&](const Vec2& x) {
        const CantileverSolution exact = beam.at(x);
        return std::pair<Eigen::Vector2d, Eigen::Vector3d>{exact.u_m, exact.stress_Pa};
      });
  const double tip = beam.at({beam.L_m, 0}).u_m.y();
  return {e.displacement_l2, e.energy, u_h({beam.L_m, 0}).y() / tip - 1};
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

namespace {

double notch_ratio(double span_m, double depth_m, double notch_m, double t_m) {
  require_positive("span", span_m, "m");
  require_positive("beam depth", depth_m, "m");
  require_positive("beam thickness", t_m, "m");
  const double x = notch_m / depth_m;
  if (!(x > 0 && x < 1))
    throw InputError("notch depth " + format_number(notch_m) + " m must lie inside the beam depth " +
                     format_number(depth_m) + " m");
  return x;
}

}  // namespace

double three_point_bending_notch_deflection_m(double P_N, double span_m, double depth_m, double notch_m, double t_m,
                                              double E_Pa) {
  const double x = notch_ratio(span_m, depth_m, notch_m, t_m);
  require_positive("Young's modulus", E_Pa, "Pa");
  const double V2 = (x / (1 - x)) * (x / (1 - x)) * (5.58 - 19.57 * x + 36.82 * x * x - 34.94 * x * x * x + 12.77 * x * x * x * x);
  return 3 * P_N * span_m * span_m / (2 * t_m * depth_m * depth_m * E_Pa) * V2;
}

double three_point_bending_stress_intensity(double P_N, double span_m, double depth_m, double notch_m, double t_m) {
  const double x = notch_ratio(span_m, depth_m, notch_m, t_m);
  const double F = 1.090 - 1.735 * x + 8.20 * x * x - 14.18 * x * x * x + 14.57 * x * x * x * x;
  return 3 * P_N * span_m / (2 * t_m * depth_m * depth_m) * std::sqrt(std::numbers::pi * notch_m) * F;
}

}  // namespace mesowave::efg
