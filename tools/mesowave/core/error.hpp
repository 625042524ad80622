#pragma once
// Errors by who must act on them. A tool exits 1 on InputError (the user can
// fix it: one line naming the value and why) and 2 on anything else.
#include <stdexcept>
#include <string>

namespace mesowave {

/// Bad input: a value out of range, an unreadable or malformed file, an
/// unusable database path. The message is one line, shown as `error: <what>`.
class InputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

}  // namespace mesowave
