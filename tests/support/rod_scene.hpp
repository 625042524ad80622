#pragma once
// A chain scene of the tests' own: the rod paper's 1.03 R chain (Table 1), a force burst on the
// first sphere along the line, the acceleration of the last, 1.5 ms (the shipped rod scene's
// values; that one takes its transducers from lab-data/steel-rod/experiment.toml).
#include <filesystem>
#include <string>

namespace mesowave::test {

inline std::string rod_chain_scene_toml(const std::filesystem::path& packing) {
  return R"toml([scene]
name = "rod-wave"
[packing]
file = ")toml" + packing.string() + R"toml("
[material]
E_dem_GPa = 660.0
nu_dem = 0.3
damping = 0.0
bond_factor = 1.0
[time]
dt_ns = 50
duration_ms = 1.5
[[actuator]]
name = "A"
kind = "force"
sphere = "first"
direction = "line"
amplitude_N = 1.0
frequency_kHz = 100
cycles = 5
[[sensor]]
name = "S"
quantity = "acceleration"
component = "line"
sphere = "last"
)toml";
}

}  // namespace mesowave::test
