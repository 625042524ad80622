// Pochhammer-Chree longitudinal modes against closed forms (bar velocity,
// Rayleigh-Love, Rayleigh speed, k = 0 cut-offs) and against an independent
// semi-analytical finite element solution of the same rod (rod_safe.hpp).
#include "mesowave/wave/pochhammer_chree.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

#include "mesowave/core/error.hpp"
#include "rod_safe.hpp"

using namespace mesowave;
using namespace mesowave::wave;

namespace {

constexpr double kE = 208.72e9, kRho = 7850.66, kA = 5.1e-3;  // rod paper Section 4.1

PochhammerChree rod(double nu) { return PochhammerChree({kE, nu, kRho}, kA); }

// L(0,1) phase velocity at k a = x, from the root search at fixed k.
double first_mode_phase_velocity(const PochhammerChree& pc, double x) {
  const double k = x / kA;
  const auto w = pc.frequencies(k, pc.omega_of(1.2 * x * pc.speeds().c0 / pc.speeds().cS + 0.1));
  return w.at(0) / k;
}

// Rayleigh speed from the irrational form (2 - eta^2)^2 = 4 sqrt(1 - eta^2) sqrt(1 - eta^2 / kappa^2)
// by bisection on (0.5, 1): a second route to the library's cubic.
double rayleigh_speed_reference(double nu, double cS) {
  const double k2 = 2 * (1 - nu) / (1 - 2 * nu);
  const auto f = [&](double e) {
    const double e2 = e * e;
    return (2 - e2) * (2 - e2) - 4 * std::sqrt(1 - e2) * std::sqrt(1 - e2 / k2);
  };
  double lo = 0.5, hi = 0.999999;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(mid) > 0) == (f(lo) > 0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) * cS;
}

}  // namespace

TEST(PochhammerChree, RejectsBadMaterial) {
  EXPECT_THROW(PochhammerChree({kE, 0.5, kRho}, kA), InputError);
  EXPECT_THROW(PochhammerChree({-1, 0.3, kRho}, kA), InputError);
  EXPECT_THROW(PochhammerChree({kE, 0.3, 0}, kA), InputError);
  EXPECT_THROW(PochhammerChree({kE, 0.3, kRho}, 0), InputError);
}

TEST(PochhammerChree, WaveSpeedsOfTheRodPaperSteel) {
  const auto c = rod(0.3).speeds();
  EXPECT_NEAR(c.c0, std::sqrt(kE / kRho), 1e-9);
  EXPECT_NEAR(c.cP / c.cS, std::sqrt(2 * 0.7 / 0.4), 1e-12);
  for (double nu : {0.0, 0.1, 0.25, 0.3, 0.45}) {
    const auto s = rod(nu).speeds();
    EXPECT_NEAR(s.cR, rayleigh_speed_reference(nu, s.cS), 1e-9 * s.cS) << "nu " << nu;
  }
  // Viktorov's approximation cR/cS = (0.87 + 1.12 nu)/(1 + nu), good to about 0.5 %.
  EXPECT_NEAR(c.cR / c.cS, (0.87 + 1.12 * 0.3) / 1.3, 5e-3);
}

TEST(PochhammerChree, LowFrequencyLimitIsTheBarVelocity) {
  for (double nu : {0.1, 0.3, 0.45}) {
    const auto pc = rod(nu);
    const double cp = first_mode_phase_velocity(pc, 1e-3);
    // 1 - cp/c0 = nu^2 (ka)^2 / 4 = 5e-8 at most here.
    EXPECT_NEAR(cp / pc.speeds().c0, 1.0, 1e-7) << "nu " << nu;
  }
}

TEST(PochhammerChree, RayleighLoveApproximationAtSmallKa) {
  // Rayleigh-Love rod (lateral inertia): omega^2 = c0^2 k^2 / (1 + nu^2 k^2 a^2 / 2). It shares
  // the leading dispersive term with the exact theory, 1 - cp/c0 = nu^2 (ka)^2 / 4 + O((ka)^4).
  const double nu = 0.3;
  const auto pc = rod(nu);
  const double c0 = pc.speeds().c0;
  std::vector<double> rel_err;
  for (double x : {0.2, 0.1, 0.05}) {
    const double drop_exact = 1 - first_mode_phase_velocity(pc, x) / c0;
    const double drop_rl = 1 - 1 / std::sqrt(1 + nu * nu * x * x / 2);
    rel_err.push_back(std::abs(drop_exact / drop_rl - 1));
  }
  EXPECT_LT(rel_err.back(), 2e-3);
  // The next term is O((ka)^2) relative: halving ka divides the disagreement by about 4.
  EXPECT_NEAR(rel_err[0] / rel_err[1], 4.0, 0.2);
  EXPECT_NEAR(rel_err[1] / rel_err[2], 4.0, 0.2);
}

