// mw-signal and mw-pcc run as a user runs them: the outputs they promise, and
// for bad input exit 1 with one line `error: ...` and nothing written.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "mesowave/io/csv.hpp"
#include "mesowave/signal/correlation.hpp"
#include "mesowave/signal/signal_csv.hpp"
#include "mesowave/signal/signal_file.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::test;
using json = nlohmann::json;

namespace {

// A burst file made by the tool itself: 100 kHz, 10 MHz, 150 us unless `extra` says otherwise.
void make_burst(const TempDir& dir, const std::string& file, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"burst", "--frequency-kHz", "100", "--out", (dir / file).string()};
  auto given = [&](const std::string& option) { return std::find(extra.begin(), extra.end(), option) != extra.end(); };
  for (const auto& [option, value] : {std::pair{"--sampling-MHz", "10"}, std::pair{"--duration-us", "150"}})
    if (!given(option)) args.insert(args.end(), {option, value});
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = run_tool("mw-signal", args);
  ASSERT_EQ(r.exit_status, 0) << r.err;
}

// Exit 1, exactly one line on stderr starting with "error: " and containing `what`,
// and no file left in `dir` beyond `files_before`.
void expect_refusal(const ToolResult& r, const std::string& what, const TempDir& dir, std::size_t files_before) {
  EXPECT_EQ(r.exit_status, 1) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << "expected '" << what << "' in: " << r.err;
  EXPECT_EQ(count_files(dir.path()), files_before) << "a refused run left a file behind";
}

}  // namespace

TEST(SignalCli, BurstEnvelopeSpectrumAndTof) {
  TempDir dir;
  const auto b = run_tool("mw-signal", {"burst", "--cycles", "5", "--frequency-kHz", "100", "--delay-us", "20",
                                        "--duration-us", "200", "--out", (dir / "burst.h5").string()});
  ASSERT_EQ(b.exit_status, 0) << b.err;
  const auto burst = json::parse(b.out);
  EXPECT_EQ(burst["samples"], 2000);
  EXPECT_DOUBLE_EQ(burst["burst_end_us"].get<double>(), 70.0);
  const auto signals = signal::read_signal_file(dir / "burst.h5");
  ASSERT_EQ(signals.size(), 1u);
  EXPECT_EQ(signals[0].name, "excitation");
  EXPECT_EQ(signals[0].unit, "N");

  const auto e = run_tool("mw-signal", {"envelope", (dir / "burst.h5").string(), "--pad", "double", "--out",
                                        (dir / "env.csv").string()});
  ASSERT_EQ(e.exit_status, 0) << e.err;
  const auto env = json::parse(e.out);
  EXPECT_EQ(env["padding"], "double");
  EXPECT_EQ(env["fft_length"], 4000);
  // The envelope of a 5-cycle burst peaks at its centre: 20 + 25 us.
  EXPECT_NEAR(env["envelopes"]["excitation"]["peak_time_us"].get<double>(), 45.0, 0.01);
  const auto env_csv = signal::read_signal_csv(dir / "env.csv");
  EXPECT_EQ(env_csv[0].quantity, "force envelope");

  const auto s = run_tool("mw-signal", {"spectrum", (dir / "burst.h5").string(), "--pad", "65536",
                                        "--max-frequency-kHz", "300", "--out", (dir / "spec.csv").string()});
  ASSERT_EQ(s.exit_status, 0) << s.err;
  EXPECT_NEAR(json::parse(s.out)["spectra"]["excitation"]["peak_frequency_kHz"].get<double>(), 100.0, 0.2);
  const auto spec = io::read_csv(dir / "spec.csv");
  EXPECT_EQ(spec.header, (std::vector<std::string>{"f_kHz", "excitation [N]"}));
  EXPECT_LE(spec.number(spec.rows.size() - 1, 0), 300.0);

  const auto t = run_tool("mw-signal", {"tof", (dir / "burst.h5").string(), "--method", "aic", "--out",
                                        (dir / "tof.csv").string(), "--json", (dir / "tof.json").string()});
  ASSERT_EQ(t.exit_status, 0) << t.err;
  EXPECT_NE(t.out.find("aic"), std::string::npos);
  const auto tof = json::parse(read_file(dir / "tof.json"));
  EXPECT_NEAR(tof["picks"]["excitation"]["t_us"].get<double>(), 20.1, 1e-9);  // first nonzero sample
}

