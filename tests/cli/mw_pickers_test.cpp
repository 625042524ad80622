// mw-pickers prints the picker table; mw-upv states the remaining bias of the
// picker it used from that table, on synthetic and on TU Graz's real records.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/labraw_support.hpp"
#include "mesowave/lab/picker_study.hpp"
#include "mesowave/lab/transducer_record.hpp"
#include "mesowave/lab/upv_waveform.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::test;

namespace {

// The stored row of arrival + picker interpolated at snr, as the table's user
// reads it: the unflagged picks' column for a pick without a warning.
double table_median(const std::string& arrival, const std::string& picker, double snr, bool unflagged) {
  std::vector<const lab::PickerBiasRow*> rows;
  for (const auto& r : lab::measured_picker_bias())
    if (r.arrival == arrival && r.picker == picker) rows.push_back(&r);
  const auto m = [&](const lab::PickerBiasRow* r) { return unflagged ? r->unflagged_median_periods : r->median_periods; };
  if (snr <= rows.front()->snr_dB) return m(rows.front());
  for (std::size_t k = 0; k + 1 < rows.size(); ++k)
    if (snr <= rows[k + 1]->snr_dB) {
      const double w = (snr - rows[k]->snr_dB) / (rows[k + 1]->snr_dB - rows[k]->snr_dB);
      return m(rows[k]) + w * (m(rows[k + 1]) - m(rows[k]));
    }
  return m(rows.back());
}

}  // namespace

