// Fuzz target: packing files (HDF5, dem/packing/packing_file.hpp) as mw-dem reads them:
// the spheres and the /origin record.
#include <cstddef>
#include <cstdint>

#include "mesowave/dem/packing/packing_file.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static mesowave::fuzz::TempFile file(".h5");
  const auto& path = file.write(data, size);
  mesowave::fuzz::accept_input_error([&] { mesowave::dem::read_packing_file(path); });
  mesowave::fuzz::accept_input_error([&] { mesowave::dem::read_packing_origin(path); });
  return 0;
}
