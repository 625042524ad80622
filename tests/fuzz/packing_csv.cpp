// Fuzz target: packings made elsewhere as CSV (dem/packing/packing_import.hpp: x, y, z,
// r or d columns with units, optional id), as mw-pack import reads them.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mesowave/dem/packing/packing_import.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = mesowave::fuzz::as_text(data, size);
  mesowave::fuzz::accept_input_error([&] { mesowave::dem::parse_packing_csv(text, "fuzz.csv"); });
  return 0;
}
