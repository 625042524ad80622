#include "mesowave/wave/pochhammer_chree.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesowave/core/check.hpp"
#include "mesowave/wave/roots.hpp"

namespace mesowave::wave {

namespace {

// A0, A1, C1, C2 of one argument p = (alpha a)^2 or (beta a)^2, all times the
// same positive factor exp(-s) when p = -s^2 < 0 (exponentially scaled I_n).
struct Pieces {
  double A0, A1, C1, C2;
};

// exp(-s) I_n(s), n = 0, 1, 2: std::cyl_bessel_i up to where it overflows,
// the Hankel asymptotic series beyond (relative error < 1e-12 for s > 600).
double scaled_bessel_i(int n, double s) {
  if (s < 600) return std::cyl_bessel_i(double(n), s) * std::exp(-s);
  const double mu = 4.0 * n * n;
  double term = 1, sum = 1;
  for (int j = 1; j <= 6; ++j) {
    term *= -(mu - (2.0 * j - 1) * (2.0 * j - 1)) / (j * 8.0 * s);
    sum += term;
  }
  return sum / std::sqrt(2 * std::numbers::pi * s);
}

Pieces pieces(double p) {
  const double r = std::sqrt(std::abs(p));
  if (r < 1e-4) {
    // Taylor series of the entire functions (terms beyond p^2 are below 1e-17).
    Pieces t{1 - p / 4 + p * p / 64, p / 2 - p * p / 16, 0.5 - p / 16 + p * p / 384, 0.125 - p / 96 + p * p / 3072};
    if (p < 0) {
      const double g = std::exp(-r);
      t.A0 *= g;
      t.A1 *= g;
      t.C1 *= g;
      t.C2 *= g;
    }
    return t;
  }
  if (p > 0) {
    const double J0 = std::cyl_bessel_j(0.0, r), J1 = std::cyl_bessel_j(1.0, r);
    // Upward recurrence J2 = 2 J1 / z - J0 loses digits for small z.
    const double J2 = r < 2 ? std::cyl_bessel_j(2.0, r) : 2 * J1 / r - J0;
    return {J0, r * J1, J1 / r, J2 / p};
  }
  const double I0 = scaled_bessel_i(0, r), I1 = scaled_bessel_i(1, r);
  const double I2 = r < 2 ? scaled_bessel_i(2, r) : I0 - 2 * I1 / r;
  // J_n(i s) = i^n I_n(s): A0 = I0, A1 = -s I1, C1 = I1 / s, C2 = J2/(i s)^2 = I2 / s^2.
  return {I0, -r * I1, I1 / r, I2 / (r * r)};
}

int sign_of(double v) { return (v > 0) - (v < 0); }

}  // namespace

PochhammerChree::PochhammerChree(const IsotropicMaterial& material, double radius_m)
    : material_(material), speeds_(wave_speeds(material)), a_(require_positive("rod radius", radius_m, "m")),
      kappa_(speeds_.cP / speeds_.cS) {}

PochhammerChree::Value PochhammerChree::evaluate(double x, double Omega) const {
  const double x2 = x * x;
  const double q = Omega * Omega - x2;
  const double p = Omega * Omega / (kappa_ * kappa_) - x2;
  const Pieces P = pieces(p), Q = pieces(q);
  // D = 2 (q + x^2) A1(p) C1(q) - (q - x^2)^2 A0(p) C1(q) - 4 x^2 A1(p) A0(q)
  const double t1 = 2 * (q + x2) * P.A1 * Q.C1;
  const double t2 = (q - x2) * (q - x2) * P.A0 * Q.C1;
  const double t3 = 4 * x2 * P.A1 * Q.A0;
  Value v;
  v.D = t1 - t2 - t3;
  v.magnitude = std::abs(t1) + std::abs(t2) + std::abs(t3);
  // Partial derivatives in p, q and the explicit x.
  const double dA0p = -P.C1 / 2, dA1p = P.A0 / 2;
  const double dA0q = -Q.C1 / 2, dC1q = -Q.C2 / 2;
  const double D_p = 2 * (q + x2) * dA1p * Q.C1 - (q - x2) * (q - x2) * dA0p * Q.C1 - 4 * x2 * dA1p * Q.A0;
  const double D_q = 2 * P.A1 * Q.C1 + 2 * (q + x2) * P.A1 * dC1q - 2 * (q - x2) * P.A0 * Q.C1 -
                     (q - x2) * (q - x2) * P.A0 * dC1q - 4 * x2 * P.A1 * dA0q;
  const double D_xe = 4 * x * P.A1 * Q.C1 + 4 * x * (q - x2) * P.A0 * Q.C1 - 8 * x * P.A1 * Q.A0;
  // p = Omega^2/kappa^2 - x^2, q = Omega^2 - x^2.
  v.D_x = D_xe - 2 * x * (D_p + D_q);
  v.D_Omega = 2 * Omega * (D_p / (kappa_ * kappa_) + D_q);
  return v;
}

double PochhammerChree::relative_residual(double k, double omega) const {
  const Value v = evaluate(x_of(k), Omega_of(omega));
  return v.magnitude > 0 ? std::abs(v.D) / v.magnitude : std::abs(v.D);
}

double PochhammerChree::group_velocity(double k, double omega) const {
  const Value v = evaluate(x_of(k), Omega_of(omega));
  if (v.D_Omega == 0) return 0;
  return -speeds_.cS * v.D_x / v.D_Omega;
}

std::vector<PochhammerChree::Cutoff> PochhammerChree::cutoffs(double omega_max) const {
  std::vector<Cutoff> out;
  const double Omega_max = Omega_of(omega_max);
  const double k2 = kappa_ * kappa_;
  // Both factors scanned with a sign-change + extremum check on a fine grid.
  const auto scan = [&](auto&& f, CutoffFamily family) {
    const double h = 0.005;
    double x0 = h, f0 = f(x0);
    for (double x1 = 2 * h; x1 <= Omega_max + h; x1 += h) {
      const double f1 = f(x1);
      if (sign_of(f0) != sign_of(f1)) {
        const double r = brent_root(f, x0, x1, f0, f1);
        if (r <= Omega_max) out.push_back({omega_of(r), family});
      }
      x0 = x1;
      f0 = f1;
    }
  };
  scan([](double W) { return std::cyl_bessel_j(1.0, W); }, CutoffFamily::Shear);
  // 2 A1(p) - q A0(p) with p = Omega^2 / kappa^2, q = Omega^2, divided by y = Omega / kappa > 0.
  scan(
      [&](double W) {
        const double y = W / kappa_;
        return 2 * std::cyl_bessel_j(1.0, y) - k2 * y * std::cyl_bessel_j(0.0, y);
      },
      CutoffFamily::Dilatational);
  std::sort(out.begin(), out.end(), [](const Cutoff& a, const Cutoff& b) { return a.omega_rad_s < b.omega_rad_s; });
  return out;
}

std::vector<double> PochhammerChree::roots_in_Omega(double x, double Omega_max, double step) const {
  std::vector<double> roots;
  if (!(x > 0)) return roots;
  // Below x cR/cS/2 there is no root (the slowest mode, L(0,1), has c_phase > cR),
  // so the scan starts there and steps over the double root at Omega = 0.
  const double start = std::min(step, 0.5 * x * speeds_.cR / speeds_.cS);
  const auto D = [&](double W) { return evaluate(x, W).D; };
  const auto DW = [&](double W) { return evaluate(x, W).D_Omega; };
  double w0 = start;
  Value v0 = evaluate(x, w0);
  const int n = int(std::ceil((Omega_max - start) / step));
  for (int i = 1; i <= n; ++i) {
    const double w1 = std::min(start + i * step, Omega_max);
    const Value v1 = evaluate(x, w1);
    if (v0.D == 0) {
      roots.push_back(w0);
    } else if (sign_of(v0.D) != sign_of(v1.D)) {
      if (v1.D != 0) roots.push_back(brent_root(D, w0, w1, v0.D, v1.D));
    } else if (sign_of(v0.D_Omega) != sign_of(v1.D_Omega) && v0.D_Omega != 0 && v1.D_Omega != 0) {
      // An extremum of D inside: two roots hide here if D crosses zero at it.
      const double we = brent_root(DW, w0, w1, v0.D_Omega, v1.D_Omega);
      const double De = D(we);
      if (sign_of(De) != sign_of(v0.D)) {
        roots.push_back(De == 0 ? we : brent_root(D, w0, we, v0.D, De));
        if (De != 0) roots.push_back(brent_root(D, we, w1, De, v1.D));
      }
    }
    w0 = w1;
    v0 = v1;
    if (w1 >= Omega_max) break;
  }
  if (v0.D == 0 && (roots.empty() || roots.back() != w0)) roots.push_back(w0);
  return roots;
}

std::vector<double> PochhammerChree::frequencies(double k, double omega_max, double scan_step) const {
  auto roots = roots_in_Omega(x_of(k), Omega_of(omega_max), scan_step);
  for (double& r : roots) r = omega_of(r);
  return roots;
}

std::string mode_name(int mode) { return "L(0," + std::to_string(mode) + ")"; }

namespace {

struct Sample {
  double x, W, slope;  // k a, omega a / cS, dOmega/dx
};

double slope_at(const PochhammerChree& pc, double x, double W) {
  const auto v = pc.evaluate(x, W);
  return v.D_Omega == 0 ? 0.0 : -v.D_x / v.D_Omega;
}

// Whether the roots at x + h continue those at x: same count except roots
// crossing the top of the scan, each within a quarter of the local spacing of
// its linear prediction.
bool continues(const std::vector<Sample>& old_roots, const std::vector<double>& new_roots, double h,
               double W_top) {
  const std::size_t n_old = old_roots.size(), n_new = new_roots.size();
  const std::size_t n = std::min(n_old, n_new);
  std::vector<double> predicted(n_old);
  for (std::size_t i = 0; i < n_old; ++i) predicted[i] = old_roots[i].W + h * old_roots[i].slope;
  const auto gap = [&](std::size_t i) {
    double g = 1e300;
    if (i > 0) g = std::min({g, predicted[i] - predicted[i - 1], new_roots[i] - new_roots[i - 1]});
    if (i + 1 < n) g = std::min({g, predicted[i + 1] - predicted[i], new_roots[i + 1] - new_roots[i]});
    return g;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const double tol = std::max(0.25 * gap(i), 1e-10);
    if (!(std::abs(new_roots[i] - predicted[i]) <= tol)) return false;
  }
  for (std::size_t i = n; i < n_old; ++i)  // roots gone: must have left through the top
    if (predicted[i] < W_top - 2 * (std::abs(old_roots[i].slope) * h + 1e-9) - 1e-6) return false;
  for (std::size_t i = n; i < n_new; ++i)  // roots new: must have come in through the top
    if (new_roots[i] < W_top - 0.05) return false;
  return true;
}

DispersionPoint to_point(const PochhammerChree& pc, int mode, int branch, const Sample& s) {
  DispersionPoint p;
  p.mode = mode;
  p.branch = branch;
  p.k_rad_m = pc.k_of(s.x);
  p.omega_rad_s = pc.omega_of(s.W);
  p.f_Hz = p.omega_rad_s / (2 * std::numbers::pi);
  p.c_phase_m_s = s.x > 0 ? p.omega_rad_s / p.k_rad_m : 0.0;
  p.c_group_m_s = s.slope * pc.speeds().cS;
  return p;
}

// Zero group velocity between two samples whose slopes differ in sign: bisection
// on the sign of dOmega/dx along the curve, the mode's Omega solved at each trial k.
Sample zero_group_velocity(const PochhammerChree& pc, const Sample& s0, const Sample& s1) {
  double lo = s0.x, hi = s1.x, W = 0.5 * (s0.W + s1.W);
  const double spread = std::abs(s1.W - s0.W) + 1e-9;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    const auto f = [&](double w) { return pc.D(mid, w); };
    double wa = std::min(s0.W, s1.W) - spread, wb = std::max(s0.W, s1.W) + spread;
    double fa = f(wa), fb = f(wb);
    for (int g = 0; g < 20 && sign_of(fa) == sign_of(fb); ++g) {
      wa -= spread;
      wb += spread;
      fa = f(wa);
      fb = f(wb);
    }
    if (sign_of(fa) == sign_of(fb)) break;
    W = brent_root(f, wa, wb, fa, fb);
    (sign_of(slope_at(pc, mid, W)) == sign_of(s0.slope) ? lo : hi) = mid;
  }
  return {0.5 * (lo + hi), W, 0.0};
}

ModeCurve finish_piece(const PochhammerChree& pc, int mode, const std::vector<Sample>& c, std::size_t begin,
                       std::size_t end) {
  ModeCurve curve;
  curve.mode = mode;
  int branch = 0;
  for (std::size_t j = begin; j < end; ++j) {
    if (j > begin && c[j - 1].x > 0 && sign_of(c[j - 1].slope) * sign_of(c[j].slope) < 0) {
      const Sample z = zero_group_velocity(pc, c[j - 1], c[j]);
      curve.points.push_back(to_point(pc, mode, branch, z));
      curve.zgv_k_rad_m.push_back(pc.k_of(z.x));
      ++branch;
    }
    curve.points.push_back(to_point(pc, mode, branch, c[j]));
  }
  return curve;
}

}  // namespace

