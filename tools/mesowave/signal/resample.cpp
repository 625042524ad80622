#include "mesowave/signal/resample.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/signal/validate.hpp"

namespace mesowave::signal {
namespace {

// Second derivatives of the natural cubic spline on a uniform grid:
// M_{i-1} + 4 M_i + M_{i+1} = 6 (y_{i+1} - 2 y_i + y_{i-1}) / h^2, M_0 = M_{n-1} = 0,
// solved by the Thomas algorithm (the matrix is diagonally dominant).
std::vector<double> spline_curvatures(const std::vector<double>& y, double h) {
  const std::size_t n = y.size();
  std::vector<double> m(n, 0.0);
  if (n < 3) return m;
  const std::size_t inner = n - 2;
  std::vector<double> c(inner), d(inner);
  for (std::size_t j = 0; j < inner; ++j) {
    const std::size_t i = j + 1;
    const double rhs = 6.0 * (y[i + 1] - 2.0 * y[i] + y[i - 1]) / (h * h);
    const double diag = 4.0 - (j > 0 ? c[j - 1] : 0.0);
    c[j] = 1.0 / diag;
    d[j] = (rhs - (j > 0 ? d[j - 1] : 0.0)) / diag;
  }
  m[inner] = d[inner - 1];
  for (std::size_t j = inner - 1; j-- > 0;) m[j + 1] = d[j] - c[j] * m[j + 2];
  return m;
}

}  // namespace

std::string_view to_string(Interpolation method) {
  return method == Interpolation::linear ? "linear" : "cubic-spline";
}

Interpolation parse_interpolation(std::string_view text) {
  if (text == "linear") return Interpolation::linear;
  if (text == "cubic" || text == "cubic-spline" || text == "spline") return Interpolation::cubic_spline;
  throw InputError("interpolation '" + std::string(text) + "' must be linear or cubic (natural cubic spline)");
}

TimeBase time_base(const Signal& s) { return {s.t0_s, s.dt_s, s.samples.size()}; }

bool same_time_base(const TimeBase& a, const TimeBase& b) {
  return a.count == b.count && std::abs(a.dt_s - b.dt_s) <= 1e-9 * std::abs(a.dt_s) &&
         std::abs(a.t0_s - b.t0_s) <= 1e-6 * std::abs(a.dt_s);
}

std::string describe(const TimeBase& base) {
  return std::to_string(base.count) + " samples, dt " + format_number(base.dt_s * 1e6) + " us, t0 " +
         format_number(base.t0_s * 1e6) + " us";
}

Signal resample(const Signal& s, const TimeBase& target, Interpolation method) {
  require_valid(s, 2);
  if (!(target.dt_s > 0) || !std::isfinite(target.dt_s) || !std::isfinite(target.t0_s))
    throw InputError("resampling " + s.name + ": target sampling interval must be positive and finite");
  const TimeBase source = time_base(s);
  const double slack = 1e-9 * s.dt_s;
  if (target.count > 0 && (target.t0_s < source.t0_s - slack || target.end_s() > source.end_s() + slack))
    throw InputError("resampling signal " + s.name + ": target times " + format_number(target.t0_s * 1e6) + " .. " +
                     format_number(target.end_s() * 1e6) + " us reach outside its record " +
                     format_number(source.t0_s * 1e6) + " .. " + format_number(source.end_s() * 1e6) +
                     " us (no extrapolation)");
  const auto& y = s.samples;
  const std::size_t n = y.size();
  const std::vector<double> m =
      method == Interpolation::cubic_spline ? spline_curvatures(y, s.dt_s) : std::vector<double>();
  Signal out = s;
  out.t0_s = target.t0_s;
  out.dt_s = target.dt_s;
  out.samples.resize(target.count);
  for (std::size_t i = 0; i < target.count; ++i) {
    const double u = std::clamp((target.t0_s + double(i) * target.dt_s - s.t0_s) / s.dt_s, 0.0, double(n - 1));
    const std::size_t j = std::min(std::size_t(u), n - 2);
    const double a = u - double(j);  // in [0, 1]
    double v = (1.0 - a) * y[j] + a * y[j + 1];
    if (method == Interpolation::cubic_spline)
      v -= a * (1.0 - a) * s.dt_s * s.dt_s / 6.0 * ((2.0 - a) * m[j] + (1.0 + a) * m[j + 1]);
    out.samples[i] = v;
  }
  return out;
}

TimeBase restrict_time_base(const TimeBase& base, double begin_s, double end_s, std::string_view what) {
  const double slack = 1e-9 * base.dt_s;
  const double first = std::ceil((begin_s - base.t0_s - slack) / base.dt_s);
  const double last = std::floor((end_s - base.t0_s + slack) / base.dt_s);
  const double lo = std::max(first, 0.0), hi = std::min(last, double(base.count) - 1.0);
  if (!(hi >= lo))
    throw InputError(std::string(what) + ": no sample lies within " + format_number(begin_s * 1e6) + " .. " +
                     format_number(end_s * 1e6) + " us");
  return {base.t0_s + lo * base.dt_s, base.dt_s, std::size_t(hi - lo) + 1};
}

}  // namespace mesowave::signal
