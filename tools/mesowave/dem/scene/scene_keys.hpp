#pragma once
// One table of a scene file as its readers see it (scene.cpp and the
// actuator and sensor kinds that read their own keys, plugins.hpp): every key
// read is marked, and finish() names any key left over, so a typo is an error
// and never a silent default.
#include "mesowave/io/toml_keys.hpp"

namespace mesowave::dem {

using SceneKeys = io::TomlKeys;

}  // namespace mesowave::dem