DispersionTrace trace_longitudinal_modes(const PochhammerChree& pc, const TraceOptions& opt) {
  require_positive("maximum frequency", opt.f_max_Hz, "Hz");
  require_positive("k a step", opt.ka_step);
  require_positive("scan step", opt.scan_step);
  const double W_max = pc.Omega_of(2 * std::numbers::pi * opt.f_max_Hz);
  const double W_top = W_max * (1 + opt.margin);
  const double c0_cS = pc.speeds().c0 / pc.speeds().cS;

  DispersionTrace trace;
  std::vector<std::vector<Sample>> curves;  // per mode, possibly with gaps (left through the top)
  std::vector<Sample> row{{0.0, 0.0, c0_cS}};  // L(0,1) from the origin with slope c0 / cS
  for (const auto& c : pc.cutoffs(pc.omega_of(W_top))) row.push_back({0.0, pc.Omega_of(c.omega_rad_s), 0.0});
  const auto push_row = [&](const std::vector<Sample>& r) {
    if (curves.size() < r.size()) curves.resize(r.size());
    for (std::size_t i = 0; i < r.size(); ++i) curves[i].push_back(r[i]);
  };
  push_row(row);

  double x = 0, h_nominal = opt.ka_step, h = opt.ka_step;
  const double h_min = opt.ka_step / 4096;
  const double x_guard = 50 * W_top + 50;  // L(0,1) reaches W_max long before (c_phase > cR)
  while (x < x_guard) {
    std::vector<double> roots;
    for (;;) {
      roots = pc.roots_in_Omega(x + h, W_top, opt.scan_step);
      if (continues(row, roots, h, W_top)) break;
      if (h <= h_min) {
        ++trace.unresolved_steps;
        break;
      }
      h /= 2;
      ++trace.step_refinements;
    }
    x += h;
    std::vector<Sample> next;
    for (double W : roots) next.push_back({x, W, slope_at(pc, x, W)});
    // A mode that left through the top and comes back starts a new piece of its curve.
    for (std::size_t i = row.size(); i < next.size() && i < curves.size(); ++i)
      curves[i].push_back({std::nan(""), 0, 0});
    push_row(next);
    row = next;
    h = std::min(h_nominal, 2 * h);
    if (row.empty() || row.front().W > W_max) break;
  }

  // Each continuous piece of each mode: points in SI, zero-group-velocity points
  // located exactly, branches numbered along the piece.
  for (std::size_t m = 0; m < curves.size(); ++m) {
    const auto& c = curves[m];
    std::size_t begin = 0;
    while (begin < c.size()) {
      std::size_t end = begin;
      while (end < c.size() && !std::isnan(c[end].x)) ++end;
      bool below = false;
      for (std::size_t j = begin; j < end; ++j) below = below || c[j].W <= W_max;
      if (below) trace.modes.push_back(finish_piece(pc, int(m) + 1, c, begin, end));
      begin = end + 1;
    }
  }
  return trace;
}

