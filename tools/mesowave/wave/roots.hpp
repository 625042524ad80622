#pragma once
// Scalar root finding shared by the dispersion solvers: Brent's method on a
// bracket (sign change required), to full double precision; and golden-section
// search for the minimum of a unimodal function on an interval.
#include <cmath>
#include <functional>
#include <stdexcept>

namespace mesowave::wave {

/// Root of `f` in [a, b] given f(a) and f(b) of opposite sign (or one zero).
/// Brent (1973): inverse quadratic interpolation, secant and bisection steps,
/// converging to |b - a| <= 4 eps |x| + xtol.
double brent_root(const std::function<double(double)>& f, double a, double b, double fa, double fb,
                  double xtol = 0.0, int max_iterations = 200);

/// A minimum: where and the value there.
struct Minimum {
  double x = 0, f = 0;
};

/// Minimum of `f` on [a, b], `f` unimodal there (one local minimum): golden-section search
/// (Kiefer 1953), the interval shrunk by 0.618 per evaluation until it is below
/// xtol + 4 eps |x|, the best point evaluated returned. The position is known to about
/// sqrt(eps) relative where f is smooth (the minimum is flat), the value to rounding.
Minimum golden_section_minimum(const std::function<double(double)>& f, double a, double b, double xtol = 0.0,
                               int max_iterations = 200);

}  // namespace mesowave::wave
