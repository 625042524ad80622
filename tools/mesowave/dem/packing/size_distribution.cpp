#include "mesowave/dem/packing/size_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/io/csv.hpp"

namespace mesowave::dem {
namespace {

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  const auto k = std::size_t(std::upper_bound(x.begin(), x.end(), at) - x.begin()) - 1;
  return y[k] + (y[k + 1] - y[k]) * (at - x[k]) / (x[k + 1] - x[k]);
}

struct Column {
  std::size_t index;
  double factor;
};

std::optional<Column> find_unit_column(const io::CsvTable& table, std::initializer_list<std::string_view> stems,
                                       std::initializer_list<std::pair<std::string_view, double>> units) {
  for (auto stem : stems)
    for (auto [suffix, factor] : units)
      if (auto i = table.find_column(std::string(stem) + "_" + std::string(suffix))) return Column{*i, factor};
  return std::nullopt;
}

}  // namespace

static SieveCurve curve_from_table(const io::CsvTable& table) {
  const std::string& origin = table.origin;
  const auto size = find_unit_column(table, {"d", "size"}, {{"m", 1.0}, {"mm", 1e-3}, {"um", 1e-6}});
  if (!size) throw InputError(origin + ": no size column (d_mm, d_m, d_um, size_mm, size_m or size_um)");
  const auto passing = find_unit_column(table, {"passing"}, {{"fraction", 1.0}, {"pct", 0.01}, {"percent", 0.01}});
  if (!passing) throw InputError(origin + ": no passing column (passing_fraction 0..1 or passing_pct 0..100, by mass)");
  if (table.rows.size() < 2) throw InputError(origin + ": a sieve curve needs at least two rows");
  SieveCurve curve;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const std::string where = origin + ":" + std::to_string(table.row_lines[r]) + ": ";
    const double d = table.number(r, size->index) * size->factor;
    const double f = table.number(r, passing->index) * passing->factor;
    if (!(d > 0)) throw InputError(where + "sieve size must be positive");
    if (!curve.d_m.empty() && !(d > curve.d_m.back()))
      throw InputError(where + "sieve sizes must increase strictly from row to row");
    if (f < 0 || f > 1) throw InputError(where + "passing fraction " + format_number(f) + " lies outside [0, 1]");
    if (!curve.passing.empty() && f < curve.passing.back())
      throw InputError(where + "passing fraction decreases (a cumulative curve cannot)");
    curve.d_m.push_back(d);
    curve.passing.push_back(f);
  }
  if (!(curve.passing.back() > curve.passing.front()))
    throw InputError(origin + ": no mass passes between the first and last sieve sizes");
  return curve;
}

SieveCurve parse_sieve_curve(const std::string& csv_text, const std::string& origin) {
  return curve_from_table(io::parse_csv(csv_text, origin));
}

SieveCurve read_sieve_curve(const std::filesystem::path& path) { return curve_from_table(io::read_csv(path)); }

SizeDistribution SizeDistribution::uniform(double d_min, double d_max) {
  require_positive("d_min", d_min / 1e-3, "mm");
  require_positive("d_max", d_max / 1e-3, "mm");
  if (d_min > d_max)
    throw InputError("d_min (" + format_quantity(d_min / 1e-3, "mm") + ") exceeds d_max (" +
                     format_quantity(d_max / 1e-3, "mm") + ")");
  SizeDistribution s;
  s.uniform_ = true;
  s.sizes_ = {d_min, d_max};
  s.volume_ = {0, 1};
  s.number_ = {0, 1};
  return s;
}

SizeDistribution SizeDistribution::sieve(const SieveCurve& curve, std::optional<double> d_min, std::optional<double> d_max) {
  if (curve.d_m.size() < 2 || curve.d_m.size() != curve.passing.size())
    throw InputError("a sieve curve needs at least two (size, passing) rows");
  const double lo = d_min.value_or(curve.d_m.front());
  const double hi = d_max.value_or(curve.d_m.back());
  if (!(lo > 0) || !(hi > 0)) throw InputError("sieve-curve size limits must be positive");
  if (lo < curve.d_m.front() || hi > curve.d_m.back())
    throw InputError("size limits [" + format_quantity(lo / 1e-3, "mm") + ", " + format_quantity(hi / 1e-3, "mm") +
                     "] reach outside the sieve curve [" + format_quantity(curve.d_m.front() / 1e-3, "mm") + ", " +
                     format_quantity(curve.d_m.back() / 1e-3, "mm") + "]");
  if (!(lo < hi))
    throw InputError("d_min (" + format_quantity(lo / 1e-3, "mm") + ") must be below d_max (" +
                     format_quantity(hi / 1e-3, "mm") + ") for a sieve curve");
  SizeDistribution s;
  s.uniform_ = false;
  s.sizes_.push_back(lo);
  for (double d : curve.d_m)
    if (d > lo && d < hi) s.sizes_.push_back(d);
  s.sizes_.push_back(hi);
  const double f_lo = interpolate(curve.d_m, curve.passing, lo), f_hi = interpolate(curve.d_m, curve.passing, hi);
  s.represented_ = f_hi - f_lo;
  if (!(s.represented_ > 0))
    throw InputError("the sieve curve holds no mass between " + format_quantity(lo / 1e-3, "mm") + " and " +
                     format_quantity(hi / 1e-3, "mm"));
  for (double d : s.sizes_) s.volume_.push_back((interpolate(curve.d_m, curve.passing, d) - f_lo) / s.represented_);
  s.volume_.back() = 1;
  // Number of spheres per interval: (dF/dd) * integral of d^-3 (see header).
  s.number_.push_back(0);
  for (std::size_t k = 0; k + 1 < s.sizes_.size(); ++k) {
    const double a = s.sizes_[k], b = s.sizes_[k + 1];
    const double c = (s.volume_[k + 1] - s.volume_[k]) / (b - a);
    s.number_.push_back(s.number_.back() + c * 0.5 * (1 / (a * a) - 1 / (b * b)));
  }
  const double total = s.number_.back();
  for (double& n : s.number_) n /= total;
  s.number_.back() = 1;
  return s;
}