TEST(PochhammerChree, FirstModeApproachesTheRayleighSpeedAtLargeKa) {
  // The surface wave of a cylinder: c_phase -> cR, faster than cR at ka = 5, then slightly
  // slower with a curvature correction of order 1/(ka) (the SAFE solution agrees: 0.99759 cR
  // at ka = 40 for nu = 0.3), so the distance to cR halves when ka doubles.
  for (double nu : {0.1, 0.3, 0.45}) {
    const auto pc = rod(nu);
    const double cR = rayleigh_speed_reference(nu, pc.speeds().cS);
    const double dev40 = 1 - first_mode_phase_velocity(pc, 40.0) / cR;
    const double dev80 = 1 - first_mode_phase_velocity(pc, 80.0) / cR;
    EXPECT_GT(dev40, 0) << "nu " << nu;
    EXPECT_LT(dev40, 6e-3) << "nu " << nu;
    EXPECT_NEAR(dev40 / dev80, 2.0, 0.3) << "nu " << nu;
    EXPECT_GT(first_mode_phase_velocity(pc, 5.0), cR * 1.01) << "nu " << nu;
  }
  test::RodSafe safe(kE, 0.3, kRho, kA, 120);
  const double k = 40.0 / kA;
  EXPECT_NEAR(first_mode_phase_velocity(rod(0.3), 40.0) / (safe.frequencies(k)[0] / k), 1.0, 1e-5);
}

TEST(PochhammerChree, CutoffsAreTheRootsOfTheTwoK0Factors) {
  const auto pc = rod(0.3);
  const auto cuts = pc.cutoffs(pc.omega_of(11.0));
  ASSERT_GE(cuts.size(), 4u);
  // L(0,2): J1(omega a / cS) = 0 first zero j_{1,1} = 3.8317059702075125 (for nu = 0.3 the shear factor comes first)
  EXPECT_NEAR(pc.Omega_of(cuts[0].omega_rad_s), 3.8317059702075125, 1e-10);
  EXPECT_EQ(cuts[0].family, PochhammerChree::CutoffFamily::Shear);
  EXPECT_NEAR(pc.Omega_of(cuts[2].omega_rad_s), 7.0155866698156187, 1e-10);  // j_{1,2}
  // The dilatational factor, 2 J1(y) = kappa^2 y J0(y): residual zero at the returned root.
  const double y = pc.Omega_of(cuts[1].omega_rad_s) / pc.kappa();
  EXPECT_EQ(cuts[1].family, PochhammerChree::CutoffFamily::Dilatational);
  EXPECT_NEAR(2 * std::cyl_bessel_j(1.0, y) - pc.kappa() * pc.kappa() * y * std::cyl_bessel_j(0.0, y), 0, 1e-12);
  // The SAFE solution at k = 0 has the same non-zero frequencies.
  test::RodSafe safe(kE, 0.3, kRho, kA, 60);
  const auto w = safe.frequencies(0.0);
  std::vector<double> nonzero;
  for (double v : w)
    if (pc.Omega_of(v) > 0.5) nonzero.push_back(v);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_NEAR(nonzero[i] / cuts[i].omega_rad_s, 1.0, 2e-6) << "cut-off " << i;
  // In Hz for the rod paper's rod: L(0,2) starts at j11 cS / (2 pi a).
  EXPECT_NEAR(cuts[0].omega_rad_s / (2 * std::numbers::pi), 3.8317059702075125 * pc.speeds().cS / (2 * std::numbers::pi * kA), 1e-6);
}

