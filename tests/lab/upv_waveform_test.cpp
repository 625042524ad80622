// UPV waveforms: times of flight picked on synthetic records with a known
// onset (20 dB SNR), the readers (CSV with and without header, WAV), and the
// hard cases: an onset inside the pre-trigger, noise without an arrival,
// non-monotonic and non-uniform time columns.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "mesowave/core/error.hpp"
#include "mesowave/lab/synthetic_upv.hpp"
#include "mesowave/lab/upv_waveform.hpp"
#include "support/input_error.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::lab;

namespace {

signal::Signal as_signal(const SyntheticWaveform& w, double shift_s = 0) {
  signal::Signal s;
  s.name = "synthetic";
  s.t0_s = w.t_s.front() + shift_s;
  s.dt_s = w.t_s[1] - w.t_s[0];
  s.samples = w.amplitude_V;
  return s;
}

// P: 54 kHz, picked through a low-pass at 4 x 54 kHz; S: 40 kHz, searched
// from 1.3 t_p to 3.5 t_p and located by its envelope peak, as mw-upv does.
double pick_p(std::uint64_t seed, double tof = 35e-6) {
  SyntheticUpvSpec spec;
  spec.tof_s = tof;
  spec.seed = seed;
  OnsetOptions o;
  o.lowpass_Hz = 216e3;
  return pick_onset(as_signal(synthetic_upv_waveform(spec)), o).pick.time_s;
}

double pick_s(std::uint64_t seed, double precursor = 0) {
  SyntheticUpvSpec spec;
  spec.tof_s = 55.1e-6;
  spec.frequency_Hz = 40e3;
  spec.precursor_tof_s = precursor > 0 ? 35e-6 : 0;
  spec.precursor_fraction = precursor;
  spec.seed = seed;
  OnsetOptions o;
  o.lowpass_Hz = 160e3;
  o.search_begin_s = 1.3 * 35e-6;
  o.search_end_s = 3.5 * 35e-6;
  o.locator = "envelope-peak";
  return pick_onset(as_signal(synthetic_upv_waveform(spec)), o).pick.time_s;
}

}  // namespace

TEST(UpvWaveform, PicksWithinHalfAMicrosecondAt20dB) {
  double sum_p = 0, sum_s = 0;
  const int n = 10;
  for (int seed = 1; seed <= n; ++seed) {
    const double ep = pick_p(std::uint64_t(seed)) - 35e-6, es = pick_s(std::uint64_t(seed)) - 55.1e-6;
    EXPECT_LT(std::abs(ep), 0.5e-6) << "seed " << seed;
    sum_p += std::abs(ep);
    sum_s += std::abs(es);
  }
  // The S pick (40 kHz: a slower first half-cycle) scatters more; its mean error
  // stays well inside half a microsecond.
  EXPECT_LT(sum_p / n, 0.3e-6);
  EXPECT_LT(sum_s / n, 0.35e-6);
}

TEST(UpvWaveform, NoiselessRecordIsPickedOnTheSample) {
  SyntheticUpvSpec spec;
  spec.snr_dB = 200;
  const auto onset = pick_onset(as_signal(synthetic_upv_waveform(spec)), OnsetOptions{});
  EXPECT_NEAR(onset.pick.time_s, 35e-6, 0.11e-6);
}

TEST(UpvWaveform, OnsetInsideThePretriggerIsRefused) {
  SyntheticUpvSpec spec;
  spec.tof_s = 35e-6;
  spec.pretrigger_s = 50e-6;
  // The trigger came 45 us late: the pulse now starts 10 us before t = 0.
  const auto late = as_signal(synthetic_upv_waveform(spec), -45e-6);
  const std::string late_error = mesowave::test::input_error_of([&] { pick_onset(late, OnsetOptions{}); });
  EXPECT_NE(late_error.find("pre-trigger"), std::string::npos) << late_error;
  // A quiet pre-trigger but the pulse already under way where the search starts.
  const auto early = as_signal(synthetic_upv_waveform(spec), -30e-6);  // onset at 5 us
  OnsetOptions o;
  o.noise_end_s = -20e-6;
  o.search_begin_s = 10e-6;
  EXPECT_THROW(pick_onset(early, o), InputError);
}

TEST(UpvWaveform, NoiseWithoutAnArrivalIsRefused) {
  SyntheticUpvSpec spec;
  spec.amplitude_V = 1e-9;   // the pulse is far below the noise...
  spec.snr_dB = -120;        // ...whose RMS is 1e-3 V
  const std::string m =
      mesowave::test::input_error_of([&] { pick_onset(as_signal(synthetic_upv_waveform(spec)), OnsetOptions{}); });
  EXPECT_TRUE(m.find("stands out") != std::string::npos || m.find("reaches the threshold") != std::string::npos) << m;
}

