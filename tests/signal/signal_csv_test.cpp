// Signal CSV files: exact round trips (CSV and HDF5), the header conventions,
// and every malformed file named by line and column.
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/signal_csv.hpp"
#include "mesowave/signal/signal_file.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "mesowave/io/hdf5.hpp"
#include "support/input_error.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using signal::Signal;

namespace {

std::vector<Signal> two_sensors() {
  const signal::HannBurst burst(100e3, 5, 1.0, 10e-6);
  Signal b{"B", "acceleration", "m/s^2", "z", -5e-6, 1e-7, burst.sample(1e-7, 700, -5e-6), std::array<double, 3>{0.025, 0, 0.05}};
  Signal c{"C", "acceleration", "m/s^2", "", -5e-6, 1e-7, burst.sample(1e-7, 700, -5e-6 - 3e-6), std::nullopt};
  for (auto& v : c.samples) v *= -1.0 / 3.0;  // values that do not print short
  return {b, c};
}

std::string message_of(const std::string& text) {
  return mesowave::test::input_error_of([&] { signal::parse_signal_csv(text, "f.csv"); });
}

}  // namespace

TEST(SignalCsv, RoundTripKeepsEverySampleBitForBit) {
  const auto signals = two_sensors();
  const auto back = signal::parse_signal_csv(signal::signals_to_csv(signals), "round-trip");
  ASSERT_EQ(back.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(back[k].name, signals[k].name);
    EXPECT_EQ(back[k].unit, signals[k].unit);
    EXPECT_EQ(back[k].quantity, signals[k].quantity);
    EXPECT_EQ(back[k].component, signals[k].component);
    EXPECT_EQ(back[k].position_m, signals[k].position_m);
    EXPECT_EQ(back[k].t0_s, signals[k].t0_s);
    EXPECT_NEAR(back[k].dt_s, signals[k].dt_s, 1e-15 * signals[k].dt_s);  // from the end times
    EXPECT_EQ(back[k].samples, signals[k].samples);                        // shortest round-trip digits
  }
}

TEST(SignalCsv, ConvertsThroughHdf5AndBack) {
  test::TempDir dir;
  const auto signals = two_sensors();
  signal::write_signals(dir / "a.h5", signal::SignalFormat::hdf5, signals, {{"scene", "test"}});
  const auto h5 = signal::read_signals(dir / "a.h5");
  signal::write_signals(dir / "a.csv", signal::SignalFormat::csv, h5);
  const auto csv = signal::read_signals(dir / "a.csv");
  ASSERT_EQ(csv.size(), 2u);
  EXPECT_EQ(csv[1].samples, signals[1].samples);
  EXPECT_EQ(csv[0].position_m, signals[0].position_m);
  EXPECT_THROW(signal::signal_format_of("a.txt"), InputError);
  EXPECT_EQ(signal::signal_format_of("A.HDF5"), signal::SignalFormat::hdf5);
}

TEST(SignalCsv, ReadsOscilloscopeStyleFiles) {
  // Times in microseconds printed with few digits, a column without a unit, no metadata lines.
  const std::string text =
      "time [us],CH1 [V],CH2\n"
      "-1.0,0.01,5\n-0.9,0.02,6\n-0.8,0.00,7\n-0.7,-0.01,8\n-0.6,0.03,9\n";
  signal::SignalCsvDefaults defaults;
  defaults.unit = "V";
  defaults.quantity = "voltage";
  const auto s = signal::parse_signal_csv(text, "scope.csv", defaults);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].name, "CH1");
  EXPECT_EQ(s[0].unit, "V");
  EXPECT_EQ(s[1].unit, "V");  // the default
  EXPECT_EQ(s[1].quantity, "voltage");
  EXPECT_NEAR(s[0].t0_s, -1e-6, 1e-18);
  EXPECT_NEAR(s[0].dt_s, 1e-7, 1e-18);
  EXPECT_EQ(s[1].samples, (std::vector<double>{5, 6, 7, 8, 9}));
}

TEST(SignalCsv, MalformedFilesAreNamed) {
  EXPECT_EQ(message_of("x,B\n0,1\n1,2\n"),
            "f.csv: the first column 'x' must be the time with its unit: t_s, t_ms, t_us or t_ns (or \"t [us]\")");
  EXPECT_EQ(message_of("t_s\n0\n1\n"), "f.csv: needs a time column and at least one signal column, has 1 column(s)");
  EXPECT_EQ(message_of("t_s,B\n0,1\n"), "f.csv: needs at least 2 rows to know the sampling interval, has 1");
  EXPECT_EQ(message_of("t_s,B\n0,1\n1,nan\n2,3\n"), "f.csv:3: column 'B' holds 'nan', not a finite number");
  EXPECT_EQ(message_of("t_s,B\n0,1\n1,\n2,3\n"), "f.csv:3: column 'B' holds '', not a finite number");
  EXPECT_EQ(message_of("t_s,B\n0,1\n1.5,2\n2,3\n"),
            "f.csv:3: time 1.5 is off the uniform grid t0 + i dt (dt 1 t_s) by more than 0.1 dt; resample the file "
            "onto a uniform grid first");
  EXPECT_EQ(message_of("t_s,B\n2,1\n1,2\n0,3\n"), "f.csv: times must increase (first 2 s, last 0 s)");
  EXPECT_EQ(message_of("t_s,B,B\n0,1,2\n1,2,3\n"), "f.csv: column 'B' appears twice");
  EXPECT_EQ(message_of("t_s,B\n0,1\n1,2,3\n"), "f.csv:3: 3 fields where the header has 2");
}

TEST(SignalCsv, RefusesSignalsItCannotHold) {
  auto signals = two_sensors();
  signals[1].dt_s = 2e-7;
  EXPECT_THROW(signal::signals_to_csv(signals), InputError);  // two time bases
  signals = two_sensors();
  signals[1].name = "C,1";
  EXPECT_THROW(signal::signals_to_csv(signals), InputError);
  signals = two_sensors();
  signals[1].samples[3] = NAN;
  EXPECT_THROW(signal::signals_to_csv(signals), InputError);
  EXPECT_THROW(signal::signals_to_csv({}), InputError);
}

TEST(SignalFile, ReadsStringsAsH5pyWritesThem) {
  // h5py stores str attributes as variable-length UTF-8 strings (mesowave
  // writes fixed-length ASCII); both must read.
  test::TempDir dir;
  const auto path = dir / "h5py.h5";
  auto utf8 = [](hid_t object, const char* name, const char* value) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attr = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(attr, type, &value);
    H5Aclose(attr), H5Sclose(space), H5Tclose(type);
  };
  {
    auto file = io::h5::create_file(path);
    utf8(file.id(), "format", "mesowave-signals");
    auto group = io::h5::create_group(file.id(), "signals");
    auto b = io::h5::create_group(group.id(), "B");
    io::h5::write_doubles(b.id(), "samples", {0.0, 1.0, -1.0, 0.5});
    io::h5::set_attribute(b.id(), "t0_s", 0.0);
    io::h5::set_attribute(b.id(), "dt_s", 1e-7);
    utf8(b.id(), "quantity", "acceleration");
    utf8(b.id(), "unit", "m/s\xc2\xb2");  // m/s², not ASCII
  }
  const auto signals = signal::read_signal_file(path);
  ASSERT_EQ(signals.size(), 1u);
  EXPECT_EQ(signals[0].quantity, "acceleration");
  EXPECT_EQ(signals[0].unit, "m/s\xc2\xb2");
  EXPECT_EQ(signals[0].component, "");
  EXPECT_EQ(signals[0].samples.size(), 4u);
}
