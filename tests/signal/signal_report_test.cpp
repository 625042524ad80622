// What mw-signal reports (signal/signal_report), against closed forms: the
// burst's length, span and main lobe; a whole-period sine's spectrum peak and
// amplitude and its constant Hilbert envelope; the onset of a step; and the
// signals a conversion gathers.
#include "mesowave/signal/signal_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::signal;

namespace {

// amplitude sin(2 pi 50 kHz t) over 1000 samples of 0.1 us: five whole periods.
Signal sine(const std::string& name, double amplitude) {
  Signal s{name, "acceleration", "m/s^2", "", 0.0, 1e-7, {}, std::nullopt};
  for (int i = 0; i < 1000; ++i) s.samples.push_back(amplitude * std::sin(2 * std::numbers::pi * 5 * i / 1000.0));
  return s;
}

}  // namespace

TEST(SignalReport, BurstSpanAndMainLobe) {
  BurstRequest q;
  q.frequency_kHz = 100;
  q.cycles = 5;
  q.delay_us = 10;
  q.duration_us = 100;
  q.output = "burst.h5";
  const auto r = burst_report(q);
  ASSERT_EQ(r.signals.size(), 1u);
  EXPECT_EQ(r.signals[0].size(), 1000u);  // 100 us at 10 MHz
  EXPECT_EQ(r.summary["output"], "burst.h5");
  EXPECT_DOUBLE_EQ(r.summary["dt_ns"].get<double>(), 100);
  EXPECT_NEAR(r.summary["burst_end_us"].get<double>(), 10 + 5 / 0.1, 1e-9);  // delay + n / f_c
  EXPECT_DOUBLE_EQ(r.summary["main_lobe_kHz"][0].get<double>(), 100 * (1 - 2.0 / 5));
  EXPECT_DOUBLE_EQ(r.summary["main_lobe_kHz"][1].get<double>(), 100 * (1 + 2.0 / 5));
  EXPECT_FALSE(r.summary.contains("note"));
  EXPECT_EQ(r.attributes.at("generator"), "mw-signal burst");
  // The Hann window is zero before the delay and peaks at most at A.
  for (std::size_t i = 0; i < 100; ++i) EXPECT_EQ(r.signals[0].samples[i], 0.0) << i;
  double peak = 0;
  for (double x : r.signals[0].samples) peak = std::max(peak, std::abs(x));
  EXPECT_LE(peak, 1.0);
  EXPECT_GT(peak, 0.9);

  q.duration_us = 30;  // ends inside the burst
  EXPECT_TRUE(burst_report(q).summary.contains("note"));
  q.sampling_MHz = 0;
  EXPECT_THROW(burst_report(q), InputError);
}

TEST(SignalReport, SpectrumAndEnvelopeOfAWholePeriodSine) {
  test::TempDir dir;
  const auto file = dir / "s.h5";
  signal::write_signals(file, signal::SignalFormat::hdf5, {sine("A", 2), sine("B", 0.5)});
  const SignalSource source{file, {}};
  const auto sp = spectrum_report(source, "sp.csv", {});
  EXPECT_NEAR(sp.summary["spectra"]["A"]["peak_frequency_kHz"].get<double>(), 50, 0.1);  // a hundredth of a bin
  EXPECT_DOUBLE_EQ(sp.summary["df_kHz"].get<double>(), 10);  // 1 / (1000 x 0.1 us)
  EXPECT_EQ(sp.summary["rows"], 501);                          // 0 .. Nyquist
  EXPECT_EQ(sp.csv.substr(0, sp.csv.find('\n')), "f_kHz,A [m/s^2],B [m/s^2]");
  const auto row = sp.csv.find("\n50,");
  ASSERT_NE(row, std::string::npos);
  const auto line = sp.csv.substr(row + 4, sp.csv.find('\n', row + 1) - row - 4);
  EXPECT_NEAR(std::stod(line.substr(0, line.find(','))), 2.0, 1e-12);  // 2 |X_k| / n reads the amplitude
  EXPECT_NEAR(std::stod(line.substr(line.find(',') + 1)), 0.5, 1e-12);
  EXPECT_EQ(sp.metrics.size(), 2u);
  SpectrumRequest capped;
  capped.max_frequency_kHz = 100;
  EXPECT_EQ(spectrum_report(source, "sp.csv", capped).summary["rows"], 11);

  // The analytic signal of a whole-period sine has a constant magnitude: the amplitude.
  const auto env = envelope_report({file, {"B"}}, "env.h5", "none", "none");
  ASSERT_EQ(env.signals.size(), 1u);
  for (double x : env.signals[0].samples) EXPECT_NEAR(x, 0.5, 1e-12);
  EXPECT_EQ(env.attributes.at("envelope_of"), file.string());
  EXPECT_EQ(env.summary["fft_length"], 1000);
  EXPECT_THROW(envelope_report({file, {"Q"}}, "env.h5", "none", "none"), InputError);
}

TEST(SignalReport, ThresholdFindsAStepAndConvertGathers) {
  test::TempDir dir;
  Signal step{"S", "voltage", "V", "", -10e-6, 1e-7, {}, std::nullopt};
  for (int i = 0; i < 500; ++i) step.samples.push_back(step.time(std::size_t(i)) >= 20e-6 ? 1.0 : 0.0);
  const auto file = dir / "step.csv";
  signal::write_signals(file, signal::SignalFormat::csv, {step});
  TofRequest q;
  q.method = "threshold";
  q.relative = 0.5;
  const auto r = tof_report({file, {}}, q);
  EXPECT_NEAR(r.summary["picks"]["S"]["t_us"].get<double>(), 20, 0.1);  // within a sample of the step
  EXPECT_NE(r.text.find("threshold"), std::string::npos);
  EXPECT_EQ(r.csv.substr(0, r.csv.find('\n')), "signal,method,t_us,quality,quality_name");
  EXPECT_EQ(r.metrics.at(0).name, "tof_S");
  q.method = "peak";
  EXPECT_THROW(tof_report({file, {}}, q), InputError);

  const auto other = dir / "two.h5";
  signal::write_signals(other, signal::SignalFormat::hdf5, {sine("A", 1), sine("B", 1)});
  const auto c = convert_report({file, other}, {"B", "S"}, {}, "all.h5");
  ASSERT_EQ(c.signals.size(), 2u);
  EXPECT_EQ(c.summary["signals"], nlohmann::ordered_json::array({"B", "S"}));
  EXPECT_EQ(c.summary["inputs"], file.string() + " " + other.string());
  EXPECT_EQ(c.inputs.size(), 2u);
}

// HannBurst::rate against a central difference of the burst itself (error (w h)^2 / 6: h = 1 ns at
// 40 kHz gives about 1e-8 of the peak rate), inside the burst, and zero outside it.
TEST(SignalReport, HannBurstRateIsTheBurstsDerivative) {
  const signal::HannBurst burst(40e3, 2, 1.5, 10e-6);
  const double h = 1e-9, peak_rate = 2 * std::numbers::pi * 40e3 * 1.5;
  for (double t = 10.5e-6; t < 10e-6 + burst.duration_s(); t += 1.3e-6)
    EXPECT_NEAR(burst.rate(t), (burst(t + h) - burst(t - h)) / (2 * h), 1e-7 * peak_rate) << t;
  EXPECT_EQ(burst.rate(5e-6), 0.0);
  EXPECT_EQ(burst.rate(10e-6 + burst.duration_s() + 1e-6), 0.0);
}
