#include "mesowave/lab/upv_waveform.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/gnuplot.hpp"
#include "mesowave/lab/compression_record.hpp"
#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/fft.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "mesowave/signal/noise.hpp"
#include "mesowave/signal/resample.hpp"
#include "mesowave/signal/validate.hpp"

namespace mesowave::lab {

namespace {

std::string us(double t) { return format_fixed(t * 1e6, 2) + " us"; }

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

signal::Signal from_times(const std::vector<double>& t, std::vector<double> x, const std::vector<std::size_t>& lines,
                          const std::string& origin, const std::string& name) {
  if (t.size() < 8) throw InputError(origin + ": fewer than 8 samples");
  for (std::size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]))
      throw InputError(origin + ":" + std::to_string(lines[i]) + ": time " + us(t[i]) + " does not increase (previous " +
                       us(t[i - 1]) + "): the time column must be strictly increasing");
  const double dt = (t.back() - t.front()) / double(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i)
    if (std::abs((t[i] - t[i - 1]) - dt) > 0.01 * dt)
      throw InputError(origin + ":" + std::to_string(lines[i]) + ": time step " + us(t[i] - t[i - 1]) +
                       " differs from the mean step " + us(dt) + ": the record is not uniformly sampled");
  signal::Signal s;
  s.name = name;
  s.quantity = "voltage";
  s.unit = "V";
  s.t0_s = t.front();
  s.dt_s = dt;
  s.samples = std::move(x);
  return s;
}

signal::Signal read_csv_waveform(const std::filesystem::path& path, const WaveformReadOptions& o,
                                 const std::string& name) {
  std::string text = read_all(path);
  if (o.no_header) {
    // Name the columns 1, 2, ... by the first data line.
    std::size_t first = 0;
    while (first < text.size() && (text[first] == '#' || text[first] == '\n')) {
      const auto nl = text.find('\n', first);
      first = nl == std::string::npos ? text.size() : nl + 1;
    }
    const auto nl = text.find('\n', first);
    const std::string line = text.substr(first, nl == std::string::npos ? std::string::npos : nl - first);
    const std::size_t fields = std::size_t(std::count(line.begin(), line.end(), ',')) + 1;
    std::string header;
    for (std::size_t i = 1; i <= fields; ++i) {
      if (i > 1) header += ',';
      header += std::to_string(i);
    }
    text = header + "\n" + text;
  }
  auto table = io::parse_csv(text, path.string());
  if (o.no_header)
    for (auto& l : table.row_lines) --l;  // the line numbers of the file, not of the named copy
  std::size_t ti = 0;
  if (!o.time_column.empty()) {
    ti = table.column(o.time_column);
  } else {
    bool found = false;
    for (std::size_t c = 0; c < table.header.size() && !found; ++c) {
      const std::string n = lower(table.header[c]);
      if (n.rfind("t_", 0) == 0 || n.rfind("time", 0) == 0) ti = c, found = true;
    }
    if (!found) throw InputError(path.string() + ": no time column (t_us, time_s, ...; or --time-column)");
  }
  const std::size_t ai = o.amplitude_column.empty() ? ti + 1 : table.column(o.amplitude_column);
  if (ai >= table.header.size()) throw InputError(path.string() + ": no amplitude column after the time column");
  std::string unit = o.time_unit;
  if (unit.empty()) {
    if (o.no_header) unit = "s";
    else {
      const auto us_pos = table.header[ti].rfind('_');
      if (us_pos == std::string::npos)
        throw InputError(path.string() + ": the time column '" + table.header[ti] +
                         "' carries no unit (t_s, t_us, ...; or --time-unit)");
      unit = table.header[ti].substr(us_pos + 1);
    }
  }
  const double factor = unit_to_si(unit, "time", path.string() + " time column");
  std::vector<double> t, x;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    t.push_back(table.number(r, ti) * factor);
    x.push_back(table.number(r, ai));
  }
  auto s = from_times(t, std::move(x), table.row_lines, path.string(), name);
  return s;
}

template <class T>
T read_le(const std::string& d, std::size_t at) {
  T v;
  std::memcpy(&v, d.data() + at, sizeof v);
  return v;
}

