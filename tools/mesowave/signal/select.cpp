#include "mesowave/signal/select.hpp"

#include "mesowave/core/error.hpp"

namespace mesowave::signal {

std::vector<Signal> select_signals(const std::vector<Signal>& all, const std::vector<std::string>& names,
                                   std::string_view origin) {
  if (all.empty()) throw InputError(std::string(origin) + " holds no signals");
  if (names.empty()) return all;
  std::vector<Signal> chosen;
  for (const auto& name : names) {
    bool found = false;
    for (const auto& s : all)
      if (s.name == name) {
        chosen.push_back(s);
        found = true;
        break;
      }
    if (!found) {
      std::string have;
      for (const auto& s : all) have += (have.empty() ? "" : ", ") + s.name;
      throw InputError(std::string(origin) + " has no signal '" + name + "' (it has " + have + ")");
    }
  }
  return chosen;
}

}  // namespace mesowave::signal