std::optional<GroupVelocityMinimum> l01_group_velocity_minimum(const PochhammerChree& pc, const DispersionTrace& trace) {
  if (trace.modes.empty() || trace.modes.front().mode != 1) return std::nullopt;
  const auto& l01 = trace.modes.front().points;
  std::size_t imin = 0;
  for (std::size_t i = 1; i < l01.size(); ++i)
    if (l01[i].c_group_m_s < l01[imin].c_group_m_s) imin = i;
  if (imin == 0 || imin + 1 >= l01.size()) return std::nullopt;
  const double x_lo = pc.x_of(l01[imin - 1].k_rad_m), x_hi = pc.x_of(l01[imin + 1].k_rad_m);
  // Omega(x) rises along L(0,1) (c_g > 0), so the neighbours' Omega bracket the root at any x
  // between them; L(0,2) lies far above.
  const double W_lo = pc.Omega_of(l01[imin - 1].omega_rad_s), W_hi = pc.Omega_of(l01[imin + 1].omega_rad_s);
  const auto root = [&](double x) {
    const auto g = [&](double W) { return pc.D(x, W); };
    return brent_root(g, W_lo, W_hi, g(W_lo), g(W_hi));
  };
  const auto c_group = [&](double x) { return slope_at(pc, x, root(x)) * pc.speeds().cS; };
  const Minimum m = golden_section_minimum(c_group, x_lo, x_hi);
  GroupVelocityMinimum out;
  out.k_rad_m = pc.k_of(m.x);
  out.omega_rad_s = pc.omega_of(root(m.x));
  out.f_Hz = out.omega_rad_s / (2 * std::numbers::pi);
  out.c_group_m_s = m.f;
  return out;
}

