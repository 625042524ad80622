// Fuzz target: signal files (HDF5, signal/signal_file.hpp), as every tool that reads
// signals opens them.
#include <cstddef>
#include <cstdint>

#include "mesowave/signal/signal_file.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static mesowave::fuzz::TempFile file(".h5");
  const auto& path = file.write(data, size);
  mesowave::fuzz::accept_input_error([&] { mesowave::signal::read_signal_file(path); });
  return 0;
}