signal::Signal read_wav_waveform(const std::filesystem::path& path, const WaveformReadOptions& o,
                                 const std::string& name) {
  const std::string d = read_all(path);
  const std::string where = path.string();
  if (d.size() < 12 || d.compare(0, 4, "RIFF") != 0 || d.compare(8, 4, "WAVE") != 0)
    throw InputError(where + ": not a RIFF/WAVE file");
  std::uint16_t format = 0, channels = 0, bits = 0;
  std::uint32_t rate = 0;
  std::size_t data_at = 0, data_size = 0;
  for (std::size_t at = 12; at + 8 <= d.size();) {
    const std::string id = d.substr(at, 4);
    const std::uint32_t size = read_le<std::uint32_t>(d, at + 4);
    if (id == "fmt " && at + 24 <= d.size()) {
      format = read_le<std::uint16_t>(d, at + 8);
      channels = read_le<std::uint16_t>(d, at + 10);
      rate = read_le<std::uint32_t>(d, at + 12);
      bits = read_le<std::uint16_t>(d, at + 22);
    } else if (id == "data") {
      data_at = at + 8;
      data_size = std::min<std::size_t>(size, d.size() - data_at);
    }
    at += 8 + std::size_t(size) + (size % 2);  // in 64 bits: a chunk size near 2^32 wrapped to 0 and looped for ever (libFuzzer)
  }
  if (!data_at) throw InputError(where + ": no data chunk");
  if (channels != 1) throw InputError(where + ": " + std::to_string(channels) + " channels (a mono record is needed)");
  const bool pcm16 = format == 1 && bits == 16, float32 = format == 3 && bits == 32;
  if (!pcm16 && !float32) throw InputError(where + ": only 16-bit PCM or 32-bit float WAV is supported");
  signal::Signal s;
  s.name = name;
  s.quantity = "voltage";
  s.unit = pcm16 ? "1 (full scale)" : "1";
  const std::size_t n = data_size / (bits / 8);
  for (std::size_t i = 0; i < n; ++i)
    s.samples.push_back(pcm16 ? read_le<std::int16_t>(d, data_at + 2 * i) / 32768.0
                              : double(read_le<float>(d, data_at + 4 * i)));
  if (s.samples.size() < 8) throw InputError(where + ": fewer than 8 samples");
  s.dt_s = o.sample_interval_s ? *o.sample_interval_s : 1.0 / double(rate);
  if (!(s.dt_s > 0)) throw InputError(where + ": no sample rate; give --sample-interval-us");
  s.t0_s = -double(o.trigger_sample.value_or(0)) * s.dt_s;
  return s;
}

double rms(const std::vector<double>& x, std::size_t a, std::size_t b) {
  double m = 0;
  for (std::size_t i = a; i < b; ++i) m += x[i];
  m /= double(b - a);
  double v = 0;
  for (std::size_t i = a; i < b; ++i) v += (x[i] - m) * (x[i] - m);
  return std::sqrt(v / double(b - a));
}

