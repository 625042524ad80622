#pragma once
// Choosing signals from a file by name, as the tools' --signals option does.
#include <string>
#include <string_view>
#include <vector>

#include "mesowave/signal/signal.hpp"

namespace mesowave::signal {

/// The signals named in `names`, in that order; all of them if `names` is
/// empty. InputError naming `origin` and the names it has for a name it lacks.
std::vector<Signal> select_signals(const std::vector<Signal>& all, const std::vector<std::string>& names,
                                   std::string_view origin);

}  // namespace mesowave::signal