std::vector<DispersionPoint> sample_at_frequencies(const PochhammerChree& pc, const DispersionTrace& trace,
                                                   const std::vector<double>& f_Hz) {
  std::vector<DispersionPoint> out;
  for (const auto& curve : trace.modes) {
    const auto& pts = curve.points;
    std::vector<DispersionPoint> mode_points;
    for (double f : f_Hz) {
      const double omega = 2 * std::numbers::pi * f;
      const double W = pc.Omega_of(omega);
      for (std::size_t j = 0; j + 1 < pts.size(); ++j) {
        const auto& p0 = pts[j];
        const auto& p1 = pts[j + 1];
        const double d0 = p0.omega_rad_s - omega, d1 = p1.omega_rad_s - omega;
        // Half-open crossing test so a frequency on a node is counted once.
        if (!((d0 < 0 && d1 >= 0) || (d0 > 0 && d1 <= 0))) continue;
        const double x0 = pc.x_of(p0.k_rad_m), x1 = pc.x_of(p1.k_rad_m);
        const auto g = [&](double x) { return pc.D(x, W); };
        double x;
        const double g0 = g(x0), g1 = g(x1);
        if (d1 == 0) x = x1;
        else if (sign_of(g0) != sign_of(g1)) x = brent_root(g, x0, x1, g0, g1);
        else x = x0 + (x1 - x0) * d0 / (d0 - d1);  // a cut-off end (D even in x): linear start
        if (!(x > 0)) continue;
        DispersionPoint p;
        p.mode = curve.mode;
        p.branch = p1.branch;  // an interval that starts at a zero-group-velocity point belongs to the next branch
        p.omega_rad_s = omega;
        p.f_Hz = f;
        p.k_rad_m = pc.k_of(x);
        p.c_phase_m_s = omega / p.k_rad_m;
        p.c_group_m_s = pc.group_velocity(p.k_rad_m, omega);
        mode_points.push_back(p);
      }
    }
    std::stable_sort(mode_points.begin(), mode_points.end(),
                     [](const DispersionPoint& a, const DispersionPoint& b) { return a.branch < b.branch; });
    out.insert(out.end(), mode_points.begin(), mode_points.end());
  }
  return out;
}

}  // namespace mesowave::wave
