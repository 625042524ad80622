// The closed forms of efg/beam_theory against what they must satisfy independently of how they are
// written: equilibrium (central differences of the stress field), Hooke's law for the strains of
// the displacement field (central differences), the traction-free edges, the end load's resultant,
// each clamp's conditions, and the three-point bending deflection against the cantilever's
// boundary work (Clapeyron: the work of the surface tractions is twice the strain energy).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "mesowave/efg/beam_theory.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

namespace {

// The Belytschko, Lu & Gu (1994) beam: L = 48, D = 12, t = 1, E = 3e7, nu = 0.3, P = 1000 (any units).
constexpr double kP = 1000, kL = 48, kD = 12, kT = 1, kE = 3e7, kNu = 0.3;

CantileverSolution beam(double x, double y, CantileverClamp clamp = CantileverClamp::chord_vertical) {
  return timoshenko_cantilever(kP, kL, kD, kT, kE, kNu, {x, y}, clamp);
}

// Gauss-Legendre on [a, b], 6 points: exact for the polynomials (degree <= 11) integrated here.
template <class F>
double integrate(F f, double a, double b) {
  static const double xi[] = {0.2386191860831969, 0.6612093864662645, 0.9324695142031521};
  static const double wi[] = {0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
  double sum = 0;
  for (int k = 0; k < 3; ++k)
    for (double s : {-1.0, 1.0}) sum += wi[k] * f(0.5 * (a + b) + 0.5 * (b - a) * s * xi[k]);
  return 0.5 * (b - a) * sum;
}

const CantileverClamp kClamps[] = {CantileverClamp::chord_vertical, CantileverClamp::axis_horizontal,
                                   CantileverClamp::section_vertical};

}  // namespace

TEST(BeamTheory, CantileverStressIsInEquilibrium) {
  const double h = 1e-3;
  for (double x : {0.5, 10.0, 30.0, 47.0})
    for (double y : {-5.9, -2.0, 0.0, 3.3, 6.0}) {
      const Eigen::Vector3d dx = (beam(x + h, y).stress_Pa - beam(x - h, y).stress_Pa) / (2 * h);
      const Eigen::Vector3d dy = (beam(x, y + h).stress_Pa - beam(x, y - h).stress_Pa) / (2 * h);
      const double scale = kP * kL / (kT * kD * kD * kD / 12.0);  // |d sigma_xx / dy| at the clamp
      EXPECT_NEAR(dx(0) + dy(2), 0.0, 1e-7 * scale) << x << ", " << y;
      EXPECT_NEAR(dx(2) + dy(1), 0.0, 1e-7 * scale) << x << ", " << y;
    }
}

TEST(BeamTheory, CantileverDisplacementStrainsObeyPlaneStressHooke) {
  const double h = 1e-3, G = kE / (2 * (1 + kNu));
  for (auto clamp : kClamps)
    for (double x : {1.0, 24.0, 46.0})
      for (double y : {-5.0, 0.0, 4.0}) {
        const Eigen::Vector2d ux = (beam(x + h, y, clamp).u_m - beam(x - h, y, clamp).u_m) / (2 * h);
        const Eigen::Vector2d uy = (beam(x, y + h, clamp).u_m - beam(x, y - h, clamp).u_m) / (2 * h);
        const Eigen::Vector3d s = beam(x, y, clamp).stress_Pa;
        const double eps_scale = std::abs(kP * kL * kD / 2 / (kE * kT * kD * kD * kD / 12.0));
        EXPECT_NEAR(ux(0), (s(0) - kNu * s(1)) / kE, 1e-6 * eps_scale);
        EXPECT_NEAR(uy(1), (s(1) - kNu * s(0)) / kE, 1e-6 * eps_scale);
        EXPECT_NEAR(uy(0) + ux(1), s(2) / G, 1e-6 * eps_scale);
      }
}

TEST(BeamTheory, CantileverEdgesAreFreeAndTheEndCarriesP) {
  for (double x : {0.0, 12.0, 48.0})
    for (double y : {-kD / 2, kD / 2}) {
      EXPECT_NEAR(beam(x, y).stress_Pa(1), 0.0, 1e-9);
      EXPECT_NEAR(beam(x, y).stress_Pa(2), 0.0, 1e-9);
    }
  // The loaded end: no normal stress, the shear adds up to P; at any section the moment is P (L - x).
  for (double y : {-6.0, -1.0, 2.5}) EXPECT_NEAR(beam(kL, y).stress_Pa(0), 0.0, 1e-9);
  for (double x : {0.0, 20.0, 48.0}) {
    EXPECT_NEAR(kT * integrate([&](double y) { return beam(x, y).stress_Pa(2); }, -kD / 2, kD / 2), kP, 1e-9 * kP);
    EXPECT_NEAR(kT * integrate([&](double y) { return beam(x, y).stress_Pa(0); }, -kD / 2, kD / 2), 0.0, 1e-9 * kP);
    EXPECT_NEAR(-kT * integrate([&](double y) { return y * beam(x, y).stress_Pa(0); }, -kD / 2, kD / 2),
                kP * (kL - x), 1e-9 * kP * kL);
  }
}

TEST(BeamTheory, CantileverClampsHoldWhatTheBookSays) {
  const double h = 1e-4, tol = 1e-15;
  for (auto clamp : kClamps) EXPECT_NEAR(beam(0, 0, clamp).u_m.norm(), 0.0, tol);
  EXPECT_NEAR(beam(0, kD / 2).u_m.x(), 0.0, tol);
  EXPECT_NEAR(beam(0, -kD / 2).u_m.x(), 0.0, tol);
  const double dvdx = (beam(h, 0, CantileverClamp::axis_horizontal).u_m.y() -
                       beam(-h, 0, CantileverClamp::axis_horizontal).u_m.y()) / (2 * h);
  const double dudy = (beam(0, h, CantileverClamp::section_vertical).u_m.x() -
                       beam(0, -h, CantileverClamp::section_vertical).u_m.x()) / (2 * h);
  EXPECT_NEAR(dvdx, 0.0, 1e-12);
  EXPECT_NEAR(dudy, 0.0, 1e-12);
  // T&G's tip deflections: P L^3 / (3 E I), plus P L D^2 (1 + nu) / (4 E I) with the section vertical.
  const double I = kT * kD * kD * kD / 12.0, bending = kP * kL * kL * kL / (3 * kE * I);
  EXPECT_NEAR(beam(kL, 0, CantileverClamp::axis_horizontal).u_m.y(), bending, 1e-12 * bending);
  EXPECT_NEAR(beam(kL, 0, CantileverClamp::section_vertical).u_m.y(),
              bending + kP * kL * kD * kD * (1 + kNu) / (4 * kE * I), 1e-12 * bending);
}

TEST(BeamTheory, CantileverClampsDifferByARigidRotation) {
  for (auto clamp : kClamps) {
    // d = u_clamp - u_chord must be (omega y, -omega x): linear with zero strain.
    auto d = [&](double x, double y) { return Eigen::Vector2d(beam(x, y, clamp).u_m - beam(x, y).u_m); };
    const double omega = d(0, 1).x();
    for (double x : {0.0, 17.0, 48.0})
      for (double y : {-6.0, 0.0, 5.0}) {
        EXPECT_NEAR(d(x, y).x(), omega * y, 1e-15);
        EXPECT_NEAR(d(x, y).y(), -omega * x, 1e-15);
      }
  }
}

TEST(BeamTheory, ThreePointBendingIsTheCantileverHalfByClapeyron) {
  // A simply supported beam of span 2L under 2P is two cantilevers of length L under P. The
  // Timoshenko-beam deflection (kappa = 5/6) must equal the elasticity cantilever's boundary work
  // divided by P: 2U = sum of traction . displacement over the loaded end and the clamped end
  // (the clamp's reaction tractions are -sigma there), for every slenderness and every clamp.
  for (double L : {6.0, 24.0, 48.0, 480.0})
    for (auto clamp : kClamps) {
      auto at = [&](double x, double y) { return timoshenko_cantilever(kP, L, kD, kT, kE, kNu, {x, y}, clamp); };
      const double tip = integrate([&](double y) { return at(L, y).stress_Pa(2) * at(L, y).u_m.y(); }, -kD / 2, kD / 2);
      const double root = integrate([&](double y) {
        const auto s = at(0, y);
        return -s.stress_Pa(0) * s.u_m.x() - s.stress_Pa(2) * s.u_m.y();
      }, -kD / 2, kD / 2);
      const double work_deflection = kT * (tip + root) / kP;
      const double beam_deflection = three_point_bending_deflection_m(2 * kP, 2 * L, kD, kT, kE, kNu);
      EXPECT_NEAR(work_deflection, beam_deflection, 1e-10 * beam_deflection) << L;
    }
}

TEST(BeamTheory, ThreePointBendingTendsToEulerBernoulliWhenSlender) {
  // Slender: the shear term falls as (D / S)^2 against the bending term; the cantilever limit is
  // the tip deflection P/2 (S/2)^3 / (3 E I) = P S^3 / (48 E I), which every clamp approaches.
  for (double S : {1e3, 1e4}) {
    const double I = kT * kD * kD * kD / 12.0;
    const double euler = kP * S * S * S / (48 * kE * I);
    const double beam3 = three_point_bending_deflection_m(kP, S, kD, kT, kE, kNu);
    const double shear_share = 12.0 * (1 + kNu) / 5.0 * (kD / S) * (kD / S);  // (P S/(4 kappa G A)) / euler
    EXPECT_NEAR(beam3 / euler - 1, shear_share, 1e-12);
    for (auto clamp : kClamps) {
      const double tip = timoshenko_cantilever(kP / 2, S / 2, kD, kT, kE, kNu, {S / 2, 0}, clamp).u_m.y();
      EXPECT_NEAR(tip / beam3, 1.0, 3 * shear_share);
    }
  }
}

TEST(BeamTheory, NotchComplianceAgreesWithTheStressIntensityByIrwinKies) {
  // Two independent fits of Tada's handbook tied by the energy release rate: G = K^2 / E' =
  // P^2 / (2 t) dC/da, so delta_notch(a) = (2 t P / E') int_0^a (K / P)^2 da'. The fits agree to
  // about 1 % for shallow notches and 7 % at a/W = 0.5 (the compliance fit is the more accurate).
  const double S = 0.4, W = 0.1, t = 0.1, E = 20e9, P = 1000;
  for (double x : {0.05, 0.1, 0.3, 0.5}) {
    const double a = x * W;
    const double integral = integrate([&](double s) {
      const double K = three_point_bending_stress_intensity(P, S, W, s, t);
      return K * K;
    }, 1e-12, a);
    const double by_K = 2 * t / (E * P) * integral;
    const double fit = three_point_bending_notch_deflection_m(P, S, W, a, t, E);
    EXPECT_NEAR(fit / by_K, 1.0, x <= 0.1 ? 0.02 : 0.08) << x;
  }
  // Shallow notch: K -> 1.12 sigma sqrt(pi a) (the edge crack), F(0) = 1.09 here.
  const double sigma = 3 * P * S / (2 * t * W * W);
  EXPECT_NEAR(three_point_bending_stress_intensity(P, S, W, 1e-6, t) / (sigma * std::sqrt(std::numbers::pi * 1e-6)), 1.09, 1e-4);
  EXPECT_NE(test::input_error_of([] { three_point_bending_notch_deflection_m(1, 0.45, 0.1, 0.1, 0.1, 2e10); }).find("notch depth 0.1"),
            std::string::npos);
}

TEST(BeamTheory, BadInputNamesTheValue) {
  EXPECT_NE(test::input_error_of([] { timoshenko_cantilever(1, 0, 1, 1, 1, 0.3, {0, 0}); })
                .find("beam length"),
            std::string::npos);
  EXPECT_NE(test::input_error_of([] { three_point_bending_deflection_m(1, 1, 1, 1, 1, 1.0); }).find("nu = 1"),
            std::string::npos);
  EXPECT_NE(test::input_error_of([] { three_point_bending_deflection_m(1, 1, 1, -1, 1, 0.2); }).find("thickness"),
            std::string::npos);
}