TEST(PochhammerChree, FirstModeGroupVelocityMinimum) {
  const auto pc = rod(0.3);
  TraceOptions opt;
  opt.f_max_Hz = pc.omega_of(5.0) / (2 * std::numbers::pi);
  opt.ka_step = 0.005;
  const auto trace = trace_longitudinal_modes(pc, opt);
  const auto& l01 = trace.modes.at(0).points;
  std::size_t imin = 1;
  for (std::size_t i = 1; i < l01.size(); ++i)
    if (l01[i].c_group_m_s < l01[imin].c_group_m_s) imin = i;
  const double c0 = pc.speeds().c0;
  const double cg_min = l01[imin].c_group_m_s / c0, ka_min = l01[imin].k_rad_m * kA;
  // The commonly quoted figure: about 0.38 c0 near ka = 2.7 (nu = 0.3).
  EXPECT_NEAR(cg_min, 0.38, 0.005);
  EXPECT_NEAR(ka_min, 2.7, 0.05);
  // The same minimum from the SAFE eigenvectors (Hellmann-Feynman), on a golden search in k.
  test::RodSafe safe(kE, 0.3, kRho, kA, 24);
  double lo = 2.4 / kA, hi = 3.0 / kA;
  for (int i = 0; i < 22; ++i) {
    const double m1 = lo + (hi - lo) * 0.382, m2 = lo + (hi - lo) * 0.618;
    if (safe.group_velocity(m1, 0) < safe.group_velocity(m2, 0)) hi = m2;
    else lo = m1;
  }
  const double k_safe = 0.5 * (lo + hi);
  EXPECT_NEAR(safe.group_velocity(k_safe, 0) / c0, cg_min, 2e-5);
  EXPECT_NEAR(k_safe * kA, ka_min, 0.01);
}

// The refined L(0,1) minimum against a brute-force search that shares nothing with the
// library: the frequency equation (rod paper Eq. (1), divided by beta) written in k and omega
// with the standard library's Bessel functions, its lowest root at fixed k by a scan and
// bisection, c_g = d omega / dk by central differences, minimised over a fine ka grid.
TEST(PochhammerChree, RefinedGroupVelocityMinimumMatchesABruteForceSearch) {
  const auto pc = rod(0.3);
  const double cP = pc.speeds().cP, cS = pc.speeds().cS, c0 = pc.speeds().c0, cR = pc.speeds().cR;
  const auto F = [&](double k, double w) {
    const double a2 = w * w / (cP * cP) - k * k, b2 = w * w / (cS * cS) - k * k;
    double aJ1, J0a, J1b_b, J0b;  // alpha J1(alpha a), J0(alpha a), J1(beta a) / beta, J0(beta a)
    if (a2 > 0) {
      const double al = std::sqrt(a2);
      aJ1 = al * std::cyl_bessel_j(1.0, al * kA), J0a = std::cyl_bessel_j(0.0, al * kA);
    } else {
      const double s = std::sqrt(-a2);
      aJ1 = -s * std::cyl_bessel_i(1.0, s * kA), J0a = std::cyl_bessel_i(0.0, s * kA);
    }
    if (b2 > 0) {
      const double be = std::sqrt(b2);
      J1b_b = std::cyl_bessel_j(1.0, be * kA) / be, J0b = std::cyl_bessel_j(0.0, be * kA);
    } else {
      const double t = std::sqrt(-b2);
      J1b_b = std::cyl_bessel_i(1.0, t * kA) / t, J0b = std::cyl_bessel_i(0.0, t * kA);
    }
    return (2 / kA) * (b2 + k * k) * aJ1 * J1b_b - (b2 - k * k) * (b2 - k * k) * J0a * J1b_b -
           4 * k * k * aJ1 * J0b;
  };
  // The lowest root at fixed k: L(0,1)'s phase velocity lies between cR and c0.
  const auto omega_of_k = [&](double k) {
    double lo = 0.9 * cR * k, flo = F(k, lo);
    const double step = (1.01 * c0 - 0.9 * cR) * k / 400;
    double hi = lo + step, fhi = F(k, hi);
    while ((flo > 0) == (fhi > 0)) lo = hi, flo = fhi, hi += step, fhi = F(k, hi);
    for (int i = 0; i < 200 && hi - lo > 0; ++i) {
      const double mid = 0.5 * (lo + hi), fm = F(k, mid);
      if (mid == lo || mid == hi) break;
      ((fm > 0) == (flo > 0) ? lo : hi) = mid;
      if ((fm > 0) == (flo > 0)) flo = fm;
    }
    return 0.5 * (lo + hi);
  };
  const double dx = 1e-5;  // central-difference step in k a
  const auto c_group = [&](double x) { return (omega_of_k((x + dx) / kA) - omega_of_k((x - dx) / kA)) / (2 * dx / kA); };
  const auto brute = [&](double from, double to, double h) {
    std::pair<double, double> best{from, c_group(from)};
    for (double x = from + h; x <= to; x += h)
      if (const double c = c_group(x); c < best.second) best = {x, c};
    return best;
  };
  const auto coarse = brute(2.0, 3.5, 1e-3);
  const auto fine = brute(coarse.first - 2e-3, coarse.first + 2e-3, 1e-5);

  TraceOptions opt;
  opt.f_max_Hz = 600e3;  // the default trace (ka step 0.01), as mw-dispersion theory runs it
  const auto trace = trace_longitudinal_modes(pc, opt);
  const auto m = l01_group_velocity_minimum(pc, trace);
  ASSERT_TRUE(m.has_value());
  const double ka = m->k_rad_m * kA;
  std::printf("L(0,1) minimum: refined ka %.8f, c_g/c0 %.12f; brute force ka %.5f, c_g/c0 %.12f\n", ka,
              m->c_group_m_s / c0, fine.first, fine.second / c0);
  EXPECT_NEAR(ka, fine.first, 5e-5);
  EXPECT_NEAR(m->c_group_m_s / c0, fine.second / c0, 1e-9);
  EXPECT_NEAR(m->omega_rad_s, omega_of_k(m->k_rad_m), 1e-9 * m->omega_rad_s);
  EXPECT_NEAR(m->f_Hz, m->omega_rad_s / (2 * std::numbers::pi), 1e-9 * m->f_Hz);

  // What the trace's grid alone reported: a grid point, slower-looking only to the step.
  const auto& l01 = trace.modes.at(0).points;
  std::size_t imin = 0;
  for (std::size_t i = 1; i < l01.size(); ++i)
    if (l01[i].c_group_m_s < l01[imin].c_group_m_s) imin = i;
  std::printf("trace grid point: ka %.8f, c_g/c0 %.12f\n", l01[imin].k_rad_m * kA, l01[imin].c_group_m_s / c0);
  EXPECT_GE(l01[imin].c_group_m_s, m->c_group_m_s);
  EXPECT_GT(std::abs(l01[imin].k_rad_m * kA - ka), 10 * 5e-5);  // the grid point is off by more than the check's tolerance
}