// The matched filter of the header: the lag L (record time of the wavelet's first sample)
// in [search start, end] where c(L) = sum_k (x[L + k] - noise mean) w[k] has its largest local
// maximum, refined by a parabola through c at L - 1, L, L + 1.
signal::Pick matched_filter_pick(const signal::Signal& s, const OnsetOptions& o, const Onset& onset, std::size_t i0,
                                 std::size_t i1, std::size_t first_index) {
  signal::Signal w = *o.wavelet;
  w.t0_s = 0;
  if (std::abs(w.dt_s - s.dt_s) > 1e-9 * s.dt_s) {
    const auto n = std::size_t(std::floor(w.dt_s * double(w.size() - 1) / s.dt_s)) + 1;
    w = signal::resample(w, signal::TimeBase{0.0, s.dt_s, n}, signal::Interpolation::linear);
  }
  double mean = 0;
  for (std::size_t i = i0; i < i1; ++i) mean += s.samples[i] / double(i1 - i0);
  // Located by the envelope peak, the onset comes before it by about the wavelet's own rise to
  // its envelope peak, d_w: lags up to the peak - d_w / 2 only, so that the record's later,
  // longer cycles (a smeared or reverberating burst) do not win one period late.
  double end = onset.locator.time_s + o.aic_after_s;
  if (o.locator == "envelope-peak") {
    signal::EnvelopePeakOptions env;
    const double d_w = signal::envelope_peak_pick(w, env).time_s;
    end = onset.locator.time_s - 0.5 * d_w;
  }
  const auto empty = [&] {
    return InputError("record " + s.name + ": the xcorr window " + us(onset.search_begin_s) + " .. " + us(end) +
                      " is empty (the envelope peak minus half the wavelet's rise): the wavelet is longer than the arrival");
  };
  if (!(end > onset.search_begin_s)) throw empty();
  const auto last = std::min(s.size() - 1, std::size_t(std::floor((std::min(end, onset.search_end_s) - s.t0_s) / s.dt_s + 1e-9)));
  if (last < first_index + 2) throw empty();
  const auto c = [&](std::size_t L) {
    double sum = 0;
    for (std::size_t k = 0; k < w.size() && L + k < s.size(); ++k) sum += (s.samples[L + k] - mean) * w.samples[k];
    return sum;
  };
  // c over the window and one lag past it (where the record has one), so that its last lag can
  // be told a local maximum or not.
  std::vector<double> cs;
  for (std::size_t L = first_index; L <= std::min(last + 1, s.size() - 1); ++L) cs.push_back(c(L));
  // The largest local maximum inside the window: a largest c on the window's end is the slope
  // up to a later match (a period late), on its start the tail of an earlier one.
  std::size_t best = 0;
  for (std::size_t L = first_index + 1; L <= last && L + 1 < first_index + cs.size(); ++L) {
    const double v = cs[L - first_index];
    if (v >= cs[L - 1 - first_index] && v > cs[L + 1 - first_index] && (best == 0 || v > cs[best - first_index])) best = L;
  }
  if (best == 0 || !(cs[best - first_index] > 0))
    throw InputError("record " + s.name + ": the record does not match the wavelet anywhere in " +
                     us(onset.search_begin_s) + " .. " + us(end) +
                     " (no positive peak of the correlation): the onset lies before the window, or another wavelet, or its polarity is inverted");
  double shift = 0;
  {
    const double a = cs[best - 1 - first_index], b = cs[best - first_index], d = cs[best + 1 - first_index];
    const double den = a - 2 * b + d;
    if (den < 0) shift = std::clamp(0.5 * (a - d) / den, -0.5, 0.5);
  }
  double norm_x = 0, norm_w = 0;
  for (std::size_t k = 0; k < w.size() && best + k < s.size(); ++k) {
    const double x = s.samples[best + k] - mean;
    norm_x += x * x;
    norm_w += w.samples[k] * w.samples[k];
  }
  signal::Pick p;
  p.method = "xcorr";
  p.time_s = s.time(best) + shift * s.dt_s;
  p.index = shift > 0 ? best + 1 : best;
  p.quality = cs[best - first_index] / std::max(std::sqrt(norm_x * norm_w), 1e-300);
  p.quality_name = "xcorr_coefficient";
  return p;
}

}  // namespace

signal::Signal read_upv_waveform(const std::filesystem::path& path, const WaveformReadOptions& options,
                                 const std::string& name) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path.string());
  char head[4] = {0};
  in.read(head, 4);
  if (in.gcount() == 4 && std::string_view(head, 4) == "RIFF") return read_wav_waveform(path, options, name);
  if (options.sample_interval_s || options.trigger_sample)
    throw InputError(path.string() + ": --sample-interval-us and --trigger-sample apply to WAV records; a CSV has times");
  return read_csv_waveform(path, options, name);
}

signal::Signal lowpass(const signal::Signal& record, double corner_Hz) {
  if (!(corner_Hz > 0)) throw InputError("low-pass corner must be positive");
  signal::Signal out = record;
  const std::size_t n = record.size();
  double mean = 0;
  for (double v : record.samples) mean += v / double(n);
  std::vector<double> x(record.samples);
  for (double& v : x) v -= mean;
  const std::size_t m = signal::fast_fft_length(2 * n);
  auto X = signal::rfft(x, m);
  const double df = 1.0 / (double(m) * record.dt_s);
  for (std::size_t k = 0; k < X.size(); ++k) {
    const double f = double(k) * df;
    const double g = f <= corner_Hz ? 1.0
                     : f >= 2 * corner_Hz ? 0.0
                                          : 0.5 * (1 + std::cos(M_PI * (f - corner_Hz) / corner_Hz));
    X[k] *= g;
  }
  const auto y = signal::irfft(X, m);
  for (std::size_t i = 0; i < n; ++i) out.samples[i] = y[i] + mean;
  return out;
}

