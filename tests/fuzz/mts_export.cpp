// Fuzz target: MTS 793 text exports (io/mts_export.hpp: Latin-1, tabs, decimal
// commas, header and data blocks), as the compression-record reader (lab/compression_record.hpp) takes them.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mesowave/io/mts_export.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = mesowave::fuzz::as_text(data, size);
  mesowave::fuzz::accept_input_error([&] {
    const auto mts = mesowave::io::parse_mts_export(text, "fuzz.dat");
    (void)mts.header_number("Durchmesser");
  });
  return 0;
}
