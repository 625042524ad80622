#pragma once
// The run summary as JSON (mw-dem writes it; keys end in their unit).
#include <nlohmann/json.hpp>

#include "mesowave/dem/simulation.hpp"

namespace mesowave::dem {

nlohmann::ordered_json to_json(const RunReport& report);

}  // namespace mesowave::dem
