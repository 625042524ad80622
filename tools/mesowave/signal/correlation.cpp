#include "mesowave/signal/correlation.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <set>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/signal/internal.hpp"
#include "mesowave/signal/validate.hpp"

namespace mesowave::signal {
namespace {

double mean_of(std::span<const double> x) { return internal::sum4(x) / double(x.size()); }

// A record is constant when its spread is below the rounding of its values;
// its "variance" is then noise from the mean's rounding and r meaningless.
// Since max |x| <= sqrt(ss) + |mean|, most records pass without a scan.
bool constant(std::span<const double> x, double mean, double ss) {
  const double rms = std::sqrt(ss / double(x.size()));
  if (rms > 1e-13 * (std::sqrt(ss) + std::abs(mean))) return false;
  double peak = 0;
  for (double v : x) peak = std::max(peak, std::abs(v));
  return !(rms > 1e-13 * peak);
}

std::size_t offset_in(const TimeBase& outer, const TimeBase& inner) {
  return std::size_t(std::llround((inner.t0_s - outer.t0_s) / outer.dt_s));
}

}  // namespace

double internal::pearson_unchecked(std::span<const double> a, std::span<const double> b, std::string_view what) {
  // Two passes (means, then centred sums): the one-pass formula cancels
  // catastrophically for a signal riding on an offset.
  const double ma = mean_of(a), mb = mean_of(b);
  double saa = 0, sbb = 0, sab = 0;
  internal::centred_sums(a, b, ma, mb, saa, sbb, sab);
  const std::string w(what);
  if (constant(a, ma, saa)) throw InputError(w + ": the first record has zero variance (constant), r is undefined");
  if (constant(b, mb, sbb)) throw InputError(w + ": the second record has zero variance (constant), r is undefined");
  return std::clamp(sab / std::sqrt(saa * sbb), -1.0, 1.0);  // |r| <= 1 up to rounding
}

double pearson(std::span<const double> a, std::span<const double> b, std::string_view what) {
  const std::string w(what);
  if (a.empty() || b.empty()) throw InputError(w + ": cannot correlate an empty record");
  if (a.size() != b.size())
    throw InputError(w + ": unequal lengths (" + std::to_string(a.size()) + " and " + std::to_string(b.size()) +
                     " samples)");
  require_samples(a, w + " (first)");
  require_samples(b, w + " (second)");
  return internal::pearson_unchecked(a, b, what);
}

SensorCorrelation correlate(const Signal& a, const Signal& b, const CorrelationOptions& options) {
  require_valid(a);
  require_valid(b);
  const std::string what = a.name == b.name ? "sensor " + a.name : "signals " + a.name + " and " + b.name;
  const TimeBase ta = time_base(a), tb = time_base(b);

  TimeBase common = ta;
  std::span<const double> xa = a.samples, xb = b.samples;
  std::vector<double> b_resampled;
  bool resampled = false;
  if (same_time_base(ta, tb)) {
    // compared as they are
  } else if (!options.resampling) {
    const bool same_sampling = std::abs(ta.dt_s - tb.dt_s) <= 1e-9 * ta.dt_s &&
                               std::abs(ta.t0_s - tb.t0_s) <= 1e-6 * ta.dt_s;
    if (same_sampling)
      throw InputError(what + ": unequal lengths (" + std::to_string(ta.count) + " and " + std::to_string(tb.count) +
                       " samples on the same sampling); cut both to a common window or resample explicitly");
    throw InputError(what + ": different time bases (" + describe(ta) + " vs " + describe(tb) +
                     "); ask for a resampling (mw-pcc --resample linear|cubic) to interpolate one onto the other");
  } else {
    common = restrict_time_base(ta, std::max(ta.t0_s, tb.t0_s), std::min(ta.end_s(), tb.end_s()),
                                what + ": the records do not overlap in time");
    xa = xa.subspan(offset_in(ta, common), common.count);
    b_resampled = resample(b, common, *options.resampling).samples;
    xb = b_resampled;
    resampled = true;
  }

  // Envelopes in per-thread scratch (slots 10 and 11, see ScratchBuffer).
  ScratchBuffer<double> env_a(10, xa.size()), env_b(11, xb.size());
  const std::span<const double> ea(env_a.data(), xa.size()), eb(env_b.data(), xb.size());
  SensorCorrelation c;
  if (options.spectra) {
    internal::envelope_and_spectrum_unchecked(xa, std::span<double>(env_a.data(), xa.size()), options.envelope,
                                              common.dt_s, *options.spectra, c.spectrum_a);
    internal::envelope_and_spectrum_unchecked(xb, std::span<double>(env_b.data(), xb.size()), options.envelope,
                                              common.dt_s, *options.spectra, c.spectrum_b);
  } else {
    internal::envelope_into_unchecked(xa, std::span<double>(env_a.data(), xa.size()), options.envelope);
    internal::envelope_into_unchecked(xb, std::span<double>(env_b.data(), xb.size()), options.envelope);
  }

  TimeBase window = common;
  if (options.begin_s || options.end_s)
    window = restrict_time_base(common, options.begin_s.value_or(common.t0_s), options.end_s.value_or(common.end_s()),
                                what + ": the comparison window");
  const std::size_t first = offset_in(common, window), count = window.count;

  c.sensor = a.name;
  c.compared = window;
  c.envelope_samples = common.count;
  c.resampled = resampled;
  c.pcc_signal = internal::pearson_unchecked(xa.subspan(first, count), xb.subspan(first, count), what);
  c.pcc_envelope = internal::pearson_unchecked(ea.subspan(first, count), eb.subspan(first, count), what + " (envelopes)");
  return c;
}

CorrelationTable correlate_sensors(std::span<const Signal> a, std::span<const Signal> b,
                                   const CorrelationOptions& options, const std::vector<std::string>& only) {
  auto index = [](std::span<const Signal> set, const char* label) {
    std::map<std::string, std::size_t> names;
    for (std::size_t i = 0; i < set.size(); ++i)
      if (!names.emplace(set[i].name, i).second)
        throw InputError("sensor '" + set[i].name + "' appears twice in the " + label + " set");
    return names;
  };
  const auto in_a = index(a, "first"), in_b = index(b, "second");

  CorrelationTable table;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  if (!only.empty()) {
    std::set<std::string> seen;
    for (const auto& name : only) {
      if (!seen.insert(name).second) throw InputError("sensor '" + name + "' is named twice");
      auto ia = in_a.find(name), ib = in_b.find(name);
      if (ia == in_a.end()) throw InputError("sensor '" + name + "' is not in the first set");
      if (ib == in_b.end()) throw InputError("sensor '" + name + "' is not in the second set");
      pairs.emplace_back(ia->second, ib->second);
    }
  } else {
    for (const auto& s : a) {
      auto ib = in_b.find(s.name);
      if (s.name == kExcitationName && ib != in_b.end()) {
        table.excitation_left_out = true;
        continue;
      }
      if (ib == in_b.end()) table.only_in_a.push_back(s.name);
      else pairs.emplace_back(in_a.at(s.name), ib->second);
    }
    for (const auto& s : b)
      if (!in_a.count(s.name)) table.only_in_b.push_back(s.name);
  }
  if (pairs.empty()) throw InputError("the two sets share no sensor name, nothing to correlate");

  // Each pair is independent; errors are collected per pair so that the
  // first one in sensor order is reported, whatever the threads did.
  table.sensors.resize(pairs.size());
  std::vector<std::exception_ptr> errors(pairs.size());
#pragma omp parallel for schedule(dynamic)
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    try {
      table.sensors[i] = correlate(a[pairs[i].first], b[pairs[i].second], options);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  }
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);

  for (const auto& s : table.sensors) {
    table.mean_pcc_signal += s.pcc_signal;
    table.mean_pcc_envelope += s.pcc_envelope;
  }
  table.mean_pcc_signal /= double(table.sensors.size());
  table.mean_pcc_envelope /= double(table.sensors.size());

  const auto resampled = std::count_if(table.sensors.begin(), table.sensors.end(), [](auto& s) { return s.resampled; });
  if (resampled == 0)
    table.resampling = "none (same time base)";
  else
    table.resampling = "second set onto the first's samples by " + std::string(to_string(*options.resampling)) +
                       " interpolation (" + std::to_string(resampled) + " of " + std::to_string(table.sensors.size()) +
                       " sensors)";
  table.envelope_method = options.envelope.describe(table.sensors.front().envelope_samples);
  return table;
}

}  // namespace mesowave::signal
