#include "mesowave/lab/picker_study.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/gnuplot.hpp"
#include "mesowave/lab/transducer_record.hpp"
#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/noise.hpp"
#include "mesowave/signal/spectrum.hpp"

namespace mesowave::lab {

namespace {

Onset with_picker(const signal::Signal& record, const std::string& picker) {
  OnsetOptions o;  // mw-upv's defaults (lab::UpvMeasurement)
  o.picker = picker;
  return pick_onset(record, o);
}

Onset after_p(const UpvRecordPair& r, const std::string& picker) {
  const double t_p = with_picker(r.p_channel, "aic").pick.time_s;  // mw-upv picks t_p first, by its default
  OnsetOptions o = shear_wave_options(OnsetOptions{}, t_p, 0.0);
  o.picker = picker;
  return pick_onset(r.s_channel, o);
}

// mw-upv --s-wavelet: the matched filter in mw-upv's S window with the transducer response.
Onset xcorr_after_p(const UpvRecordPair& r) {
  const double t_p = with_picker(r.p_channel, "aic").pick.time_s;
  OnsetOptions o = shear_wave_options(OnsetOptions{}, t_p, 0.0);
  o.picker = "xcorr";
  o.wavelet = r.s_wavelet;
  return pick_onset(r.s_channel, o);
}

// AIC on the envelope rather than the record, in mw-upv's S window: the
// envelope's second rise, where the S energy adds to the P precursor's.
Onset envelope_aic_after_p(const UpvRecordPair& r) {
  Onset located = after_p(r, "envelope-peak");
  const auto e = signal::envelope(r.s_channel, signal::HilbertOptions{signal::Detrend::mean,
                                                                       signal::Padding{signal::Padding::Mode::double_length, 0}});
  signal::AicOptions aic;
  aic.search = {located.search_begin_s, located.locator.time_s};
  located.pick = signal::aic_pick(e, aic);
  located.warnings.clear();
  return located;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  // Linear interpolation between order statistics (Hyndman-Fan type 7).
  const double h = q * double(v.size() - 1);
  const auto lo = std::size_t(std::floor(h));
  const auto hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (h - double(lo)) * (v[hi] - v[lo]);
}

// Median, MAD and 90th percentile of |error| of `errors`.
std::array<double, 3> statistics(const std::vector<double>& errors) {
  const double median = quantile(errors, 0.5);
  std::vector<double> dev, absolute;
  for (double e : errors) dev.push_back(std::abs(e - median)), absolute.push_back(std::abs(e));
  return {median, quantile(dev, 0.5), quantile(absolute, 0.9)};
}

// Errors of the picks in order, and which of them carried a warning.
struct Errors {
  std::vector<double> all, unflagged;
  void insert(const Errors& e) {
    all.insert(all.end(), e.all.begin(), e.all.end());
    unflagged.insert(unflagged.end(), e.unflagged.begin(), e.unflagged.end());
  }
};

void fill_statistics(PickerBiasRow& row, const Errors& errors) {
  const auto a = statistics(errors.all);
  row.median_periods = a[0], row.mad_periods = a[1], row.p90_abs_periods = a[2];
  const auto u = statistics(errors.unflagged);
  row.unflagged_median_periods = u[0], row.unflagged_mad_periods = u[1], row.unflagged_p90_abs_periods = u[2];
}

}  // namespace

bool is_flagged(const Onset& onset) {
  // The envelope-peak picker always says that it gives the group arrival; that is not a flag.
  return std::any_of(onset.warnings.begin(), onset.warnings.end(),
                     [](const std::string& w) { return w.find("group arrival") == std::string::npos; });
}

UpvRecordPair study_record_pair(const PickerStudyGrid& grid, double f, double rise, double fraction, double snr,
                                std::uint64_t seed, double slow_rise) {
  TransducerRecordSpec spec;
  spec.frequency_Hz = f;
  spec.rise_periods = rise;
  spec.snr_dB = snr;
  UpvRecordPair pair;
  pair.t_p_s = grid.t_p_s;
  pair.t_s_s = grid.t_s_s;
  spec.onset_s = grid.t_p_s;
  spec.seed = 2 * seed - 1;
  pair.p_channel = transducer_record(spec);
  pair.p_channel.name = "P channel";
  spec.onset_s = grid.t_s_s;
  spec.precursor_onset_s = grid.t_p_s;
  spec.precursor_fraction = fraction;
  spec.seed = 2 * seed;
  spec.slow_rise_fraction = slow_rise;
  pair.s_channel = transducer_record(spec);
  pair.s_channel.name = "S channel";
  const double a = transducer_decay_rate(f, rise);
  pair.s_wavelet = pair.s_channel;
  pair.s_wavelet.name = "S wavelet";
  pair.s_wavelet.t0_s = 0;
  pair.s_wavelet.samples.clear();
  for (double t = 0; t <= (4 * rise + 1) / f; t += spec.sample_interval_s)
    pair.s_wavelet.samples.push_back(transducer_response(t, f, a));
  return pair;
}

const std::vector<PickerStrategy>& picker_strategies() {
  static const std::vector<PickerStrategy> strategies = [] {
    std::vector<PickerStrategy> s;
    for (const std::string picker : {"threshold", "aic", "envelope-peak"}) {
      s.push_back({"P", picker, "mw-upv's P chain with --picker " + picker + " on the P channel",
                   [picker](const UpvRecordPair& r) { return with_picker(r.p_channel, picker); }});
    }
    // mw-upv --aic-after-us 30: its arrival check and AIC window one period of
    // 33 kHz long instead of 10 us (a third of a period at 30 kHz).
    s.push_back({"P", "aic-window-30us", "mw-upv's P chain with --aic-after-us 30",
                 [](const UpvRecordPair& r) {
                   OnsetOptions o;
                   o.aic_after_s = 30e-6;
                   return pick_onset(r.p_channel, o);
                 }});
    for (const std::string picker : {"threshold", "aic", "envelope-peak"}) {
      s.push_back({"S", picker, "the P chain with --picker " + picker + " on the S channel (no t_p known)",
                   [picker](const UpvRecordPair& r) { return with_picker(r.s_channel, picker); }});
    }
    s.push_back({"S", "aic-after-p", "mw-upv's S chain: AIC from 1.3 t_p to the envelope peak in 1.3-3.5 t_p",
                 [](const UpvRecordPair& r) { return after_p(r, "aic"); }});
    s.push_back({"S", "envelope-peak-after-p", "the envelope peak in 1.3-3.5 t_p (the S group arrival)",
                 [](const UpvRecordPair& r) { return after_p(r, "envelope-peak"); }});
    s.push_back({"S", "envelope-aic-after-p", "AIC on the envelope in mw-upv's S window (the envelope's second rise)",
                 [](const UpvRecordPair& r) { return envelope_aic_after_p(r); }});
    s.push_back({"S", "xcorr-after-p", "the matched filter with the transducer response in mw-upv's S window (--s-wavelet)",
                 [](const UpvRecordPair& r) { return xcorr_after_p(r); }});
    return s;
  }();
  return strategies;
}

PickerStudy run_picker_study(const PickerStudyGrid& grid) {
  if (grid.seeds < 1 || grid.seeds > 999) throw InputError("picker study: seeds must be 1 .. 999");
  const auto& strategies = picker_strategies();
  struct Point {
    double f, rise, fraction, snr, slow = 0;
  };
  if (std::find(grid.slow_rise_fraction.begin(), grid.slow_rise_fraction.end(), 0.0) == grid.slow_rise_fraction.end())
    throw InputError("picker study: the slow-rise fractions must include 0 (the pooled rows' records)");
  // Slow rise outermost, 0 first: the points without one come in the order they had before it existed.
  std::vector<double> slows{0.0};
  for (double v : grid.slow_rise_fraction)
    if (v != 0 && std::find(slows.begin(), slows.end(), v) == slows.end()) slows.push_back(v);
  std::vector<Point> points;
  for (double slow : slows)
    for (double snr : grid.snr_dB)
      for (double f : grid.frequency_Hz)
        for (double rise : grid.rise_periods)
          for (double fraction : grid.precursor_fraction) points.push_back({f, rise, fraction, snr, slow});

  // Bad grid values are refused here, before the parallel loop (an exception
  // must not leave an OpenMP region).
  for (const auto& p : points) study_record_pair(grid, p.f, p.rise, p.fraction, p.snr, 1, p.slow);
  // errors[point][strategy]: one slot each, filled in any order, read in order.
  std::vector<std::vector<Errors>> errors(points.size(), std::vector<Errors>(strategies.size()));
  std::vector<std::vector<PickerBiasRow>> cells(points.size(), std::vector<PickerBiasRow>(strategies.size()));
#pragma omp parallel for schedule(dynamic)
  for (std::ptrdiff_t c = 0; c < std::ptrdiff_t(points.size()); ++c) {
    const auto& p = points[std::size_t(c)];
    for (std::size_t k = 0; k < strategies.size(); ++k) {
      auto& row = cells[std::size_t(c)][k];
      row.arrival = strategies[k].arrival, row.picker = strategies[k].name;
      row.snr_dB = p.snr, row.frequency_Hz = p.f, row.rise_periods = p.rise, row.precursor_fraction = p.fraction;
      row.slow_rise_fraction = p.slow;
    }
    for (std::size_t i = 0; i < grid.seeds; ++i) {
      // The seed follows from the point's values, not its place in the grid,
      // so that a smaller grid reproduces the larger one's records.
      const std::uint64_t point_key = std::uint64_t(std::llround(p.f / 100)) * 1000003u +
                                      std::uint64_t(std::llround(p.rise * 100)) * 10007u +
                                      std::uint64_t(std::llround(p.fraction * 100)) * 101u +
                                      std::uint64_t(std::llround(p.snr)) +
                                      std::uint64_t(std::llround(p.slow * 1000)) * 100000007u;  // 0: the seeds before it
      const std::uint64_t seed = point_key * 1000u + i + 1;
      const auto pair = study_record_pair(grid, p.f, p.rise, p.fraction, p.snr, seed, p.slow);
      for (std::size_t k = 0; k < strategies.size(); ++k) {
        if (p.slow != 0 && strategies[k].arrival == "P") continue;  // the P channel has no slow rise
        auto& row = cells[std::size_t(c)][k];
        ++row.records;
        try {
          const Onset onset = strategies[k].pick(pair);
          const bool flagged = is_flagged(onset);
          row.flagged += flagged;
          const double truth = strategies[k].arrival == "P" ? pair.t_p_s : pair.t_s_s;
          const double error = (onset.pick.time_s - truth) * p.f;
          errors[std::size_t(c)][k].all.push_back(error);
          if (!flagged) errors[std::size_t(c)][k].unflagged.push_back(error);
        } catch (const InputError& e) {
          if (!row.refused++) row.first_refusal = e.what();
        }
      }
    }
    for (std::size_t k = 0; k < strategies.size(); ++k) fill_statistics(cells[std::size_t(c)][k], errors[std::size_t(c)][k]);
  }

  PickerStudy study;
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (std::size_t k = 0; k < strategies.size(); ++k)
      if (points[c].slow == 0 || strategies[k].arrival != "P") study.cells.push_back(cells[c][k]);
  // Pools strategy k over the grid points at key's SNR and slow rise (and precursor fraction).
  const auto pool = [&](std::size_t k, const Point& key, bool by_fraction) {
    PickerBiasRow row;
    row.arrival = strategies[k].arrival, row.picker = strategies[k].name, row.snr_dB = key.snr;
    row.slow_rise_fraction = key.slow;
    if (by_fraction) row.precursor_fraction = key.fraction;
    Errors pooled;
    for (std::size_t c = 0; c < points.size(); ++c) {
      if (points[c].snr != key.snr || points[c].slow != key.slow || (by_fraction && points[c].fraction != key.fraction))
        continue;
      row.records += cells[c][k].records;
      row.refused += cells[c][k].refused;
      row.flagged += cells[c][k].flagged;
      if (row.first_refusal.empty()) row.first_refusal = cells[c][k].first_refusal;
      pooled.insert(errors[c][k]);
    }
    fill_statistics(row, pooled);
    return row;
  };
  for (std::size_t k = 0; k < strategies.size(); ++k)
    for (double snr : grid.snr_dB) {
      study.pooled.push_back(pool(k, Point{0, 0, 0, snr}, false));
      for (double fraction : grid.precursor_fraction)
        study.by_fraction.push_back(pool(k, Point{0, 0, fraction, snr}, true));
    }
  for (std::size_t k = 0; k < strategies.size(); ++k)
    if (strategies[k].arrival == "S")
      for (double snr : grid.snr_dB)
        for (double slow : slows) study.by_slow_rise.push_back(pool(k, Point{0, 0, 0, snr, slow}, false));
  return study;
}

namespace {

// The noiseless pair of one calibration (the noise is added per seed: the same samples as
// point_force_record with that SNR and seed, which adds it to the normalised record).
UpvRecordPair clean_point_force_pair(int calibration) {
  // Continuum speeds of docs/cube-150.md's two calibrations: v_p = sqrt(M / rho), v_s = sqrt(G / rho).
  const double E = calibration == 0 ? 27.413e9 : 36.671e9, nu = calibration == 0 ? 0.16001 : 0.1618, rho = 2129.56;
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  PointForceRecordSpec spec;
  spec.p_speed_m_s = std::sqrt(M / rho);
  spec.s_speed_m_s = std::sqrt(G / rho);
  spec.snr_dB = std::numeric_limits<double>::infinity();
  UpvRecordPair pair;
  pair.t_p_s = spec.distance_m / spec.p_speed_m_s;
  pair.t_s_s = spec.distance_m / spec.s_speed_m_s;
  spec.axial = true;
  spec.frequency_Hz = 162e3;  // upv50-p.toml
  pair.p_channel = point_force_record(spec);
  pair.p_channel.name = "P channel";
  spec.axial = false;
  spec.frequency_Hz = 120e3;  // upv50-s.toml
  pair.s_channel = point_force_record(spec);
  pair.s_channel.name = "S channel";
  pair.s_wavelet = burst_wavelet(120e3, 2, true, spec.sample_interval_s);
  return pair;
}

}  // namespace

UpvRecordPair point_force_pair(int calibration, double snr, std::uint64_t seed) {
  if (calibration != 0 && calibration != 1) throw InputError("point-force pair: calibration is 0 (static) or 1 (dynamic)");
  static const std::array<UpvRecordPair, 2> clean{clean_point_force_pair(0), clean_point_force_pair(1)};
  UpvRecordPair pair = clean[std::size_t(calibration)];
  const double rms = std::pow(10.0, -snr / 20);
  for (auto [record, s] : {std::pair{&pair.p_channel, 2 * seed - 1}, std::pair{&pair.s_channel, 2 * seed}}) {
    const auto noise = signal::gaussian_noise(record->size(), rms, s);
    for (std::size_t i = 0; i < record->size(); ++i) record->samples[i] += noise[i];
  }
  return pair;
}

std::vector<PickerBiasRow> run_point_force_study(const std::vector<double>& snr_dB, std::size_t seeds) {
  if (seeds < 1 || seeds > 999) throw InputError("point-force study: seeds must be 1 .. 999");
  const auto& strategies = picker_strategies();
  std::vector<std::size_t> s_strategies;
  for (std::size_t k = 0; k < strategies.size(); ++k)
    if (strategies[k].arrival == "S") s_strategies.push_back(k);
  const std::size_t per_snr = 2 * seeds;
  // errors[snr][record][strategy], refused/flagged marks; filled in any order, read in order.
  struct Slot {
    bool picked = false, flagged = false;
    double error = 0;
    std::string refusal;
  };
  std::vector<std::vector<Slot>> slots(snr_dB.size() * per_snr, std::vector<Slot>(s_strategies.size()));
#pragma omp parallel for schedule(dynamic)
  for (std::ptrdiff_t j = 0; j < std::ptrdiff_t(slots.size()); ++j) {
    const std::size_t q = std::size_t(j) / per_snr, m = std::size_t(j) % per_snr;
    const int calibration = int(m / seeds);
    const std::uint64_t seed = (std::uint64_t(std::llround(snr_dB[q])) * 10 + std::uint64_t(calibration)) * 1000u + m % seeds + 1;
    const auto pair = point_force_pair(calibration, snr_dB[q], seed);
    for (std::size_t k = 0; k < s_strategies.size(); ++k) {
      auto& slot = slots[std::size_t(j)][k];
      try {
        const Onset onset = strategies[s_strategies[k]].pick(pair);
        slot.picked = true;
        slot.flagged = is_flagged(onset);
        slot.error = (onset.pick.time_s - pair.t_s_s) * 120e3;
      } catch (const InputError& e) {
        slot.refusal = e.what();
      }
    }
  }
  std::vector<PickerBiasRow> rows;
  for (std::size_t k = 0; k < s_strategies.size(); ++k)
    for (std::size_t q = 0; q < snr_dB.size(); ++q) {
      PickerBiasRow row;
      row.arrival = "S", row.picker = strategies[s_strategies[k]].name, row.snr_dB = snr_dB[q], row.frequency_Hz = 120e3;
      Errors errors;
      for (std::size_t m = 0; m < per_snr; ++m) {
        const auto& slot = slots[q * per_snr + m][k];
        ++row.records;
        if (!slot.picked) {
          if (!row.refused++) row.first_refusal = slot.refusal;
          continue;
        }
        row.flagged += slot.flagged;
        errors.all.push_back(slot.error);
        if (!slot.flagged) errors.unflagged.push_back(slot.error);
      }
      fill_statistics(row, errors);
      rows.push_back(row);
    }
  return rows;
}

std::string picker_bias_markdown(const std::vector<PickerBiasRow>& rows) {
  const bool fractions = std::any_of(rows.begin(), rows.end(), [](const auto& r) { return r.precursor_fraction > 0; });
  const bool slow = std::any_of(rows.begin(), rows.end(), [](const auto& r) { return r.slow_rise_fraction > 0; });
  std::string s = std::string("| arrival | picker | SNR [dB] |") + (fractions ? " precursor |" : "") +
                  (slow ? " slow rise |" : "") +
                  " records | refused | flagged | median [periods] | MAD [periods] | p90 abs [periods] |"
                  " unflagged: median | MAD | p90 abs |\n" +
                  "|---|---|---|" + (fractions ? "---|" : "") + (slow ? "---|" : "") +
                  "---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    s += "| " + r.arrival + " | " + r.picker + " | " + format_fixed(r.snr_dB, 0) + " | ";
    if (fractions) s += format_fixed(r.precursor_fraction, 1) + " | ";
    if (slow) s += format_fixed(r.slow_rise_fraction, 2) + " | ";
    s += std::to_string(r.records) + " | " + std::to_string(r.refused) + " | " + std::to_string(r.flagged) + " | ";
    s += r.records > r.refused ? format_fixed(r.median_periods, 3) + " | " + format_fixed(r.mad_periods, 3) + " | " +
                                     format_fixed(r.p90_abs_periods, 3) + " | "
                               : "- | - | - | ";
    s += r.records > r.refused + r.flagged
             ? format_fixed(r.unflagged_median_periods, 3) + " | " + format_fixed(r.unflagged_mad_periods, 3) + " | " +
                   format_fixed(r.unflagged_p90_abs_periods, 3) + " |\n"
             : "- | - | - |\n";
  }
  return s;
}