signal::Signal burst_wavelet(double f, double cycles, bool derivative, double dt) {
  if (!(f > 0) || !(cycles > 0) || !(dt > 0) || !std::isfinite(f) || !std::isfinite(cycles))
    throw InputError("burst wavelet: frequency, cycles and sample interval must be positive");
  const signal::HannBurst burst(f, cycles);
  signal::Signal w;
  w.name = "burst wavelet";
  w.quantity = derivative ? "d/dt of the load" : "load";
  w.unit = "1";
  w.t0_s = 0;
  w.dt_s = dt;
  for (std::size_t i = 0; double(i) * dt <= burst.duration_s(); ++i) {
    const double t = double(i) * dt;
    w.samples.push_back(derivative ? burst.rate(t) : burst(t));
  }
  return w;
}

Onset pick_onset(const signal::Signal& raw, const OnsetOptions& o) {
  signal::require_valid(raw, 8);
  const signal::Signal s = o.lowpass_Hz > 0 ? lowpass(raw, o.lowpass_Hz) : raw;
  if (o.picker != "threshold" && o.picker != "aic" && o.picker != "envelope-peak" && o.picker != "xcorr")
    throw InputError("picker '" + o.picker + "' is not one of threshold, aic, envelope-peak, xcorr");
  if (o.picker == "xcorr" && (!o.wavelet || o.wavelet->size() < 4))
    throw InputError("the xcorr picker needs a wavelet of 4 samples or more (mw-upv --s-wavelet or --s-wavelet-burst-kHz)");
  const double end_s = s.time(s.size() - 1);
  if (!o.noise_end_s && !(s.t0_s < 0))
    throw InputError("record " + s.name + " starts at " + us(s.t0_s) +
                     " (no pre-trigger samples): give the noise window (--noise-window-us)");
  const double noise_begin = o.noise_begin_s.value_or(s.t0_s), noise_end = o.noise_end_s.value_or(0.0);
  const auto i0 = std::size_t(std::max(0.0, std::ceil((noise_begin - s.t0_s) / s.dt_s - 1e-9)));
  const auto i1 = std::size_t(std::max(0.0, std::ceil((noise_end - s.t0_s) / s.dt_s - 1e-9)));
  if (i1 > s.size() || i1 < i0 + 16)
    throw InputError("record " + s.name + ": the noise window " + us(noise_begin) + " .. " + us(noise_end) +
                     " holds fewer than 16 samples");
  // An onset before the trigger shows as a pre-trigger whose quarters differ.
  if (o.check_quiet_noise) {
    const std::size_t q = (i1 - i0) / 4;
    const double first = rms(s.samples, i0, i0 + q), last = rms(s.samples, i1 - q, i1);
    const double ratio = std::max(first, last) / std::max(std::min(first, last), 1e-300);
    if (ratio > 3.0)
      throw InputError("record " + s.name + ": the noise window " + us(noise_begin) + " .. " + us(noise_end) +
                       " is not quiet (RMS " + format_number(first) + " in its first quarter, " + format_number(last) +
                       " in its last): the onset lies inside the pre-trigger or the trigger came late; give another "
                       "--noise-window-us or check the trigger");
  }
  Onset onset;
  onset.search_begin_s = std::max({o.search_begin_s.value_or(noise_end), noise_end, o.crosstalk_s});
  onset.search_end_s = o.search_end_s.value_or(end_s);
  if (!(onset.search_end_s > onset.search_begin_s + 4 * s.dt_s))
    throw InputError("record " + s.name + ": the search window " + us(onset.search_begin_s) + " .. " +
                     us(onset.search_end_s) + " is empty");
  const auto first_index = std::size_t(std::ceil((onset.search_begin_s - s.t0_s) / s.dt_s - 1e-9));
  {
    double mean = 0, peak = 0;
    for (std::size_t i = i0; i < i1; ++i) mean += s.samples[i] / double(i1 - i0);
    for (std::size_t i = first_index; i < s.size() && s.time(i) <= onset.search_end_s; ++i)
      peak = std::max(peak, std::abs(s.samples[i] - mean));
    onset.snr_dB = 20 * std::log10(std::max(peak, 1e-300) / std::max(rms(s.samples, i0, i1), 1e-300));
  }
  const std::string before = std::string("inside the ") +
                             (o.crosstalk_s > 0 && onset.search_begin_s <= o.crosstalk_s ? "cross-talk window" : "pre-trigger") +
                             "? (--crosstalk-us, the search window)";
  // Locate the arrival: the first crossing of the threshold, or the envelope peak.
  if (o.locator == "envelope-peak") {
    signal::EnvelopePeakOptions env;
    env.search = {onset.search_begin_s, onset.search_end_s};
    onset.locator = signal::envelope_peak_pick(s, env);
    if (onset.locator.index <= first_index + 1)
      throw InputError("record " + s.name + ": the envelope is largest at the start of the search window (" +
                       us(onset.search_begin_s) + "): the arrival lies before it - " + before);
    if (onset.locator.quality < 1.5)
      onset.warnings.push_back("record " + s.name + ": the envelope has competing peaks in " + us(onset.search_begin_s) +
                               " .. " + us(onset.search_end_s) + " (peak ratio " + format_fixed(onset.locator.quality, 2) +
                               "): the arrival is ambiguous there");
    // A stronger arrival right after the window: the wave may come later than
    // the window allows (an S wave in a material with nu > 0.45, fresh paste).
    const auto e = signal::envelope(std::span<const double>(s.samples), env.hilbert);
    const auto in_window = [&](double a, double b) {
      double m = 0;
      for (std::size_t i = 0; i < s.size(); ++i)
        if (s.time(i) >= a && s.time(i) <= b) m = std::max(m, e[i]);
      return m;
    };
    const double width = onset.search_end_s - onset.search_begin_s;
    const double inside = in_window(onset.search_begin_s, onset.search_end_s);
    const double after = in_window(onset.search_end_s, onset.search_end_s + 3 * width);
    if (after > 1.5 * inside)
      onset.warnings.push_back("record " + s.name + ": a stronger arrival follows the search window (envelope " +
                               format_fixed(after / inside, 1) + " x higher before " +
                               us(onset.search_end_s + 3 * width) + "): the wave may arrive after " +
                               us(onset.search_end_s) + " (widen the search window)");
  } else {
    signal::ThresholdOptions th;
    th.noise_begin_s = noise_begin;
    th.noise_end_s = noise_end;
    th.factor = o.threshold_factor;
    th.relative = o.threshold_relative;
    th.search = {onset.search_begin_s, onset.search_end_s};
    onset.locator = signal::threshold_pick(s, th);
    if (onset.locator.index <= first_index)
      throw InputError("record " + s.name + ": the signal is above the threshold already at the start of the search window (" +
                       us(onset.search_begin_s) + "): the onset lies before it - " + before);
  }
  // The located arrival must stand out of the noise: a record of noise alone
  // also crosses a threshold somewhere, and that is not an onset.
  {
    const double noise = rms(s.samples, i0, i1);
    const double a = onset.locator.time_s - (o.locator == "envelope-peak" ? 0.5 * o.aic_after_s : 0.0);
    const auto j0 = std::size_t(std::max(0.0, (a - s.t0_s) / s.dt_s));
    const auto j1 = std::min(s.size(), j0 + std::max<std::size_t>(8, std::size_t(o.aic_after_s / s.dt_s)));
    const double ratio = rms(s.samples, j0, j1) / std::max(noise, 1e-300);
    if (ratio < o.min_arrival_snr)
      throw InputError("record " + s.name + ": no arrival stands out of the noise (RMS after the " +
                       onset.locator.method + " at " + us(onset.locator.time_s) + " is " + format_fixed(ratio, 1) +
                       " x the noise RMS, less than " + format_fixed(o.min_arrival_snr, 1) + "): no onset picked");
  }
  if (o.picker == "threshold") {
    if (o.locator != "threshold") throw InputError("the threshold picker needs the threshold locator");
    onset.pick = onset.locator;
  } else if (o.picker == "aic") {
    signal::AicOptions aic;
    const double end = o.locator == "envelope-peak" ? onset.locator.time_s : onset.locator.time_s + o.aic_after_s;
    aic.search = {onset.search_begin_s, std::min(onset.search_end_s, end)};
    onset.pick = signal::aic_pick(s, aic);
    if (onset.pick.index <= first_index + 2)
      throw InputError("record " + s.name + ": the AIC onset falls on the start of the search window (" +
                       us(onset.search_begin_s) + "): the onset lies before it - " + before);
    // An onset is a change from quiet to signal: within a wave train (an S pick
    // inside the P wave's ringing) the record is as strong before the pick as after.
    {
      const auto k = onset.pick.index;
      const auto w = std::max<std::size_t>(8, std::size_t(o.aic_after_s / s.dt_s));
      if (k >= w && k + w <= s.size()) {
        const double contrast = rms(s.samples, k, k + w) / std::max(rms(s.samples, k - w, k), 1e-300);
        onset.contrast = contrast;
        if (contrast < o.min_contrast)
          onset.warnings.push_back("record " + s.name + ": the record is nearly as strong before the onset at " +
                                   us(onset.pick.time_s) + " as after it (RMS ratio " + format_fixed(contrast, 2) +
                                   " < " + format_fixed(o.min_contrast, 1) +
                                   "): not a clear arrival, perhaps inside an earlier wave train");
      }
    }
    if (o.locator == "threshold" && onset.pick.time_s > onset.locator.time_s + s.dt_s)
      onset.warnings.push_back("record " + s.name + ": the AIC onset (" + us(onset.pick.time_s) +
                               ") lies after the threshold crossing (" + us(onset.locator.time_s) + ")");
  } else if (o.picker == "xcorr") {
    onset.pick = matched_filter_pick(s, o, onset, i0, i1, first_index);
    if (onset.pick.quality < o.min_xcorr_coefficient)
      onset.warnings.push_back("record " + s.name + ": the record matches the wavelet poorly at the xcorr onset " +
                               us(onset.pick.time_s) + " (coefficient " + format_fixed(onset.pick.quality, 2) + " < " +
                               format_fixed(o.min_xcorr_coefficient, 2) + "): another wavelet, or another arrival");
  } else {
    signal::EnvelopePeakOptions env;
    env.search = {onset.search_begin_s, onset.search_end_s};
    onset.pick = signal::envelope_peak_pick(s, env);
    onset.warnings.push_back("record " + s.name + ": the envelope peak is the group arrival, later than the onset");
  }
  return onset;
}

