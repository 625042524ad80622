#pragma once
// The message of the InputError a call throws, "" if it throws none: for tests
// that check the one line names the value and why.
#include <functional>
#include <string>

#include "mesowave/core/error.hpp"

namespace mesowave::test {

inline std::string input_error_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace mesowave::test
