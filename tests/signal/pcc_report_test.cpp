// What mw-pcc reports (signal/pcc_report): signals whose correlation is known in
// closed form - an affine copy (r = 1), a mirror image (r = -1) and other
// harmonics over whole periods (orthogonal, r = 0) - through files, table,
// metrics, JSON, spectra and the figures asked for.
#include "mesowave/signal/pcc_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/signal_csv.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::signal;

namespace {

// offset + scale (sin(n x) + sin(m x) / 2), x = 2 pi i / 1000 over 1000 samples of
// 0.1 us: harmonics n and m of 10 kHz, whose beat gives the envelope a variance.
Signal wave(const std::string& name, int n, int m, double scale, double offset) {
  Signal s{name, "acceleration", "m/s^2", "", 0.0, 1e-7, {}, std::nullopt};
  for (int i = 0; i < 1000; ++i) {
    const double x = 2 * std::numbers::pi * i / 1000.0;
    s.samples.push_back(offset + scale * (std::sin(n * x) + 0.5 * std::sin(m * x)));
  }
  return s;
}

std::vector<double> csv_row(const std::string& csv, const std::string& first) {
  std::istringstream in(csv.substr(csv.find("\n" + first + ",") + 1));
  std::string line, cell;
  std::getline(in, line);
  std::istringstream cells(line);
  std::vector<double> v;
  while (std::getline(cells, cell, ',')) v.push_back(std::stod(cell));
  return v;
}

}  // namespace

