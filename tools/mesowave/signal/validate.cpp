#include "mesowave/signal/validate.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::signal {
namespace {

void check(std::span<const double> x, std::string_view what, std::size_t min_count, const Signal* s) {
  if (x.size() < min_count) {
    if (x.empty()) throw InputError(std::string(what) + " is empty (no samples)");
    throw InputError(std::string(what) + " has " + std::to_string(x.size()) + " sample" + (x.size() == 1 ? "" : "s") +
                     ", needs at least " + std::to_string(min_count));
  }
  // Non-finite doubles have every exponent bit set; an OR over the records
  // vectorises, the loop that names the culprit runs only when there is one.
  std::uint64_t bad = 0;
  for (double v : x) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    bad |= std::uint64_t((bits & 0x7ff0000000000000u) == 0x7ff0000000000000u);
  }
  if (!bad) return;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i])) {
      std::string where = "sample " + std::to_string(i);
      if (s) where += " (t = " + format_number(s->time(i) * 1e6) + " us)";
      throw InputError(std::string(what) + ": " + where + " is " + (std::isnan(x[i]) ? "NaN" : "infinite"));
    }
}

}  // namespace

void require_samples(std::span<const double> x, std::string_view what, std::size_t min_count) {
  check(x, what, min_count, nullptr);
}

void require_valid(const Signal& s, std::size_t min_count) {
  const std::string what = "signal " + (s.name.empty() ? std::string("(unnamed)") : s.name);
  if (!std::isfinite(s.dt_s) || s.dt_s <= 0)
    throw InputError(what + ": sampling interval dt_s (" + format_number(s.dt_s) + " s) must be positive and finite");
  if (!std::isfinite(s.t0_s)) throw InputError(what + ": start time t0_s is not finite");
  check(s.samples, what, min_count, &s);
}

}  // namespace mesowave::signal
