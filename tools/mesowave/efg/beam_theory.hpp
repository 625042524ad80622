#pragma once
// Closed forms the EFG tests and mw-efg compare with: the two-dimensional elasticity solution of a
// cantilever under a parabolic end shear (the standard meshless validation, Belytschko, Lu & Gu 1994,
// "Element-free Galerkin methods", Int. J. Numer. Meth. Eng. 37: 229-256, Section 6) and the
// mid-span deflection of the simply supported (three-point bending) beam with shear deformation,
// against which the notched beam's initial stiffness is checked (issue 15, Must show 3).
#include <Eigen/Core>
#include <functional>

namespace mesowave::efg {

/// How the clamped end x = 0 of the cantilever is held. Timoshenko & Goodier, Theory of Elasticity,
/// 3rd ed. (1970), Section 21, derive one stress field and fix its rigid-body rotation by one of the
/// two conditions at the centroid of the end section; the meshless literature uses a third.
enum class CantileverClamp {
  /// u = v = 0 at the centroid, u = 0 at the top and bottom of the end section (its chord stays
  /// vertical): Belytschko, Lu & Gu (1994), the form EFG papers impose on the clamped edge.
  chord_vertical,
  /// T&G Eq. (k)-(l): u = v = dv/dx = 0 at the centroid (the axis stays horizontal).
  /// Tip deflection P L^3 / (3 E I).
  axis_horizontal,
  /// T&G p. 44: u = v = du/dy = 0 at the centroid (the element of the section stays vertical).
  /// Tip deflection P L^3 / (3 E I) + P L D^2 (1 + nu) / (4 E I): the shear deflection.
  section_vertical,
};

/// Displacement [m] and plane stress (sigma_xx, sigma_yy, tau_xy) [Pa] of the elasticity solution.
struct CantileverSolution {
  Eigen::Vector2d u_m;
  Eigen::Vector3d stress_Pa;
};

/// Timoshenko & Goodier's plane-stress cantilever: length L along x (clamped at x = 0, loaded at
/// x = L), depth D along y (-D/2 <= y <= D/2), thickness t, end load P [N] in +y distributed as the
/// parabolic shear tau_xy = P / (2 I) (D^2/4 - y^2), I = t D^3 / 12. With the chord_vertical clamp
///   u_x = -P y / (6 E I) [(6 L - 3 x) x + (2 + nu)(y^2 - D^2/4)],
///   u_y =  P / (6 E I) [3 nu y^2 (L - x) + (4 + 5 nu) D^2 x / 4 + (3 L - x) x^2],
///   sigma_xx = -P (L - x) y / I, sigma_yy = 0;
/// the other clamps add a rigid rotation. For plane strain pass E / (1 - nu^2) and nu / (1 - nu).
/// InputError for L, D, t, E <= 0 or nu outside (-1, 1) (the plane-strain equivalent may pass 0.5).
CantileverSolution timoshenko_cantilever(double P_N, double L_m, double D_m, double t_m, double E_Pa, double nu,
                                         const Eigen::Vector2d& x,
                                         CantileverClamp clamp = CantileverClamp::chord_vertical);

/// The cantilever as one value: the defaults are Belytschko, Lu & Gu's beam (L = 48, D = 12,
/// t = 1, E = 3e7, nu = 0.3, P = 1000 in consistent units), which the meshless literature reports.
struct CantileverBeam {
  double P_N = 1000, L_m = 48, D_m = 12, t_m = 1, E_Pa = 3e7, nu = 0.3;
  CantileverClamp clamp = CantileverClamp::chord_vertical;
  CantileverSolution at(const Eigen::Vector2d& x) const {
    return timoshenko_cantilever(P_N, L_m, D_m, t_m, E_Pa, nu, x, clamp);
  }
};

/// Errors of an approximate solution of the cantilever, integrated by `gauss` x `gauss` points over
/// cells_x x cells_y equal cells of the beam (pass the method's own cells, so that the piecewise
/// fields of a finite element mesh are integrated exactly):
///   displacement: ||u_h - u||_L2 / ||u||_L2;
///   energy: sqrt(int (s_h - s) : C (s_h - s)) / sqrt(int s : C s), C the plane-stress compliance;
///   tip: u_h,y(L, 0) / u_y(L, 0) - 1.
struct CantileverErrors { double displacement_L2 = 0, energy = 0, tip_deflection = 0; };
CantileverErrors cantilever_errors(const CantileverBeam& beam,
                                   const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& u_h,
                                   const std::function<Eigen::Vector3d(const Eigen::Vector2d&)>& stress_h,
                                   int cells_x, int cells_y, int gauss = 3);

/// Mid-span deflection of a simply supported beam (span S, rectangular section depth x thickness)
/// under a central load P, bending plus shear (Timoshenko beam, shear coefficient kappa = 5/6, the
/// energy-consistent value for the parabolic shear of a rectangle):
///   P S^3 / (48 E I) + P S / (4 kappa G A),  G = E / (2 (1 + nu)), A = depth t.
/// Each half is a cantilever of length S/2 carrying P/2; the shear term is what the elasticity
/// cantilever's end load does through tau_xy (Clapeyron), which the tests check.
double three_point_bending_deflection_m(double P_N, double span_m, double depth_m, double t_m, double E_Pa,
                                        double nu);

/// The extra load-point deflection a notch (a crack of depth a from the tension face) adds to the
/// simply supported beam under a central load, by linear elastic fracture mechanics: Tada, Paris &
/// Irwin, The Stress Analysis of Cracks Handbook (3rd ed., 2000), p. 2.17, three-point bend S/W = 4:
///   delta_notch = 3 P S^2 / (2 t W^2 E') V2(a/W),
///   V2(x) = (x / (1 - x))^2 (5.58 - 19.57 x + 36.82 x^2 - 34.94 x^3 + 12.77 x^4),
/// E' = E in plane stress. Fitted for S/W = 4 (within about 1 % for any a/W); for other
/// slenderness a first estimate. Beside the beam's own deflection it gives the notched beam's
/// stiffness 1 / (delta_beam + delta_notch) per newton. InputError for sizes <= 0 or a / W outside (0, 1).
double three_point_bending_notch_deflection_m(double P_N, double span_m, double depth_m, double notch_m, double t_m,
                                              double E_Pa);

/// Tada's stress intensity factor of the same beam, K_I = sigma sqrt(pi a) F(a/W), sigma = 3 P S / (2 t W^2),
/// F(x) = 1.090 - 1.735 x + 8.20 x^2 - 14.18 x^3 + 14.57 x^4 (S/W = 4, p. 2.16) [Pa sqrt(m)].
double three_point_bending_stress_intensity(double P_N, double span_m, double depth_m, double notch_m, double t_m);

}  // namespace mesowave::efg
