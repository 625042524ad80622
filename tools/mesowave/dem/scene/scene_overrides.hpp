#pragma once
// What mw-dem's options change in a scene before it runs: the packing file,
// any [material] parameter (material_parameters.hpp: --E-dem-GPa, --nu-dem,
// ...; mw-calibrate's --from JSON fills them), unbreakable bonds, every
// burst's frequency, the time step and duration, the snapshot interval, every
// moving platen's speed and a [test]'s stop stress and modulus levels.
// Each value is checked as the scene file's own value is, and an error names
// the option.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "mesowave/dem/scene/scene.hpp"

namespace mesowave::dem {

struct SceneOverrides {
  std::filesystem::path packing;        ///< empty: the scene's [packing] file
  std::map<std::string, double> material;  ///< material_parameters() key -> value in the key's unit
  bool unbreakable = false;             ///< no T, C: bonds never break
  std::string damping_law;              ///< empty: the scene's [model] damping_law
  // 0 (or empty, or a negative snapshot interval): keep the scene's value.
  double frequency_kHz = 0, dt_ns = 0, duration_ms = 0, snapshot_us = -1, stop_at_MPa = 0, velocity_mm_s = 0;
  std::vector<double> modulus_levels_MPa;  ///< two stresses, or none
  bool curves = false;                     ///< a [test]'s curves are asked for: the scene needs a [test]
};

/// The options that fill `o` (one per override, named as in mw-dem's --help).
void add_override_options(CLI::App& app, SceneOverrides& o);

/// Applies `o` to `scene`; InputError naming the option for a value out of
/// range or an override the scene cannot take (--stop-at-MPa without a [test]).
void apply_overrides(Scene& scene, const SceneOverrides& o);

}  // namespace mesowave::dem
