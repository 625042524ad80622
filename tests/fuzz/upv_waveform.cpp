// Fuzz target: pulse-analyser records (lab/upv_waveform.hpp): WAV (RIFF, 16-bit
// PCM or 32-bit float) and instrument CSV, as mw-upv reads them.
#include <cstddef>
#include <cstdint>

#include "mesowave/lab/upv_waveform.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static mesowave::fuzz::TempFile file(".rec");
  const auto& path = file.write(data, size);
  mesowave::fuzz::accept_input_error([&] { mesowave::lab::read_upv_waveform(path, {}, "fuzz"); });
  mesowave::lab::WaveformReadOptions headerless;
  headerless.no_header = true;
  headerless.time_column = "1";
  headerless.amplitude_column = "2";
  headerless.time_unit = "us";
  mesowave::fuzz::accept_input_error([&] { mesowave::lab::read_upv_waveform(path, headerless, "fuzz"); });
  return 0;
}
