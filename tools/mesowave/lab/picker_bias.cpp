// The picker table as measured, and what mw-upv states from it.
#include <algorithm>
#include <cmath>

#include "mesowave/core/format.hpp"
#include "mesowave/lab/picker_study.hpp"
#include "mesowave/signal/spectrum.hpp"

namespace mesowave::lab {

const std::vector<PickerBiasRow>& measured_picker_bias() {
  // `mw-pickers --table-cpp` with the default grid (PickerStudyGrid{}, 30 seeds
  // per point); docs/upv-pickers.md prints it and picker_study_test recomputes it.
  static const std::vector<PickerBiasRow> rows = {
#include "mesowave/lab/picker_bias_table.inc"
  };
  return rows;
}

namespace {

const char* table_source =
    "docs/upv-pickers.md, the picker table (mw-pickers: synthetic records, f 30-60 kHz, rise 1-2 periods, P precursor "
    "0.1-0.5, SNR 20-60 dB, 30 seeds per point; median and MAD of pick - true onset)";

}  // namespace

StatedBias state_pick_bias(const signal::Signal& record, const Onset& onset, const std::string& arrival,
                           const std::string& strategy) {
  StatedBias b;
  b.strategy = arrival + " " + strategy;
  b.snr_dB = onset.snr_dB;
  std::vector<const PickerBiasRow*> rows;
  for (const auto& r : measured_picker_bias())
    if (r.arrival == arrival && r.picker == strategy && r.records > r.refused) rows.push_back(&r);
  if (rows.empty()) return b;
  std::sort(rows.begin(), rows.end(), [](auto* x, auto* y) { return x->snr_dB < y->snr_dB; });
  b.measured = true;
  b.source = table_source;
  // Linear in SNR between the table's rows; the end rows outside them.
  const double snr = std::clamp(b.snr_dB, rows.front()->snr_dB, rows.back()->snr_dB);
  b.outside_grid = snr != b.snr_dB;
  std::size_t k = 0;
  while (k + 2 < rows.size() && rows[k + 1]->snr_dB < snr) ++k;
  const auto* lo = rows[k];
  const auto* hi = rows[std::min(k + 1, rows.size() - 1)];
  const double w = hi->snr_dB > lo->snr_dB ? (snr - lo->snr_dB) / (hi->snr_dB - lo->snr_dB) : 0.0;
  // An unflagged pick is held to the unflagged picks' statistics (where the
  // table has them at both rows).
  b.unflagged = !is_flagged(onset) && lo->records > lo->refused + lo->flagged && hi->records > hi->refused + hi->flagged;
  const auto median = [&](const PickerBiasRow* r) { return b.unflagged ? r->unflagged_median_periods : r->median_periods; };
  const auto mad = [&](const PickerBiasRow* r) { return b.unflagged ? r->unflagged_mad_periods : r->mad_periods; };
  b.median_periods = median(lo) + w * (median(hi) - median(lo));
  b.mad_periods = mad(lo) + w * (mad(hi) - mad(lo));

  // The record's own period: the spectrum peak over 200 us after the pick.
  const std::size_t first = onset.pick.index;
  const std::size_t count = std::min(record.size() - std::min(first, record.size()),
                                     std::size_t(std::llround(200e-6 / record.dt_s)));
  if (count >= 16) {
    signal::SpectrumOptions o;
    o.detrend = signal::Detrend::mean;
    o.padding = signal::Padding{signal::Padding::Mode::to_length, std::max<std::size_t>(4 * count, 4096)};
    const auto spectrum = signal::amplitude_spectrum(
        std::span<const double>(record.samples.data() + first, count), record.dt_s, o);
    b.frequency_Hz = signal::peak_frequency_hz(spectrum, 5e3);  // above the offset's leakage
    b.median_s = b.median_periods / b.frequency_Hz;
    b.mad_s = b.mad_periods / b.frequency_Hz;
  }
  return b;
}

void describe_bias(nlohmann::ordered_json& j, const std::string& k, const StatedBias& b) {
  j[k + "_pick_snr_dB"] = b.snr_dB;
  if (!b.measured) {
    j[k + "_pick_bias"] = "not measured: " + b.strategy + " is not in docs/upv-pickers.md's picker table";
    return;
  }
  j[k + "_pick_bias_periods"] = b.median_periods;
  j[k + "_pick_bias_mad_periods"] = b.mad_periods;
  if (b.frequency_Hz > 0) {
    j[k + "_pick_frequency_kHz"] = b.frequency_Hz / 1e3;
    j[k + "_pick_bias_us"] = b.median_s * 1e6;
    j[k + "_pick_bias_mad_us"] = b.mad_s * 1e6;
  }
  j[k + "_pick_bias_source"] = std::string(table_source) + "; " + b.strategy + " at " + format_fixed(b.snr_dB, 1) +
                               " dB, " + (b.unflagged ? "unflagged picks" : "all picks (this one is flagged)") +
                               (b.outside_grid ? " (outside the table's SNR range: its end row)" : "") +
                               "; the remaining bias, not subtracted from " + k + "_us";
}

}  // namespace mesowave::lab
