#pragma once
// Scalar root finding shared by the dispersion solvers: Brent's method on a
// bracket (sign change required), to full double precision.
#include <cmath>
#include <functional>
#include <stdexcept>

namespace mesowave::wave {

/// Root of `f` in [a, b] given f(a) and f(b) of opposite sign (or one zero).
/// Brent (1973): inverse quadratic interpolation, secant and bisection steps,
/// converging to |b - a| <= 4 eps |x| + xtol.
double brent_root(const std::function<double(double)>& f, double a, double b, double fa, double fb,
                  double xtol = 0.0, int max_iterations = 200);

}  // namespace mesowave::wave
