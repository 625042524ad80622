// Fuzz target: DEM scene files (TOML, dem/scene/scene.hpp), as mw-dem reads them.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mesowave/dem/scene/scene.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = mesowave::fuzz::as_text(data, size);
  mesowave::fuzz::accept_input_error([&] { mesowave::dem::parse_scene(text, "fuzz.toml"); });
  return 0;
}
