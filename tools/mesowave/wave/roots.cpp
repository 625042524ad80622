#include "mesowave/wave/roots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace mesowave::wave {

double brent_root(const std::function<double(double)>& f, double a, double b, double fa, double fb, double xtol,
                  int max_iterations) {
  if (fa == 0) return a;
  if (fb == 0) return b;
  if ((fa > 0) == (fb > 0)) throw std::logic_error("brent_root: the interval does not bracket a root");
  const double eps = std::numeric_limits<double>::epsilon();
  double c = a, fc = fa, d = b - a, e = d;
  for (int it = 0; it < max_iterations; ++it) {
    if ((fb > 0) == (fc > 0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2 * eps * std::abs(b) + 0.5 * xtol;
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0) return b;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      double p, q;
      const double s = fb / fa;
      if (a == c) {
        p = 2 * m * s;
        q = 1 - s;
      } else {
        const double qq = fa / fc, r = fb / fc;
        p = s * (2 * m * qq * (qq - r) - (b - a) * (r - 1));
        q = (qq - 1) * (r - 1) * (s - 1);
      }
      if (p > 0) q = -q;
      else p = -p;
      if (2 * p < std::min(3 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (m > 0 ? tol : -tol);
    fb = f(b);
  }
  return b;
}

Minimum golden_section_minimum(const std::function<double(double)>& f, double a, double b, double xtol,
                               int max_iterations) {
  if (!(a < b)) throw std::logic_error("golden_section_minimum: empty interval");
  const double eps = std::numeric_limits<double>::epsilon();
  const double r = 0.5 * (std::sqrt(5.0) - 1);  // 1/phi
  double c = b - r * (b - a), d = a + r * (b - a);
  double fc = f(c), fd = f(d);
  for (int it = 0; it < max_iterations && b - a > xtol + 4 * eps * std::max(std::abs(a), std::abs(b)); ++it) {
    if (fc <= fd) {  // the minimum lies in [a, d]
      b = d;
      d = c;
      fd = fc;
      c = b - r * (b - a);
      fc = f(c);
    } else {  // in [c, b]
      a = c;
      c = d;
      fc = fd;
      d = a + r * (b - a);
      fd = f(d);
    }
  }
  return fc <= fd ? Minimum{c, fc} : Minimum{d, fd};
}

}  // namespace mesowave::wave