std::string picker_bias_csv(const std::vector<PickerBiasRow>& rows) {
  std::vector<std::vector<std::string>> out;
  for (const auto& r : rows)
    out.push_back({r.arrival, r.picker, format_fixed(r.snr_dB, 1), format_fixed(r.frequency_Hz / 1e3, 1),
                   format_fixed(r.rise_periods, 2), format_fixed(r.precursor_fraction, 2),
                   format_fixed(r.slow_rise_fraction, 2), std::to_string(r.records),
                   std::to_string(r.refused), std::to_string(r.flagged), format_fixed(r.median_periods, 4),
                   format_fixed(r.mad_periods, 4), format_fixed(r.p90_abs_periods, 4),
                   format_fixed(r.unflagged_median_periods, 4), format_fixed(r.unflagged_mad_periods, 4),
                   format_fixed(r.unflagged_p90_abs_periods, 4), r.first_refusal});
  return io::to_csv({"arrival", "picker", "snr_dB", "frequency_kHz", "rise_periods", "precursor_fraction",
                     "slow_rise_fraction", "records",
                     "refused", "flagged", "median_error_periods", "mad_error_periods", "p90_abs_error_periods", "unflagged_median_error_periods",
                     "unflagged_mad_error_periods", "unflagged_p90_abs_error_periods", "first_refusal"},
                    out);
}