TEST(PochhammerChree, GroupVelocityFromTheImplicitDerivativeMatchesFiniteDifferences) {
  for (double nu : {0.1, 0.3, 0.45}) {
    const auto pc = rod(nu);
    for (double x : {0.3, 1.0, 2.7, 4.0}) {
      const double k = x / kA, h = 1e-5 / kA;
      const double wmax = pc.omega_of(9.0);
      const auto w0 = pc.frequencies(k, wmax), wp = pc.frequencies(k + h, wmax), wm = pc.frequencies(k - h, wmax);
      ASSERT_EQ(w0.size(), wp.size());
      ASSERT_EQ(w0.size(), wm.size());
      for (std::size_t n = 0; n < w0.size(); ++n) {
        const double fd = (wp[n] - wm[n]) / (2 * h);
        const double cg = pc.group_velocity(k, w0[n]);
        EXPECT_NEAR(cg, fd, 1e-6 * pc.speeds().c0) << "nu " << nu << " ka " << x << " mode " << n + 1;
      }
    }
  }
}

// Root tracking across a dense k grid: every traced point a root, the n-th
// traced mode the n-th SAFE eigenvalue at the same k (nothing skipped or swapped),
// and continuity of each curve.
class Tracking : public ::testing::TestWithParam<double> {};

TEST_P(Tracking, NoBranchSkippedOrSwapped) {
  const double nu = GetParam();
  const auto pc = rod(nu);
  const double W_max = 8.0;
  TraceOptions opt;
  opt.f_max_Hz = pc.omega_of(W_max) / (2 * std::numbers::pi);
  const auto trace = trace_longitudinal_modes(pc, opt);
  EXPECT_EQ(trace.unresolved_steps, 0);
  ASSERT_GE(trace.modes.size(), 3u);
  test::RodSafe safe(kE, nu, kRho, kA, 40);
  const double wmax = pc.omega_of(W_max);
  int compared = 0;
  for (const auto& curve : trace.modes) {
    double max_res = 0;
    for (std::size_t i = 0; i < curve.points.size(); ++i) {
      const auto& p = curve.points[i];
      if (p.k_rad_m > 0) max_res = std::max(max_res, pc.relative_residual(p.k_rad_m, p.omega_rad_s));
      if (i > 0) {
        // Continuity: the group velocity (energy velocity) never exceeds cP, so a step dx
        // in k a moves omega a / cS by at most kappa dx; a jump to another branch would not.
        const double dW = std::abs(pc.Omega_of(p.omega_rad_s - curve.points[i - 1].omega_rad_s));
        const double dx = (p.k_rad_m - curve.points[i - 1].k_rad_m) * kA;
        EXPECT_LE(dW, pc.kappa() * dx + 1e-9) << "mode " << curve.mode << " at ka " << p.k_rad_m * kA;
        EXPECT_LE(std::abs(p.c_group_m_s), pc.speeds().cP * (1 + 1e-9));
      }
    }
    EXPECT_LT(max_res, 1e-9) << "mode " << curve.mode;
  }
  // At every 10th k of the L(0,1) trace: the traced frequencies below the band top are
  // exactly the SAFE eigenvalues below it, in order.
  const auto& l01 = trace.modes.at(0).points;
  for (std::size_t i = 1; i < l01.size(); i += 10) {
    const double k = l01[i].k_rad_m;
    std::vector<double> traced;
    for (const auto& curve : trace.modes)
      for (const auto& p : curve.points)
        if (p.k_rad_m == k && p.omega_rad_s < wmax) traced.push_back(p.omega_rad_s);
    std::vector<double> ref;
    for (double w : safe.frequencies(k))
      if (w < wmax * (1 - 1e-4)) ref.push_back(w);
    ASSERT_GE(traced.size(), ref.size()) << "ka " << k * kA;
    for (std::size_t n = 0; n < ref.size(); ++n) {
      EXPECT_NEAR(traced[n] / ref[n], 1.0, 2e-5) << "nu " << nu << " ka " << k * kA << " mode " << n + 1;
      ++compared;
    }
  }
  EXPECT_GT(compared, 150);
}

