#pragma once
// Argument checks that produce the project's one-line error messages, e.g.
//   mass_g (-3 g) must be positive and finite
#include <cmath>
#include <string>
#include <string_view>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave {

/// Throws InputError unless `value` is finite and > 0. `unit` is only used to
/// show the value as the user gave it ("35 us").
inline double require_positive(std::string_view name, double value, std::string_view unit = "") {
  if (!std::isfinite(value) || value <= 0.0)
    throw InputError(std::string(name) + " (" + format_quantity(value, unit) +
                     ") must be positive and finite");
  return value;
}

/// Throws InputError unless `value` is finite.
inline double require_finite(std::string_view name, double value, std::string_view unit = "") {
  if (!std::isfinite(value))
    throw InputError(std::string(name) + " (" + format_quantity(value, unit) + ") must be finite");
  return value;
}

/// Throws InputError unless lo <= value <= hi (both finite).
inline double require_in_range(std::string_view name, double value, double lo, double hi,
                               std::string_view unit = "") {
  if (!std::isfinite(value) || value < lo || value > hi)
    throw InputError(std::string(name) + " (" + format_quantity(value, unit) + ") must lie in [" +
                     format_number(lo) + ", " + format_number(hi) + "]" +
                     (unit.empty() ? "" : " " + std::string(unit)));
  return value;
}

}  // namespace mesowave
