// Fuzz target: lab-data files (TOML, io/quantity_file.hpp: one table per
// quantity with value, unit, source, cite), as `--from` reads them.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mesowave/io/quantity_file.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = mesowave::fuzz::as_text(data, size);
  mesowave::fuzz::accept_input_error([&] {
    for (const auto& q : mesowave::io::parse_quantity_text(text, "fuzz.toml")) (void)q.option_name();
  });
  return 0;
}