double SizeDistribution::sample_diameter(Mt64Random& random) const {
  const double u = random.uniform01();
  if (uniform_) return sizes_[0] + (sizes_[1] - sizes_[0]) * u;
  // Inverse of the piecewise number CDF; within an interval n(d) ~ d^-3.
  auto k = std::size_t(std::upper_bound(number_.begin(), number_.end(), u) - number_.begin());
  k = std::clamp<std::size_t>(k, 1, sizes_.size() - 1) - 1;
  while (number_[k + 1] <= number_[k] && k + 2 < sizes_.size()) ++k;  // skip empty intervals
  const double a = sizes_[k], b = sizes_[k + 1];
  const double t = std::clamp((u - number_[k]) / (number_[k + 1] - number_[k]), 0.0, 1.0);
  const double inv_sq = 1 / (a * a) - t * (1 / (a * a) - 1 / (b * b));
  return std::clamp(1 / std::sqrt(inv_sq), a, b);
}

double SizeDistribution::number_cdf(double d) const {
  if (d <= sizes_.front()) return d < sizes_.front() ? 0.0 : (uniform_ && sizes_[0] == sizes_[1] ? 1.0 : 0.0);
  if (d >= sizes_.back()) return 1;
  if (uniform_) return (d - sizes_[0]) / (sizes_[1] - sizes_[0]);
  const auto k = std::size_t(std::upper_bound(sizes_.begin(), sizes_.end(), d) - sizes_.begin()) - 1;
  const double a = sizes_[k], b = sizes_[k + 1];
  const double span = 1 / (a * a) - 1 / (b * b);
  return number_[k] + (number_[k + 1] - number_[k]) * (1 / (a * a) - 1 / (d * d)) / span;
}

double SizeDistribution::volume_cdf(double d) const {
  if (d < sizes_.front()) return 0;
  if (d >= sizes_.back()) return 1;
  if (uniform_) {
    const double a = sizes_[0], b = sizes_[1];
    return (std::pow(d, 4) - std::pow(a, 4)) / (std::pow(b, 4) - std::pow(a, 4));
  }
  return interpolate(sizes_, volume_, d);
}

double SizeDistribution::mean_power(int k) const {
  if (k < 1 || k > 3) throw std::logic_error("mean_power: k must be 1, 2 or 3");
  if (uniform_) {
    const double a = sizes_[0], b = sizes_[1];
    if (a == b) return std::pow(a, k);
    return (std::pow(b, k + 1) - std::pow(a, k + 1)) / ((k + 1) * (b - a));
  }
  // Sum over intervals of c_k * integral d^(k-3) dd, divided by the number total.
  double moment = 0, count = 0;
  for (std::size_t i = 0; i + 1 < sizes_.size(); ++i) {
    const double a = sizes_[i], b = sizes_[i + 1];
    const double c = (volume_[i + 1] - volume_[i]) / (b - a);
    count += c * 0.5 * (1 / (a * a) - 1 / (b * b));
    if (k == 1) moment += c * (1 / a - 1 / b);
    else if (k == 2) moment += c * std::log(b / a);
    else moment += c * (b - a);
  }
  return moment / count;
}

double SizeDistribution::mean_sphere_volume() const { return std::numbers::pi / 6 * mean_power(3); }

std::string SizeDistribution::describe() const {
  if (uniform_)
    return "uniform by number in [" + format_number(sizes_.front() / 1e-3) + ", " + format_number(sizes_.back() / 1e-3) +
           "] mm";
  return "sieve curve (by mass) in [" + format_number(sizes_.front() / 1e-3) + ", " +
         format_number(sizes_.back() / 1e-3) + "] mm, " + std::to_string(sizes_.size() - 1) + " intervals";
}

std::vector<double> draw_diameters_for_volume(const SizeDistribution& sizes, double solid_volume, Mt64Random& random) {
  constexpr double sixth_pi = std::numbers::pi / 6;
  std::vector<double> d;
  d.reserve(std::size_t(solid_volume / sizes.mean_sphere_volume() * 1.01) + 16);
  double filled = 0;
  for (;;) {
    const double next = sizes.sample_diameter(random);
    const double v = sixth_pi * next * next * next;
    if (filled + v <= solid_volume) {
      d.push_back(next);
      filled += v;
      continue;
    }
    // Close the gap exactly: one sphere of the remaining volume if its size
    // is allowed, else the remainder is added to an earlier sphere that stays
    // within d_max (the last such one).
    const double rest = solid_volume - filled;
    const double d_rest = std::cbrt(rest / sixth_pi);
    if (d_rest >= sizes.d_min() && d_rest <= sizes.d_max()) {
      d.push_back(d_rest);
    } else {
      const double v_max = sixth_pi * sizes.d_max() * sizes.d_max() * sizes.d_max();
      for (std::size_t k = d.size(); k-- > 0;) {
        const double v = sixth_pi * d[k] * d[k] * d[k];
        if (v + rest <= v_max) {
          d[k] = std::min(sizes.d_max(), std::cbrt((v + rest) / sixth_pi));
          break;
        }
      }
    }
    return d;
  }
}

}  // namespace mesowave::dem
