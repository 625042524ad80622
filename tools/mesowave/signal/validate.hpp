#pragma once
// The checks every analysis makes on its input, with one-line messages that
// name the record: "signal B: sample 1204 (t = 120.4 us) is NaN".
#include <cstddef>
#include <span>
#include <string_view>

#include "mesowave/signal/signal.hpp"

namespace mesowave::signal {

/// InputError unless `x` holds at least `min_count` samples, all finite.
void require_samples(std::span<const double> x, std::string_view what, std::size_t min_count = 1);

/// The same for a signal (named by its name), plus a positive finite dt_s and finite t0_s.
void require_valid(const Signal& s, std::size_t min_count = 1);

}  // namespace mesowave::signal
