#pragma once
// Sphere diameters: uniform between d_min and d_max (the concrete paper's
// 1.6-2.0 mm, Section 4.2; like Yade's makeCloud each sphere's diameter is
// drawn uniformly, so "uniform" is by NUMBER), or following a sieve curve.
//
// A sieve curve gives, for each sieve size d_k, the cumulative fraction
// passing F_k BY MASS - what a sieve analysis (e.g. EN 933-1) measures. With
// one particle density, mass fraction = volume fraction, so F is the volume
// CDF of the diameters. Between sieve sizes F is taken linear in d (the
// curve as it is usually drawn, linear interpolation of the table). The number
// density then follows as n(d) ~ F'(d) / d^3: in [d_k, d_k+1] the number of
// spheres is proportional to (F_k+1 - F_k)/(d_k+1 - d_k) * (d_k^-2 - d_k+1^-2)/2.
// A packing drawn from it and filled to a target solid VOLUME reproduces F.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/core/random.hpp"

namespace mesowave::dem {

/// Sieve analysis: sizes strictly increasing (m), passing fractions (by mass,
/// 0..1) non-decreasing.
struct SieveCurve {
  std::vector<double> d_m;
  std::vector<double> passing;
};

/// Reads a sieve curve from CSV: a size column `d_mm`, `d_m`, `d_um`,
/// `size_mm`, `size_m` or `size_um`, and a passing column `passing_fraction`
/// (0..1) or `passing_pct` (0..100), by mass. InputError (file and line) for a
/// missing column, sizes not positive and strictly increasing, fractions
/// outside [0, 1] or decreasing, fewer than two rows, or no mass between the
/// first and last sizes.
SieveCurve read_sieve_curve(const std::filesystem::path& path);
SieveCurve parse_sieve_curve(const std::string& csv_text, const std::string& origin);

class SizeDistribution {
public:
  /// Diameters uniform (by number) in [d_min, d_max]; d_min = d_max gives one size.
  static SizeDistribution uniform(double d_min_m, double d_max_m);
  /// Diameters whose volume CDF follows `curve`, cut to [d_min, d_max] when
  /// given (the curve is interpolated there) and renormalised over the range
  /// kept: F(d) = (F_curve(d) - F_curve(d_lo)) / (F_curve(d_hi) - F_curve(d_lo)).
  static SizeDistribution sieve(const SieveCurve& curve, std::optional<double> d_min_m = std::nullopt,
                                std::optional<double> d_max_m = std::nullopt);

  double d_min() const { return sizes_.front(); }
  double d_max() const { return sizes_.back(); }
  bool is_uniform() const { return uniform_; }
  /// Mass fraction of the sieve curve the distribution represents (1 for uniform).
  double represented_fraction() const { return represented_; }

  double sample_diameter(Mt64Random& random) const;

  /// Fraction of spheres, by number, with diameter <= d.
  double number_cdf(double d) const;
  /// Fraction of solid volume (= mass) in spheres with diameter <= d.
  double volume_cdf(double d) const;
  /// Mean of d^k over spheres (by number), k = 1, 2 or 3, in closed form.
  double mean_power(int k) const;
  /// Mean volume of one sphere, pi/6 E[d^3].
  double mean_sphere_volume() const;

  std::string describe() const;

private:
  bool uniform_ = true;
  double represented_ = 1;
  std::vector<double> sizes_;      // interval bounds
  std::vector<double> volume_;     // volume CDF at the bounds (0 .. 1)
  std::vector<double> number_;     // number CDF at the bounds (0 .. 1)
};

/// Diameters drawn one by one until their total volume reaches
/// `solid_volume_m3`: the draw that would overshoot is replaced by one sphere
/// of exactly the remaining volume when that size lies in [d_min, d_max];
/// otherwise the remainder is added to the last earlier sphere that can take
/// it without exceeding d_max. The total then equals the target to rounding
/// (it stays short by less than one smallest sphere only if no sphere can take
/// the remainder, or no sphere fits at all: an empty result).
std::vector<double> draw_diameters_for_volume(const SizeDistribution& sizes, double solid_volume_m3,
                                              Mt64Random& random);

}  // namespace mesowave::dem
