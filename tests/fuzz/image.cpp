// Fuzz target: gray images (io/image.hpp: PNG through libpng, TIFF pages through
// libtiff, chosen by the signature), as mw-porosity reads micrographs and CT stacks.
#include <cstddef>
#include <cstdint>

#include "mesowave/io/image.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static mesowave::fuzz::TempFile file(".img");
  const auto& path = file.write(data, size);
  mesowave::fuzz::accept_input_error([&] { mesowave::io::read_gray_images(path); });
  return 0;
}
