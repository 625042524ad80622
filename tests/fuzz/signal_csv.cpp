// Fuzz target: signal CSV (signal/signal_csv.hpp: a time column, one column per
// signal, "# signal" metadata comments), as mw-signal reads it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mesowave/signal/signal_csv.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = mesowave::fuzz::as_text(data, size);
  mesowave::fuzz::accept_input_error([&] { mesowave::signal::parse_signal_csv(text, "fuzz.csv"); });
  mesowave::fuzz::accept_input_error([&] { mesowave::signal::parse_signal_csv(text, "fuzz.csv", {"V", "voltage"}); });
  return 0;
}