INSTANTIATE_TEST_SUITE_P(PoissonRatios, Tracking, ::testing::Values(0.1, 0.3, 0.45));

TEST(PochhammerChree, BackwardWaveOfL02IsReportedOnBothBranches) {
  const auto pc = rod(0.3);
  TraceOptions opt;
  opt.f_max_Hz = pc.omega_of(4.5) / (2 * std::numbers::pi);
  opt.ka_step = 0.005;
  const auto trace = trace_longitudinal_modes(pc, opt);
  const auto& l02 = trace.modes.at(1);
  ASSERT_EQ(l02.mode, 2);
  ASSERT_EQ(l02.zgv_k_rad_m.size(), 1u);  // one zero-group-velocity point
  // Its frequency is the minimum of L(0,2) over k: below the cut-off.
  double w_zgv = 0;
  for (const auto& p : l02.points)
    if (p.c_group_m_s == 0 && p.k_rad_m > 0) w_zgv = p.omega_rad_s;
  const double w_cut = pc.cutoffs(pc.omega_of(4.0)).at(0).omega_rad_s;
  ASSERT_GT(w_zgv, 0);
  EXPECT_LT(w_zgv, w_cut);
  test::RodSafe safe(kE, 0.3, kRho, kA, 40);
  EXPECT_NEAR(safe.group_velocity(l02.zgv_k_rad_m[0], 1), 0.0, 1e-3 * pc.speeds().c0);
  // Between the ZGV point and the cut-off: two wavenumbers, group velocities of opposite sign.
  const double f = (0.5 * (w_zgv + w_cut)) / (2 * std::numbers::pi);
  const auto pts = sample_at_frequencies(pc, trace, {f});
  std::vector<DispersionPoint> mode2;
  for (const auto& p : pts)
    if (p.mode == 2) mode2.push_back(p);
  ASSERT_EQ(mode2.size(), 2u);
  EXPECT_LT(mode2[0].c_group_m_s, 0);
  EXPECT_GT(mode2[1].c_group_m_s, 0);
  EXPECT_EQ(mode2[0].branch, 0);
  EXPECT_EQ(mode2[1].branch, 1);
  EXPECT_LT(mode2[0].k_rad_m, mode2[1].k_rad_m);
  for (const auto& p : mode2) {
    EXPECT_LT(pc.relative_residual(p.k_rad_m, p.omega_rad_s), 1e-10);
    EXPECT_NEAR(safe.frequencies(p.k_rad_m).at(1) / p.omega_rad_s, 1.0, 1e-5);  // the 2nd eigenvalue there
    EXPECT_NEAR(safe.group_velocity(p.k_rad_m, 1) / p.c_group_m_s, 1.0, 2e-3);
  }
}

TEST(PochhammerChree, FrequencySamplingMatchesTheTrace) {
  const auto pc = rod(0.3);
  TraceOptions opt;
  opt.f_max_Hz = 500e3;
  const auto trace = trace_longitudinal_modes(pc, opt);
  std::vector<double> f;
  for (double v = 10e3; v <= 500e3; v += 10e3) f.push_back(v);
  const auto pts = sample_at_frequencies(pc, trace, f);
  int l01 = 0;
  for (const auto& p : pts) {
    EXPECT_LT(pc.relative_residual(p.k_rad_m, p.omega_rad_s), 1e-10);
    if (p.mode == 1) ++l01;
  }
  EXPECT_EQ(l01, int(f.size()));  // L(0,1) exists at every frequency, once
}
