// Fuzz target: packings in Yade's textExt layout (dem/packing/packing_import.hpp:
// "#format ..." line, whitespace-separated columns), as mw-pack import reads them.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mesowave/dem/packing/packing_import.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = mesowave::fuzz::as_text(data, size);
  mesowave::fuzz::accept_input_error([&] { mesowave::dem::parse_yade_text(text, "fuzz.txt"); });
  return 0;
}
