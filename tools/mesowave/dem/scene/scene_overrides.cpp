#include "mesowave/dem/scene/scene_overrides.hpp"

#include <algorithm>
#include <limits>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/dem/contact/material_parameters.hpp"
#include "mesowave/dem/scene/plugins.hpp"

namespace mesowave::dem {

void add_override_options(CLI::App& app, SceneOverrides& o) {
  app.add_option("--packing", o.packing, "Packing file to use instead of the scene's [packing] file");
  app.add_option("--frequency-kHz", o.frequency_kHz, "Centre frequency of every actuator's burst [kHz]");
  app.add_option("--dt-ns", o.dt_ns, "Time step instead of the scene's [ns]");
  app.add_option("--duration-ms", o.duration_ms, "Duration instead of the scene's [ms]");
  for (const MaterialParameter& p : material_parameters())
    if (!p.option.empty())
      app.add_option_function<double>(p.option, [&o, key = p.key](double v) { o.material[key] = v; },
                                      p.meaning + " (beats the scene's [material]; --from mw-calibrate's JSON fills it)");
  app.add_option("--damping-law", o.damping_law,
                 "local (Eq. 7, alpha_d) | viscous (mass-proportional, c = 4 alpha_d f_c: the same amplitude loss "
                 "per cycle at the bursts' centre frequency, linear) instead of the scene's [model] damping_law")
      ->check(CLI::IsMember({"local", "viscous"}));
  app.add_flag("--unbreakable-bonds", o.unbreakable,
               "Bonds never break (no T, C): the elastic response (mw-calibrate's elastic trials)");
  app.add_option("--stop-at-MPa", o.stop_at_MPa, "A [test] ends once its stress reaches this [MPa]");
  app.add_option("--velocity-mm-s", o.velocity_mm_s,
                 "Every moving platen or wall (velocity, wall actuators with a velocity) at this speed instead [mm/s]");
  app.add_option("--modulus-levels-MPa", o.modulus_levels_MPa,
                 "A [test]'s secant modulus between these two stresses [MPa] instead of the scene's levels")
      ->expected(2)
      ->delimiter(',');
}

void apply_overrides(Scene& scene, const SceneOverrides& o) {
  if (!o.packing.empty()) scene.packing_file = o.packing;
  for (const auto& [key, value] : o.material) set_material_value(scene, key, value, material_parameter(key).option);
  if (o.velocity_mm_s != 0) {
    require_positive("--velocity-mm-s", o.velocity_mm_s, "mm/s");
    for (auto& a : scene.actuators)
      if (actuator_kinds().get(a.kind, "actuator " + a.name).moving && a.amplitude != 0)
        a.amplitude = o.velocity_mm_s * units::mm;
  }
  if (!o.damping_law.empty()) scene.damping_law = o.damping_law;
  if (o.unbreakable)
    scene.material.tensile_strength_Pa = scene.material.cohesion_Pa = std::numeric_limits<double>::infinity();
  if ((o.stop_at_MPa != 0 || !o.modulus_levels_MPa.empty()) && !scene.test.active())
    throw InputError("--stop-at-MPa and --modulus-levels-MPa need a scene with a [test] table");
  if (o.stop_at_MPa != 0) scene.test.stop_at_Pa = require_positive("--stop-at-MPa", o.stop_at_MPa, "MPa") * units::MPa;
  if (!o.modulus_levels_MPa.empty()) {
    const auto& v = o.modulus_levels_MPa;
    if (v.size() != 2 || !(v[0] >= 0 && v[1] > v[0]))
      throw InputError("--modulus-levels-MPa (" + format_number(v[0]) + ", " + format_number(v.back()) +
                       ") must rise from a lower to an upper stress");
    scene.test.levels_absolute = true;
    scene.test.levels[0] = v[0] * units::MPa;
    scene.test.levels[1] = v[1] * units::MPa;
  }
  if (o.frequency_kHz != 0)
    for (auto& a : scene.actuators) a.frequency_hz = require_positive("--frequency-kHz", o.frequency_kHz, "kHz") * units::kHz;
  if (o.dt_ns != 0) scene.dt_s = require_positive("--dt-ns", o.dt_ns, "ns") * units::ns;
  if (o.duration_ms != 0) scene.duration_s = require_positive("--duration-ms", o.duration_ms, "ms") * units::ms;
  if (o.snapshot_us >= 0) scene.snapshot_interval_s = o.snapshot_us * units::us;
  if (o.curves && !scene.test.active())
    throw InputError("--curves needs a scene with a [test] table (a compression or tension test)");
}

}  // namespace mesowave::dem
