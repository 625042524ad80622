#pragma once
// What every fuzz target (tests/fuzz/<target>.cpp) shares. A target is one
// libFuzzer entry point, LLVMFuzzerTestOneInput, that hands the bytes to one
// parser of user files. Built two ways (docs/fuzzing.md):
//  - `make fuzz`: with clang and -fsanitize=fuzzer,address,undefined, the
//    libFuzzer campaign (build-fuzz/);
//  - the normal build: with replay_main.cpp, a main() that feeds every file
//    of tests/fuzz/corpus/<target>/ through the same entry point - a CTest
//    test (fuzz.<target>), so every crash once found stays fixed.
//
// The contract a parser is held to: for any bytes it returns, or throws
// InputError with a message; any other exception, a crash, a hang or
// undefined behaviour is a bug. An InputError is the right answer to a
// malformed file, so it is caught here; anything else escapes and libFuzzer
// (or the replay's std::terminate) reports it.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <string_view>
#include <system_error>

#include "mesowave/core/error.hpp"

namespace mesowave::fuzz {

inline std::string as_text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// Runs `parse`; an InputError must say what is wrong (an empty message is a
/// bug too, it would print a bare "error:"). With MESOWAVE_FUZZ_VERBOSE set,
/// prints each input's verdict (to see that a regression input is refused for
/// the right reason, and that the seeds parse).
template <class Parse>
void accept_input_error(Parse&& parse) {
  static const bool verbose = std::getenv("MESOWAVE_FUZZ_VERBOSE") != nullptr;
  try {
    parse();
    if (verbose) std::cerr << "  parsed\n";
  } catch (const InputError& e) {
    if (std::string_view(e.what()).empty()) std::abort();
    if (verbose) std::cerr << "  InputError: " << e.what() << "\n";
  }
}

/// The readers of HDF5, PNG, TIFF and WAV take a path: the input is written to
/// one temporary file per process (named by the process id, so parallel
/// libFuzzer jobs do not share it), removed at exit.
class TempFile {
public:
  explicit TempFile(const std::string& extension)
      : path_(std::filesystem::temp_directory_path() /
              ("mesowave-fuzz-" + std::to_string(::getpid()) + extension)) {}
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  const std::filesystem::path& write(const std::uint8_t* data, std::size_t size) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    out.close();
    if (!out) std::abort();  // the harness, not the parser, failed
    return path_;
  }

private:
  std::filesystem::path path_;
};

}  // namespace mesowave::fuzz