std::string picker_example_figure_script(const UpvRecordPair& pair, const std::filesystem::path& png,
                                         const std::string& title) {
  const double t_lo = -10e-6, t_hi = 4 * pair.t_s_s;
  std::string s = "set terminal pngcairo size 1200,700 font 'Sans,11'\nset output " + io::gnuplot_quote(png) + "\n";
  std::string plots, marks;
  const char* colours[] = {"#1f77b4", "#2ca02c", "#9467bd", "#d62728", "#ff7f0e", "#8c564b", "#e377c2"};
  std::size_t colour = 0;
  for (const auto& [arrival, record, offset] : {std::tuple{"P", &pair.p_channel, 0.0}, std::tuple{"S", &pair.s_channel, -2.6}}) {
    double peak = 0;
    std::vector<double> t, v;
    for (std::size_t i = 0; i < record->size(); ++i)
      if (record->time(i) >= t_lo && record->time(i) <= t_hi) peak = std::max(peak, std::abs(record->samples[i]));
    for (std::size_t i = 0; i < record->size(); ++i)
      if (record->time(i) >= t_lo && record->time(i) <= t_hi) {
        t.push_back(record->time(i) * 1e6);
        v.push_back(record->samples[i] / peak + offset);
      }
    const std::string block = std::string("rec") + arrival;
    s += io::gnuplot_datablock(block, {t, v});
    plots += std::string(plots.empty() ? "" : ", ") + "$" + block + " using 1:2 with lines lw 1 lc rgb '#555555' notitle";
    marks += "set label '" + std::string(arrival) + " channel' at graph 0.01, first " + format_exact(offset + 0.5) +
             " font 'Sans,11'\n";
    // The true onsets on this channel: the S channel also holds the P precursor.
    std::vector<std::pair<std::string, double>> truths = {{std::string("true ") + arrival, arrival == std::string("P") ? pair.t_p_s : pair.t_s_s}};
    if (arrival == std::string("S")) truths.push_back({"true P (precursor)", pair.t_p_s});
    for (const auto& [label, time] : truths)
      marks += "set arrow from " + format_exact(time * 1e6) + ", " + format_exact(offset - 1.1) + " to " +
               format_exact(time * 1e6) + ", " + format_exact(offset + 1.1) + " nohead lw 2.5 lc rgb 'black'\n" +
               "set label '" + label + "' at " + format_exact(time * 1e6) + ", " + format_exact(offset + 1.2) +
               " right offset -0.3,0 font 'Sans,9'\n";
    double row = 0;
    for (const auto& strategy : picker_strategies()) {
      if (strategy.arrival != arrival) continue;
      try {
        const double tp = strategy.pick(pair).pick.time_s * 1e6;
        const std::string c = colours[colour++ % 7];
        marks += "set arrow from " + format_exact(tp) + ", " + format_exact(offset - 1.1) + " to " + format_exact(tp) +
                 ", " + format_exact(offset + 1.1) + " nohead dt 2 lw 1.5 lc rgb '" + c + "'\n" + "set label '" +
                 strategy.name + "' at " + format_exact(tp) + ", " + format_exact(offset - 0.75 + 0.3 * row) +
                 " left offset 0.3,0 font 'Sans,9' tc rgb '" + c + "'\n";
        row += 1;
      } catch (const InputError&) {
      }
    }
  }
  s += marks;
  s += "set xlabel 'time after the trigger [{/Symbol m}s]'\nset ytics ('' 0)\nset grid\nset key off\nset xrange [" +
       format_exact(t_lo * 1e6) + ":" + format_exact(t_hi * 1e6) + "]\nset yrange [-4:1.6]\n";
  if (!title.empty()) s += "set title '" + title + "'\n";
  return s + "plot " + plots + "\n";
}

std::string picker_bias_cpp(const std::vector<PickerBiasRow>& rows) {
  std::string s;
  char buf[512];
  for (const auto& r : rows) {
    std::snprintf(buf, sizeof buf, "{\"%s\", \"%s\", %.17g, %.17g, %.17g, %.17g, %zu, %zu, %zu, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g, {}, %.17g},\n",
                  r.arrival.c_str(), r.picker.c_str(), r.snr_dB, r.frequency_Hz, r.rise_periods, r.precursor_fraction,
                  r.records, r.refused, r.flagged, r.median_periods, r.mad_periods, r.p90_abs_periods,
                  r.unflagged_median_periods, r.unflagged_mad_periods, r.unflagged_p90_abs_periods, r.slow_rise_fraction);
    s += buf;
  }
  return s;
}

}  // namespace mesowave::lab
