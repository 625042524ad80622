#pragma once
// Entry points for the library's own hot loops, past the checks the public
// functions make (the caller has validated the records once).
#include <span>
#include <string_view>

#include "mesowave/signal/envelope.hpp"

namespace mesowave::signal::internal {

/// envelope_into without the finite-sample check.
void envelope_into_unchecked(std::span<const double> x, std::span<double> out, const HilbertOptions& options);

/// pearson for finite records of equal, non-zero length.
double pearson_unchecked(std::span<const double> a, std::span<const double> b, std::string_view what);

}  // namespace mesowave::signal::internal