OnsetOptions shear_wave_options(OnsetOptions base, double p_arrival_s, double delay_s) {
  const double tp = p_arrival_s - delay_s;
  if (!(tp > 0)) throw InputError("the P arrival must come after the delay to place the S search window");
  if (!base.search_begin_s && !base.search_end_s) {
    base.search_begin_s = delay_s + 1.3 * tp;
    base.search_end_s = delay_s + 3.5 * tp;
  }
  base.locator = "envelope-peak";
  return base;
}

TimeOfFlightPick pick_time_of_flight(const std::filesystem::path& path, const WaveformReadOptions& read,
                                     const OnsetOptions& options, double delay_s, const std::string& name) {
  TimeOfFlightPick p;
  p.record = read_upv_waveform(path, read, name + " (" + path.filename().string() + ")");
  if (read.added_noise_snr_dB) {
    p.added_noise_rms = signal::noise_rms_at_snr(p.record, *read.added_noise_snr_dB);
    p.record = signal::with_noise_at_snr(p.record, *read.added_noise_snr_dB, read.added_noise_seed);
  }
  p.onset = pick_onset(p.record, options);
  p.delay_s = delay_s;
  p.tof_s = p.onset.pick.time_s - delay_s;
  if (!(p.tof_s > 0))
    throw InputError(p.record.name + ": the onset at " + us(p.onset.pick.time_s) + " does not come after the delay " +
                     us(delay_s));
  return p;
}

