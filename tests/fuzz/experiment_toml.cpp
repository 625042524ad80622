// Fuzz target: experiment files (TOML, experiment/experiment.hpp), as the DEM scenes and mw-fem read them.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mesowave/experiment/experiment.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = mesowave::fuzz::as_text(data, size);
  mesowave::fuzz::accept_input_error([&] { mesowave::experiment::parse_experiment(text, "fuzz.toml"); });
  return 0;
}