TEST(PccReport, ClosedFormCorrelations) {
  test::TempDir dir;
  const auto a = dir / "a.h5", b = dir / "b.h5";
  const auto base = [](const std::string& name) { return wave(name, 5, 7, 1, 0); };
  signal::write_signals(a, signal::SignalFormat::hdf5, {base("B"), base("C"), base("D")});
  signal::write_signals(b, signal::SignalFormat::hdf5,
                        {wave("B", 5, 7, 2, 3), wave("C", 5, 7, -1, 0), wave("D", 9, 11, 1, 0), base("E")});
  PccRequest q;
  q.files = {a, b};
  q.sensors = {"B", "C", "D"};
  q.spectra = true;
  q.plot_envelopes = true;
  const auto r = pcc_report(q);
  ASSERT_EQ(r.table.sensors.size(), 3u);
  EXPECT_NEAR(r.table.sensors[0].pcc_signal, 1.0, 1e-12);
  EXPECT_NEAR(r.table.sensors[1].pcc_signal, -1.0, 1e-12);
  EXPECT_NEAR(r.table.sensors[2].pcc_signal, 0.0, 1e-12);
  EXPECT_NEAR(r.summary["mean_pcc_signal"].get<double>(), 0.0, 1e-12);
  EXPECT_EQ(r.inputs.size(), 2u);
  ASSERT_EQ(r.metrics.size(), 8u);  // signal and envelope per sensor, then the two means
  EXPECT_EQ(r.metrics[0].name, "pcc_B");
  EXPECT_EQ(r.metrics[7].name, "pcc_envelope_mean");
  EXPECT_NE(r.csv.find("\nB,1.0000,"), std::string::npos) << r.csv;
  EXPECT_NE(r.csv.find("\nC,-1.0000,"), std::string::npos) << r.csv;
  EXPECT_NE(r.csv.find("\nmean,"), std::string::npos);
  EXPECT_NE(r.text.find("resampling: none (same time base)"), std::string::npos) << r.text;
  // The spectra: f_kHz and both sets per sensor, amplitude 2|X_k|/n - a unit sine reads 1 at 50 kHz.
  EXPECT_EQ(r.spectra_csv.substr(0, r.spectra_csv.find('\n')),
            "f_kHz,B a [m/s^2],B b [m/s^2],C a [m/s^2],C b [m/s^2],D a [m/s^2],D b [m/s^2]");
  const auto at50 = csv_row(r.spectra_csv, "50");
  const std::vector<double> expected = {50, 1, 2, 1, 1, 1, 0};
  ASSERT_EQ(at50.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(at50[i], expected[i], 1e-12) << i;
  // Only the envelope figure was asked for: one panel per sensor, PCC in the title.
  EXPECT_FALSE(r.signals);
  EXPECT_FALSE(r.spectra);
  ASSERT_TRUE(r.envelopes);
  ASSERT_EQ(r.envelopes->panels.size(), 3u);
  EXPECT_EQ(r.envelopes->panels[1].title.rfind("C: PCC -1.000, envelopes 1.000", 0), 0u) << r.envelopes->panels[1].title;

  q.sensors.clear();  // every shared name: E has no partner
  const auto all = pcc_report(q);
  EXPECT_NE(all.text.find("not compared: E (only in b)"), std::string::npos) << all.text;
  EXPECT_EQ(all.summary["only_in_b"], nlohmann::ordered_json::array({"E"}));
}

TEST(PccReport, BadRequestsAreInputErrors) {
  PccRequest q;
  EXPECT_THROW(pcc_report(q), InputError);  // no sets
  q.files = {"a.h5"};
  EXPECT_THROW(pcc_report(q), InputError);  // one file
  q.files = {"a.h5", "b.h5"};
  q.a = {"c.h5"};
  EXPECT_THROW(pcc_report(q), InputError);  // both forms
  q.a.clear();
  q.begin_us = 50, q.end_us = 10;
  EXPECT_THROW(pcc_report(q), InputError);  // window ends before it starts
  q.end_us.reset();
  q.plots = {"fig.pdf"};
  EXPECT_THROW(pcc_report(q), InputError);  // refused before any file is read
}

// --arrival-relative: a triangle pulse (rest to 10 us, apex at 20 us, rest again from 30 us) crosses
// a fraction F of its peak at 10 + 10 F us exactly (linear refinement on a linear rise). The second
// set holds it delayed by 1.3 us and scaled by 0.8 (sensor B) and mirrored (C: the same |x|).
TEST(PccReport, ArrivalsAndPeaksOfADelayedScaledPulse) {
  test::TempDir dir;
  const auto triangle = [](const std::string& name, double delay_us, double scale) {
    Signal s{name, "velocity", "m/s", "", 0.0, 1e-7, {}, std::nullopt};
    for (int i = 0; i < 1000; ++i) {
      const double t = i * 0.1 - delay_us;
      s.samples.push_back(scale * (t <= 10 || t >= 30 ? 0.0 : t < 20 ? (t - 10) / 10 : (30 - t) / 10));
    }
    return s;
  };
  const auto a = dir / "a.h5", b = dir / "b.h5";
  signal::write_signals(a, signal::SignalFormat::hdf5, {triangle("B", 0, 1), triangle("C", 0, 1)});
  signal::write_signals(b, signal::SignalFormat::hdf5, {triangle("B", 1.3, 0.8), triangle("C", 0, -1)});
  PccRequest q;
  q.files = {a, b};
  q.arrival_relative = 0.02;
  const auto r = pcc_report(q);
  const auto& B = r.summary["sensors"][0];
  EXPECT_NEAR(B["arrival_a_us"].get<double>(), 10.2, 1e-9);
  EXPECT_NEAR(B["arrival_b_us"].get<double>(), 11.5, 1e-9);
  EXPECT_NEAR(B["arrival_shift_us"].get<double>(), 1.3, 1e-9);
  EXPECT_NEAR(B["peak_ratio"].get<double>(), 0.8, 1e-12);
  const auto& C = r.summary["sensors"][1];
  EXPECT_NEAR(C["arrival_shift_us"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(C["peak_ratio"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(r.summary["mean_abs_arrival_shift_us"].get<double>(), 0.65, 1e-9);
  EXPECT_NEAR(r.summary["mean_abs_peak_error"].get<double>(), 0.1, 1e-12);
  EXPECT_NE(r.csv.find(",10.2000,11.5000,1.3000,0.8000\n"), std::string::npos) << r.csv;  // printed to 4 decimals
  EXPECT_NE(r.csv.find("\nmean,"), std::string::npos);
  EXPECT_NE(r.csv.find(",,,0.6500,0.1000\n"), std::string::npos) << r.csv;
  // Without the option the table keeps its six columns.
  q.arrival_relative.reset();
  EXPECT_EQ(pcc_report(q).csv.substr(0, pcc_report(q).csv.find('\n')), "sensor,pcc_signal,pcc_envelope,samples,from_us,to_us");
  q.arrival_relative = 1.5;
  EXPECT_THROW(pcc_report(q), InputError);
}