void describe_pick(nlohmann::ordered_json& j, const std::string& k, const TimeOfFlightPick& p) {
  const auto& o = p.onset;
  j[k + "_pick_us"] = o.pick.time_s * 1e6;
  j[k + "_picker"] = o.pick.method;
  if (o.pick.quality_name == "aic_sd_s") j[k + "_pick_aic_sd_us"] = o.pick.quality * 1e6;
  else j[k + "_pick_" + o.pick.quality_name] = o.pick.quality;
  j[k + "_located_us"] = o.locator.time_s * 1e6;
  j[k + "_locator"] = o.locator.method;
  j[k + "_delay_us"] = p.delay_s * 1e6;
  if (o.contrast > 0) j[k + "_onset_contrast"] = o.contrast;
  if (p.added_noise_rms > 0) j[k + "_added_noise_rms"] = p.added_noise_rms;
}

}  // namespace mesowave::lab

namespace mesowave::lab {

std::string upv_figure_script(const std::vector<PickedTrace>& traces, const std::filesystem::path& png,
                              const std::string& title) {
  std::string s = "set terminal pngcairo size 1200,600 font 'Sans,11'\nset output " + io::gnuplot_quote(png) + "\n";
  double t_hi = 0, t_lo = 0;
  for (const auto& tr : traces) t_hi = std::max(t_hi, tr.onset.pick.time_s);
  t_hi = std::max(3.0 * t_hi, t_hi + 50e-6);
  for (const auto& tr : traces) t_lo = std::min(t_lo, std::max(tr.record->t0_s, -0.25 * t_hi));
  std::string plots, labels;
  for (std::size_t k = 0; k < traces.size(); ++k) {
    const auto& tr = traces[k];
    const auto& x = tr.record->samples;
    double peak = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (tr.record->time(i) >= std::max(tr.onset.search_begin_s, t_lo) && tr.record->time(i) <= t_hi)
        peak = std::max(peak, std::abs(x[i]));
    if (!(peak > 0)) peak = 1;
    const double offset = -2.4 * double(k);
    std::vector<double> t, v;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (tr.record->time(i) >= t_lo && tr.record->time(i) <= t_hi) {
        t.push_back(tr.record->time(i) * 1e6);
        v.push_back(std::clamp(x[i] / peak, -1.15, 1.15) + offset);
      }
    const std::string block = "w" + std::to_string(k);
    s += io::gnuplot_datablock(block, {t, v});
    const double tp = tr.onset.pick.time_s * 1e6, tof = (tr.onset.pick.time_s - tr.delay_s) * 1e6;
    s += "set arrow from " + format_exact(tp) + ", " + format_exact(offset - 1.15) + " to " + format_exact(tp) + ", " +
         format_exact(offset + 1.15) + " nohead dt 2 lw 2 lc rgb '" + tr.colour + "'\n";
    std::string how = tr.delay_s != 0 ? tr.onset.pick.method + ": pick " + format_fixed(tp, 1) + " - delay " +
                                            format_fixed(tr.delay_s * 1e6, 1)
                                      : tr.onset.pick.method;
    if (!tr.onset.warnings.empty()) how += "; FLAGGED, see the warnings";
    labels += "set label '" + tr.symbol + " = " + format_fixed(tof, 1) + " {/Symbol m}s (" + how + ")' at " + format_exact(tp) + ", " + format_exact(offset + 1.3) + " left offset 0.5,0 tc rgb '" +
              tr.colour + "'\n";
    plots += std::string(plots.empty() ? "" : ", ") + "$" + block + " using 1:2 with lines lw 1.5 lc rgb '" + tr.colour +
             "' title '" + tr.label + "'";
  }
  s += labels;
  s += "set xlabel 'time after the trigger [{/Symbol m}s]'\nset ylabel 'normalised amplitude'\nset grid\n"
       "set key top right\nset ytics ('' 0)\nset xrange [" +
       format_exact(t_lo * 1e6) + ":" + format_exact(t_hi * 1e6) + "]\nset yrange [" +
       format_exact(-2.4 * double(traces.size() - 1) - 1.5) + ":1.9]\n";
  if (!title.empty()) s += "set title " + io::gnuplot_text(title) + "\n";  // an apostrophe in it stays text
  s += "plot " + plots + "\n";
  return s;
}

}  // namespace mesowave::lab