TEST(SignalCli, ConvertRoundTripAndNoise) {
  TempDir dir;
  make_burst(dir, "a.h5", {"--noise-rms", "0.01", "--seed", "7", "--name", "B"});
  ASSERT_EQ(run_tool("mw-signal", {"convert", (dir / "a.h5").string(), (dir / "a.csv").string()}).exit_status, 0);
  ASSERT_EQ(run_tool("mw-signal", {"convert", (dir / "a.csv").string(), (dir / "b.h5").string()}).exit_status, 0);
  const auto a = signal::read_signal_file(dir / "a.h5"), b = signal::read_signal_file(dir / "b.h5");
  EXPECT_EQ(a[0].samples, b[0].samples);
  // Several inputs merge into one file, in order.
  make_burst(dir, "d.h5", {"--name", "D"});
  ASSERT_EQ(run_tool("mw-signal", {"convert", (dir / "a.h5").string(), (dir / "d.h5").string(),
                                   (dir / "ad.h5").string()})
                .exit_status,
            0);
  const auto merged = signal::read_signal_file(dir / "ad.h5");
  ASSERT_EQ(merged.size(), 2u);
  EXPECT_EQ(merged[0].name, "B");
  EXPECT_EQ(merged[1].name, "D");
  // The same seed gives the same noise.
  make_burst(dir, "c.h5", {"--noise-rms", "0.01", "--seed", "7", "--name", "B"});
  EXPECT_EQ(signal::read_signal_file(dir / "c.h5")[0].samples, a[0].samples);
}

TEST(SignalCli, BadInputsAreRefused) {
  TempDir dir;
  make_burst(dir, "burst.h5");
  const std::string burst = (dir / "burst.h5").string(), out = (dir / "out.h5").string();
  auto refuse = [&](const std::vector<std::string>& args, const std::string& what) {
    expect_refusal(run_tool("mw-signal", args), what, dir, 1);
  };
  refuse({"burst", "--frequency-kHz", "0", "--out", out}, "centre frequency (0 Hz) must be positive");
  refuse({"burst", "--frequency-kHz", "100", "--cycles", "-1", "--out", out}, "cycles (-1) must be positive");
  refuse({"burst", "--frequency-kHz", "100", "--out", (dir / "b.txt").string()}, "end in .h5 (HDF5) or .csv");
  refuse({"burst", "--frequency-kHz", "100", "--sampling-MHz", "0", "--out", out}, "--sampling-MHz (0 MHz)");
  refuse({"burst", "--frequency-kHz", "100", "--noise-rms", "-1", "--out", out}, "noise RMS");
  refuse({"envelope", (dir / "missing.h5").string(), "--out", out}, "missing.h5");
  refuse({"envelope", burst, "--pad", "twice", "--out", out}, "padding 'twice'");
  refuse({"envelope", burst, "--detrend", "quadratic", "--out", out}, "detrend 'quadratic'");
  refuse({"envelope", burst, "--signals", "Z", "--out", out}, "has no signal 'Z' (it has excitation)");
  refuse({"spectrum", burst, "--scaling", "dB", "--out", (dir / "s.csv").string()}, "spectrum scaling 'dB'");
  refuse({"tof", burst, "--method", "threshold"}, "no pre-trigger samples");
  make_burst(dir, "late.h5", {"--delay-us", "20"});  // exactly zero before 20 us
  const std::string late = (dir / "late.h5").string();
  auto refuse2 = [&](const std::vector<std::string>& args, const std::string& what) {
    expect_refusal(run_tool("mw-signal", args), what, dir, 2);
  };
  refuse2({"tof", late, "--method", "threshold", "--noise-end-us", "5"}, "noise is exactly zero");
  refuse2({"tof", burst, "--method", "aic", "--window-begin-us", "500"}, "no sample lies within");
  refuse2({"tof", burst, "--method", "guess"}, "--method");
  refuse2({"convert", burst, (dir / "x.json").string()}, "end in .h5 (HDF5) or .csv");
  // A CSV with a NaN sample.
  write_file(dir / "nan.csv", "t_us,B [V]\n0,1\n0.1,nan\n0.2,3\n");
  expect_refusal(run_tool("mw-signal", {"envelope", (dir / "nan.csv").string(), "--out", out}),
                 "nan.csv:3: column 'B [V]' holds 'nan', not a finite number", dir, 3);
}