TEST(MwPickers, PrintsOneRowPerStrategyAndSnr) {
  const auto r = run_tool("mw-pickers", {"--seeds", "3", "--frequency-kHz", "45", "--rise-periods", "1.5",
                                         "--precursor-fractions", "0.3", "--snr-dB", "30,40"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  for (const auto& s : lab::picker_strategies())
    for (const char* snr : {"30", "40"})
      EXPECT_NE(r.out.find("| " + s.arrival + " | " + s.name + " | " + snr + " | 3 |"), std::string::npos)
          << s.arrival << " " << s.name << " " << snr << "\n" << r.out;
  const auto bad = run_tool("mw-pickers", {"--seeds", "0"});
  EXPECT_EQ(bad.exit_status, 1);
  EXPECT_NE(bad.err.find("seeds"), std::string::npos) << bad.err;
}

TEST(MwUpv, StatesTheRemainingBiasOfItsPickers) {
  const auto r = run_tool("mw-upv", {"--from", (raw_dir() / "upv-truth.toml").string(), "--p-wave",
                                     (raw_dir() / "upv-p.csv").string(), "--s-wave", (raw_dir() / "upv-s.csv").string(),
                                     "--lowpass-kHz", "216", "--s-lowpass-kHz", "160", "--density-kg-m3", "2129.56"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = parse_json(r.out);
  // P by AIC; S by mw-upv's S chain after the P pick: the table's rows at the records' SNR.
  // Neither pick is flagged (no warnings), so the unflagged picks' statistics are stated.
  EXPECT_TRUE(j["warnings"].empty()) << j["warnings"].dump();
  for (const char* k : {"t_p_pick_bias_source", "t_s_pick_bias_source"})
    EXPECT_NE(j[k].get<std::string>().find("unflagged picks"), std::string::npos) << j[k];
  EXPECT_DOUBLE_EQ(j["t_p_pick_bias_periods"].get<double>(),
                   table_median("P", "aic", j["t_p_pick_snr_dB"].get<double>(), true));
  EXPECT_DOUBLE_EQ(j["t_s_pick_bias_periods"].get<double>(),
                   table_median("S", "aic-after-p", j["t_s_pick_snr_dB"].get<double>(), true));
  // The shipped records' transducers: 54 kHz (P) and 40 kHz (S), paper Section 3.2;
  // read off the spectrum to 10 % (a 200 us window, a resonant pulse).
  EXPECT_NEAR(j["t_p_pick_frequency_kHz"].get<double>(), 54, 5.4);
  EXPECT_NEAR(j["t_s_pick_frequency_kHz"].get<double>(), 40, 4.0);
  EXPECT_DOUBLE_EQ(j["t_p_pick_bias_us"].get<double>(),
                   j["t_p_pick_bias_periods"].get<double>() / j["t_p_pick_frequency_kHz"].get<double>() * 1e3);
  EXPECT_NE(j["t_s_pick_bias_source"].get<std::string>().find("docs/upv-pickers.md"), std::string::npos);
  EXPECT_NE(j["t_s_pick_bias_source"].get<std::string>().find("not subtracted"), std::string::npos);
}

TEST(MwUpv, RealRecordsWithoutADensity) {
  // TU Graz's cement paste at 24 h (../shared/realdata/harden-cementpaste-upt,
  // SOURCE.md): velocities only, each pick with its stated bias.
  const auto wav = std::filesystem::path(MESOWAVE_SHARED_DIR) / "realdata/harden-cementpaste-upt/wav";
  if (!std::filesystem::exists(wav)) GTEST_SKIP() << wav << " is not here";
  const auto r = run_tool("mw-upv", {"--path-mm", "49.96", "--sample-interval-us", "0.1", "--trigger-sample", "1000",
                                     "--crosstalk-us", "10", "--p-wave", (wav / "ts1_wc040_d50_6_sig_c_288.wav").string(),
                                     "--s-wave", (wav / "ts1_wc040_d50_6_sig_s_288.wav").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = parse_json(r.out);
  EXPECT_FALSE(j.contains("E_d_GPa"));
  // SOURCE.md's crude 6-sigma pick: 17.0 us; mw-upv's AIC: 16.9 us (docs/realdata-upv.md).
  EXPECT_NEAR(j["t_p_us"].get<double>(), 17.0, 0.2);
  EXPECT_TRUE(j.contains("t_p_pick_bias_us"));
  EXPECT_TRUE(j.contains("t_s_pick_bias_us"));
}

TEST(MwUpv, VelocitiesOnlyFromWaveforms) {
  // Without --density-kg-m3 there is no product to declare: the run gives
  // velocities and nu_d (it failed on declare_products before).
  const auto r = run_tool("mw-upv", {"--from", (raw_dir() / "upv-truth.toml").string(), "--p-wave",
                                     (raw_dir() / "upv-p.csv").string(), "--s-wave", (raw_dir() / "upv-s.csv").string(),
                                     "--lowpass-kHz", "216", "--s-lowpass-kHz", "160"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = parse_json(r.out);
  EXPECT_FALSE(j.contains("E_d_GPa"));
  EXPECT_NEAR(j["t_p_us"].get<double>(), truth("upv-truth.toml", "true_t_p"), 0.5);  // as with a density
  EXPECT_TRUE(j.contains("nu_d"));
}

TEST(MwUpv, MatchedFilterOnAPointForceRecord) {
  // Stokes' point force's transverse record (lab/transducer_record.hpp) as a CSV: with the
  // load's rate as the wavelet mw-upv picks the S onset r/beta to a twentieth of a period
  // (0.4 us at 120 kHz), where its AIC chain is 0.3-0.45 periods late (picker_study_test),
  // and states the table's xcorr-after-p row.
  lab::PointForceRecordSpec spec;
  spec.p_speed_m_s = 3703.0;
  spec.s_speed_m_s = 2355.0;
  spec.snr_dB = 30;  // where the AIC chain is late on every seed (at 40 dB on some; picker_study_test)
  const auto rec = lab::point_force_record(spec);
  TempDir dir;
  std::string csv = "t_us,v\n";
  for (std::size_t i = 0; i < rec.size(); ++i) csv += std::to_string(rec.time(i) * 1e6) + "," + std::to_string(rec.samples[i] * 1e3) + "\n";
  write_file(dir / "s.csv", csv);
  const double t_p_us = 50.0 / 3703.0 * 1e3, t_s_us = 50.0 / 2355.0 * 1e3;
  const std::vector<std::string> base = {"--path-mm", "50", "--t-p-us", std::to_string(t_p_us), "--s-wave",
                                         (dir / "s.csv").string()};
  auto args = base;
  for (const char* a : {"--s-wavelet-burst-kHz", "120,2", "--s-wavelet-derivative"}) args.push_back(a);
  const auto r = run_tool("mw-upv", args);
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto j = parse_json(r.out);
  EXPECT_EQ(j["t_s_picker"], "xcorr");
  EXPECT_NEAR(j["t_s_us"].get<double>(), t_s_us, 0.05 / 120e3 * 1e6);
  EXPECT_DOUBLE_EQ(j["t_s_pick_bias_periods"].get<double>(),
                   table_median("S", "xcorr-after-p", j["t_s_pick_snr_dB"].get<double>(), true));
  // The same wavelet as a record (--s-wavelet FILE: F' sampled from its first motion at t = 0,
  // after 2 us of zeros before it, which are not the wavelet) gives the same pick to a sample.
  const auto rate = lab::burst_wavelet(120e3, 2, true, 50e-9);
  std::string wcsv = "t_us,v\n";
  for (int i = -40; i < 0; ++i) wcsv += std::to_string(i * 0.05) + ",0\n";
  for (std::size_t i = 0; i < rate.size(); ++i) wcsv += std::to_string(double(i) * 0.05) + "," + std::to_string(rate.samples[i] * 1e-6) + "\n";
  write_file(dir / "wavelet.csv", wcsv);
  auto file_args = base;
  file_args.push_back("--s-wavelet");
  file_args.push_back((dir / "wavelet.csv").string());
  const auto from_file = run_tool("mw-upv", file_args);
  ASSERT_EQ(from_file.exit_status, 0) << from_file.err;
  EXPECT_NEAR(parse_json(from_file.out)["t_s_us"].get<double>(), j["t_s_us"].get<double>(), 0.05);
  const auto aic = run_tool("mw-upv", base);
  ASSERT_EQ(aic.exit_status, 0) << aic.err;
  EXPECT_GT(parse_json(aic.out)["t_s_us"].get<double>() - t_s_us, 0.3 / 120e3 * 1e6);
  // Bad values: one line that names the option.
  for (const auto& [extra, word] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--s-wavelet-burst-kHz", "0,2"}, "--s-wavelet-burst-kHz"},
           {{"--s-wavelet-derivative"}, "--s-wavelet-derivative"},
           {{"--s-wavelet-burst-kHz", "120,2", "--s-wavelet", (dir / "s.csv").string()}, "not both"},
           {{"--s-wavelet", (dir / "missing.csv").string()}, "missing.csv"}}) {
    auto bad = base;
    bad.insert(bad.end(), extra.begin(), extra.end());
    const auto b = run_tool("mw-upv", bad);
    EXPECT_EQ(b.exit_status, 1) << extra[0];
    EXPECT_NE(b.err.find(word), std::string::npos) << b.err;
  }
}
