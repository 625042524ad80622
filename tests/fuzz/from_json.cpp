// Fuzz target: an earlier tool's JSON result given to `--from` (io/quantity_file.hpp:
// a flat object whose keys end in their unit), and the option names its keys fill.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mesowave/io/quantity_file.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = mesowave::fuzz::as_text(data, size);
  mesowave::fuzz::accept_input_error([&] {
    for (const auto& q : mesowave::io::parse_quantity_text(text, "fuzz.json")) (void)q.option_name();
  });
  return 0;
}