TEST(PccCli, TwoFilesPerSensorTableAndMean) {
  TempDir dir;
  // The same burst, the second copy 1 us later: r = cos(2 pi f 1 us) times
  // the envelope's own correlation at 1 us (~0.99 for a 50 us Hann window).
  make_burst(dir, "a.h5", {"--delay-us", "30", "--name", "B"});
  make_burst(dir, "b.h5", {"--delay-us", "31", "--name", "B", "--amplitude", "0.5"});
  const auto r = run_tool("mw-pcc", {(dir / "a.h5").string(), (dir / "b.h5").string(), "--csv",
                                     (dir / "pcc.csv").string(), "--out", (dir / "pcc.json").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.out.find("mean"), std::string::npos);
  EXPECT_NE(r.out.find("resampling: none (same time base)"), std::string::npos);
  const auto result = json::parse(read_file(dir / "pcc.json"));
  const double pcc = result["sensors"][0]["pcc_signal"];
  EXPECT_LT(pcc, std::cos(2 * 3.141592653589793 * 0.1));
  EXPECT_GT(pcc, 0.98 * std::cos(2 * 3.141592653589793 * 0.1));
  EXPECT_DOUBLE_EQ(result["mean_pcc_signal"].get<double>(), pcc);
  const auto csv = io::read_csv(dir / "pcc.csv");
  EXPECT_EQ(csv.text(csv.rows.size() - 1, 0), "mean");

  // Both sets' spectra beside each other; the second burst is half as strong.
  ASSERT_EQ(run_tool("mw-pcc", {(dir / "a.h5").string(), (dir / "b.h5").string(), "--spectra",
                                (dir / "spectra.csv").string(), "--max-frequency-kHz", "300"})
                .exit_status,
            0);
  const auto spectra = io::read_csv(dir / "spectra.csv");
  EXPECT_EQ(spectra.header, (std::vector<std::string>{"f_kHz", "B a [N]", "B b [N]"}));
  const std::size_t k100 = 15;  // 100 kHz on the 150 us record's 6.67 kHz grid
  EXPECT_NEAR(spectra.number(k100, 0), 100.0, 1e-9);
  EXPECT_NEAR(spectra.number(k100, 2) / spectra.number(k100, 1), 0.5, 1e-9);
}

// The table keeps four decimals (concrete paper Table 3 prints two); the JSON carries the
// coefficients to the last bit, so a later tool reads the library's own doubles.
TEST(PccCli, JsonHoldsTheLibrarysCoefficientsBitForBitAndTheCsvFourDecimals) {
  TempDir dir;
  make_burst(dir, "a.h5", {"--delay-us", "30", "--name", "B"});
  make_burst(dir, "b.h5", {"--delay-us", "31.37", "--name", "B", "--amplitude", "0.5"});
  const auto r = run_tool("mw-pcc", {(dir / "a.h5").string(), (dir / "b.h5").string(), "--csv",
                                     (dir / "pcc.csv").string(), "--out", (dir / "pcc.json").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto a = signal::read_signals(dir / "a.h5"), b = signal::read_signals(dir / "b.h5");
  const auto table = signal::correlate_sensors(a, b);
  ASSERT_EQ(table.sensors.size(), 1u);
  const auto j = json::parse(read_file(dir / "pcc.json"));
  const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  EXPECT_EQ(bits(j["sensors"][0]["pcc_signal"].get<double>()), bits(table.sensors[0].pcc_signal));
  EXPECT_EQ(bits(j["sensors"][0]["pcc_envelope"].get<double>()), bits(table.sensors[0].pcc_envelope));
  EXPECT_EQ(bits(j["mean_pcc_signal"].get<double>()), bits(table.mean_pcc_signal));
  EXPECT_EQ(bits(j["mean_pcc_envelope"].get<double>()), bits(table.mean_pcc_envelope));
  // Not a value that four decimals hold: the JSON's digits matter.
  EXPECT_NE(std::round(table.sensors[0].pcc_signal * 1e4) / 1e4, table.sensors[0].pcc_signal);

  const auto csv = io::read_csv(dir / "pcc.csv");
  for (std::size_t row : {std::size_t(0), csv.rows.size() - 1})
    for (std::size_t col : {std::size_t(1), std::size_t(2)}) {
      const std::string cell = csv.text(row, col);
      ASSERT_NE(cell.find('.'), std::string::npos) << cell;
      EXPECT_EQ(cell.size() - cell.find('.') - 1, 4u) << cell;
    }
  char four[32];
  std::snprintf(four, sizeof four, "%.4f", table.sensors[0].pcc_signal);
  EXPECT_EQ(csv.text(0, 1), four);

  const auto help = run_tool("mw-pcc", {"--help"});
  EXPECT_NE(help.out.find("full precision"), std::string::npos) << help.out;
}

TEST(PccCli, TimeBasesAndBadRecordsAreRefused) {
  TempDir dir;
  make_burst(dir, "a.h5", {"--name", "B"});
  make_burst(dir, "short.h5", {"--name", "B", "--duration-us", "100"});
  make_burst(dir, "coarse.h5", {"--name", "B", "--sampling-MHz", "4"});
  make_burst(dir, "flat.h5", {"--name", "B", "--amplitude", "0"});
  const std::string a = (dir / "a.h5").string(), table = (dir / "t.csv").string();
  auto refuse = [&](const std::vector<std::string>& args, const std::string& what) {
    expect_refusal(run_tool("mw-pcc", args), what, dir, 4);
  };
  refuse({a, (dir / "short.h5").string(), "--csv", table}, "unequal lengths (1500 and 1000 samples");
  refuse({a, (dir / "coarse.h5").string(), "--csv", table}, "different time bases");
  refuse({a, (dir / "flat.h5").string(), "--csv", table}, "zero variance");
  refuse({a, "--csv", table}, "give two files");
  refuse({a, (dir / "coarse.h5").string(), "--resample", "nearest"}, "interpolation 'nearest'");
  refuse({a, a, "--sensors", "C"}, "sensor 'C' is not in the first set");
  refuse({a, a, "--window-begin-us", "50", "--window-end-us", "10"}, "must exceed --window-begin-us");
  // Asked for, the resampling is done and said.
  const auto r = run_tool("mw-pcc", {a, (dir / "coarse.h5").string(), "--resample", "cubic"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.out.find("by cubic-spline interpolation"), std::string::npos) << r.out;
}

TEST(PccCli, FiguresOfBothSetsSensorBySensor) {
  TempDir dir;
  make_burst(dir, "a.h5", {"--delay-us", "30", "--name", "B"});
  make_burst(dir, "b.h5", {"--delay-us", "31", "--name", "B", "--amplitude", "0.5"});
  const std::string a = (dir / "a.h5").string(), b = (dir / "b.h5").string();
  const auto r = run_tool("mw-pcc", {a, b, "--labels", "FEM,DEM", "--plot-signals", (dir / "signals.png").string(),
                                     "--plot-envelopes", (dir / "envelopes.svg").string(), "--plot-window-us", "0,100",
                                     "--plot-spectra", (dir / "spectra.png").string(), "--max-frequency-kHz", "300"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  for (const char* png : {"signals.png", "spectra.png"})
    EXPECT_EQ(read_file(dir / png).rfind("\x89PNG\r\n\x1a\n", 0), 0u) << png;
  const auto svg = read_file(dir / "envelopes.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("B: PCC"), std::string::npos);  // the panel names the sensor and its PCC
  EXPECT_NE(svg.find("DEM"), std::string::npos);
  // Refused before any work: a figure format gnuplot is not asked for, a window that ends before it starts.
  expect_refusal(run_tool("mw-pcc", {a, b, "--plot-signals", (dir / "s.pdf").string()}), "must end in .png or .svg", dir, 5);
  expect_refusal(run_tool("mw-pcc", {a, b, "--plot-signals", (dir / "s.png").string(), "--plot-window-us", "50,10"}),
                 "the end must exceed the start", dir, 5);
}

TEST(SignalCli, RecordsProvenance) {
  TempDir dir;
  const std::string db = (dir / "prov.sqlite").string();
  ASSERT_EQ(run_tool("mw-signal", {"burst", "--frequency-kHz", "200", "--out", (dir / "b.h5").string(), "--db", db})
                .exit_status,
            0);
  const auto runs = run_tool("mw-prov", {"--db", db, "runs", "--json"});
  ASSERT_EQ(runs.exit_status, 0) << runs.err;
  EXPECT_NE(runs.out.find("mw-signal"), std::string::npos);
}