TEST(UpvWaveform, CsvReaders) {
  test::TempDir dir;
  test::write_file(dir / "h.csv", "t_us,amplitude_V\n-0.2,0\n-0.1,0\n0,0\n0.1,1\n0.2,2\n0.3,3\n0.4,4\n0.5,5\n");
  const auto s = read_upv_waveform(dir / "h.csv", {}, "P");
  EXPECT_NEAR(s.t0_s, -0.2e-6, 1e-15);
  EXPECT_NEAR(s.dt_s, 0.1e-6, 1e-15);
  EXPECT_EQ(s.samples.size(), 8u);
  // As the Harden CSVs: no header, sample index, time in s, several signals.
  test::write_file(dir / "n.csv", "1001,0,5,50\n1002,1e-7,6,60\n1003,2e-7,7,70\n1004,3e-7,8,80\n"
                                  "1005,4e-7,9,90\n1006,5e-7,10,100\n1007,6e-7,11,110\n1008,7e-7,12,120\n");
  WaveformReadOptions o;
  o.no_header = true;
  o.time_column = "2";
  o.amplitude_column = "4";
  const auto n = read_upv_waveform(dir / "n.csv", o, "S");
  EXPECT_DOUBLE_EQ(n.samples[2], 70.0);
  EXPECT_NEAR(n.dt_s, 1e-7, 1e-18);
}

TEST(UpvWaveform, NonMonotonicAndNonUniformTimeAreErrors) {
  test::TempDir dir;
  test::write_file(dir / "m.csv", "t_us,amplitude_V\n0,0\n0.1,1\n0.3,2\n0.2,3\n0.4,4\n0.5,5\n0.6,6\n0.7,7\n");
  const std::string error = mesowave::test::input_error_of([&] { read_upv_waveform(dir / "m.csv", {}, "P"); });
  EXPECT_NE(error.find("m.csv:5"), std::string::npos) << error;
  EXPECT_NE(error.find("strictly increasing"), std::string::npos) << error;
  test::write_file(dir / "u.csv", "t_us,amplitude_V\n0,0\n0.1,1\n0.2,2\n0.35,3\n0.4,4\n0.5,5\n0.6,6\n0.7,7\n");
  EXPECT_THROW(read_upv_waveform(dir / "u.csv", {}, "P"), InputError);
  test::write_file(dir / "x.csv", "t,amplitude_V\n0,0\n1,1\n2,2\n3,3\n4,4\n5,5\n6,6\n7,7\n");
  EXPECT_THROW(read_upv_waveform(dir / "x.csv", {}, "P"), InputError);  // no unit on the time column
}

TEST(UpvWaveform, WavWithTrueSampleIntervalAndTrigger) {
  test::TempDir dir;
  // 16-bit PCM mono, nominal 5000 Hz as the Harden exports.
  const std::int16_t samples[10] = {0, 100, -100, 200, -200, 16384, -16384, 32767, -32768, 0};
  std::string wav = "RIFF";
  auto u32 = [&](std::uint32_t v) { wav.append(reinterpret_cast<const char*>(&v), 4); };
  auto u16 = [&](std::uint16_t v) { wav.append(reinterpret_cast<const char*>(&v), 2); };
  u32(36 + 20);
  wav += "WAVEfmt ";
  u32(16), u16(1), u16(1), u32(5000), u32(10000), u16(2), u16(16);
  wav += "data";
  u32(20);
  wav.append(reinterpret_cast<const char*>(samples), 20);
  test::write_file(dir / "r.wav", wav);
  WaveformReadOptions o;
  o.sample_interval_s = 0.1e-6;
  o.trigger_sample = 4;
  const auto s = read_upv_waveform(dir / "r.wav", o, "P");
  ASSERT_EQ(s.samples.size(), 10u);
  EXPECT_NEAR(s.t0_s, -0.4e-6, 1e-18);
  EXPECT_DOUBLE_EQ(s.samples[5], 0.5);
  EXPECT_DOUBLE_EQ(s.samples[8], -1.0);
}

// A title with an apostrophe (cube-150.mk: "calibration 'static-test'") stays one gnuplot string.
TEST(UpvWaveform, FigureTitleWithAnApostropheIsQuotedForGnuplot) {
  SyntheticUpvSpec spec;
  const auto record = as_signal(synthetic_upv_waveform(spec));
  PickedTrace trace;
  trace.record = &record;
  trace.onset = pick_onset(record, OnsetOptions{});
  trace.label = "P wave";
  trace.symbol = "t_p";
  trace.colour = "#1f4e9c";
  const auto script = upv_figure_script({trace}, "fig.png", "calibration 'static-test': the pick");
  EXPECT_NE(script.find("set title \"calibration 'static-test': the pick\"\n"), std::string::npos);
}
