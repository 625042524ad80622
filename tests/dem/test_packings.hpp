#pragma once
// Packings made in test code: a line of spheres (the rod), jittered
// face-centred-cubic blocks (a bonded network with polydisperse radii), and a
// few hand-placed cases. Not a packing generator: mw-pack is.
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "mesowave/dem/packing/packing.hpp"
#include "mesowave/dem/scene/scene.hpp"

namespace mesowave::dem::testing {

/// A deterministic uniform number in [0, 1).
class Lcg {
public:
  explicit Lcg(std::uint64_t seed) : state_(seed * 2862933555777941757ULL + 3037000493ULL) {}
  double next() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state_ >> 11) / double(1ULL << 53);
  }

private:
  std::uint64_t state_;
};

/// `count` spheres of radius r along x, centres spacing d apart from x = r.
inline Packing line_packing(std::size_t count, double r, double d, double density) {
  Packing p;
  for (std::size_t i = 0; i < count; ++i) {
    p.centres_m.push_back({r + double(i) * d, 0.0, 0.0});
    p.radii_m.push_back(r);
    p.ids.push_back(std::int64_t(i));
  }
  p.container.shape = "line";
  p.container.lower_m = {0, -r, -r};
  p.container.upper_m = {2 * r + double(count - 1) * d, r, r};
  p.particle_density_kg_m3 = density;
  return p;
}

/// An FCC block of cells x cells x cells unit cells of side `a` (4 spheres
/// each, lower corner at `a/2`), radii uniform in [r_min, r_max], centres
/// moved by up to `jitter` times a in each direction. Nearest neighbours sit
/// a/sqrt(2) apart.
inline Packing fcc_packing(int cells, double a, double r_min, double r_max, double jitter, std::uint64_t seed,
                           double density) {
  Packing p;
  Lcg rng(seed);
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  std::int64_t id = 0;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int k = 0; k < cells; ++k)
        for (const auto& b : basis) {
          std::array<double, 3> c = {(i + b[0]) * a + 0.5 * a, (j + b[1]) * a + 0.5 * a, (k + b[2]) * a + 0.5 * a};
          for (double& x : c) x += jitter * a * (2 * rng.next() - 1);
          p.centres_m.push_back(c);
          p.radii_m.push_back(r_min + (r_max - r_min) * rng.next());
          p.ids.push_back(id++);
        }
  const double side = cells * a + 0.5 * a;  // the outermost centres sit a/2 inside
  p.container.shape = "box";
  p.container.lower_m = {0, 0, 0};
  p.container.upper_m = {side, side, side};
  p.particle_density_kg_m3 = density;
  return p;
}

/// Concrete-like material (the paper's calibrated values).
inline CohesiveFrictionalMaterial concrete_material(bool breakable = true) {
  CohesiveFrictionalMaterial m;
  m.E_dem_Pa = 23.31e9;
  m.stiffness_ratio = 0.32;
  m.friction_angle_rad = 18.0 * 3.14159265358979323846 / 180.0;
  if (breakable) {
    m.tensile_strength_Pa = 24.4e6;
    m.cohesion_Pa = 24.4e6;
  }
  m.density_kg_m3 = 2290.0;
  m.damping = 0.0;
  m.bond_factor = 1.1;
  return m;
}

/// A scene on `packing` with no actuators yet; `sensors` get added by the test.
inline Scene bare_scene(const CohesiveFrictionalMaterial& m, double dt, double duration) {
  Scene s;
  s.name = "test";
  s.material = m;
  s.density_given = true;
  s.dt_s = dt;
  s.duration_s = duration;
  return s;
}

inline SphereTarget patch_target(const char* face, std::array<double, 3> centre, double size) {
  SphereTarget t;
  t.kind = SphereTarget::Kind::patch;
  t.patch.face = Face::parse(face);
  t.patch.centre_m = {centre[0], centre[1], centre[2]};
  t.patch.size_m[0] = t.patch.size_m[1] = size;
  return t;
}

inline SphereTarget end_target(bool last) {
  SphereTarget t;
  t.kind = SphereTarget::Kind::end;
  t.last = last;
  return t;
}

inline ActuatorSpec force_burst(const char* name, SphereTarget target, const char* direction, double amplitude_N,
                                double frequency_hz, double cycles = 5) {
  ActuatorSpec a;
  a.name = name;
  a.kind = "force";
  a.target = target;
  a.direction = direction;
  a.amplitude = amplitude_N;
  a.frequency_hz = frequency_hz;
  a.cycles = cycles;
  return a;
}

inline SensorSpec motion_sensor(const char* name, SphereTarget target, MotionQuantity q, const char* component) {
  SensorSpec s;
  s.name = name;
  s.quantity = q;
  s.target = target;
  s.component = component;
  return s;
}

/// FCC blocks for crushing_scene_toml: 4 cells^3 spheres, radii 0.66-0.74 mm on a 2 mm cell.
inline Packing crushing_block(int cells) { return fcc_packing(cells, 2.0e-3, 0.66e-3, 0.74e-3, 0.02, 7, 2290); }

/// A compression to failure of a crushing_block between walls on z (the shipped
/// cube-compression scene's sensors and [test], made fast): the upper wall at
/// 0.5 m/s crushes the block within a few thousand steps, so bonds break, contacts
/// are detected and the stop rule watches the peak (3 cells: 3206 steps, 52 of
/// 448 bonds broken, the stop 50 % below the peak).
inline std::string crushing_scene_toml(const std::string& packing_file) {
  std::string text = R"(
[packing]
file = "PACKING"
[material]
E_dem_GPa = 23.31
nu_dem = 0.32
friction_angle_deg = 18.0
T_MPa = 24.4
C_MPa = 24.4
damping = 0.08
bond_factor = 1.1
[time]
dt_ns = 40
duration_ms = 0.3
[model]
choice = "full"
[[actuator]]
name = "bottom"
kind = "wall"
face = "z-"
[[actuator]]
name = "top"
kind = "wall"
face = "z+"
velocity_mm_s = 500.0
ramp_us = 20
[[sensor]]
name = "P_top"
quantity = "force"
actuator = "top"
sample_interval_ns = 200
[[sensor]]
name = "P_bottom"
quantity = "force"
actuator = "bottom"
sample_interval_ns = 200
[[sensor]]
name = "V"
quantity = "strain"
component = "z"
face = "x-"
centre_rel = [0.0, 0.5, 0.5]
gauge_rel = 0.5
patch_mm = [3.0, 3.0]
sample_interval_ns = 200
[[sensor]]
name = "broken"
quantity = "broken_bonds"
sample_interval_ns = 200
[test]
kind = "compression"
load = ["P_top", "P_bottom"]
axial = ["V"]
broken_bonds = "broken"
stop_drop_pct = 50.0
stop_armed_above_MPa = 1.0
inertial_number_bound = 0.0
)";
  text.replace(text.find("PACKING"), 7, packing_file);
  return text;
}

/// n x n x n equal spheres of radius r touching on a simple cubic lattice (each column a chain of
/// bonds): E_glob = E_dem / 2 and nu_glob = 0 in closed form.
inline Packing simple_cubic_packing(int n, double r, double density) {
  Packing p;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        p.centres_m.push_back({r * (1 + 2 * i), r * (1 + 2 * j), r * (1 + 2 * k)});
        p.radii_m.push_back(r);
        p.ids.push_back(std::int64_t(p.ids.size()));
      }
  p.container.upper_m = {2 * r * n, 2 * r * n, 2 * r * n};
  p.particle_density_kg_m3 = density;
  return p;
}

/// A compression test of a small lattice: walls on z, a vertical and a horizontal extensometer on the
/// face x-; `modulus_levels` is the [test] line that sets the levels (in % of the peak or in MPa).
inline std::string lattice_compression_toml(const std::string& modulus_levels) {
  std::string text = R"(
[packing]
file = "unused.h5"
[material]
E_dem_GPa = 20.0
nu_dem = 0.3
damping = 0.1
bond_factor = 1.05
[time]
dt_ns = 20
duration_ms = 0.8
[[actuator]]
name = "bottom"
kind = "wall"
face = "z-"
[[actuator]]
name = "top"
kind = "wall"
face = "z+"
velocity_mm_s = 10.0
ramp_us = 100
[[sensor]]
name = "P_top"
quantity = "force"
actuator = "top"
sample_interval_ns = 1000
[[sensor]]
name = "P_bottom"
quantity = "force"
actuator = "bottom"
sample_interval_ns = 1000
[[sensor]]
name = "V"
quantity = "strain"
component = "z"
face = "x-"
centre_rel = [0.0, 0.5, 0.5]
gauge_rel = 0.5
patch_mm = [3.0, 1.5]
sample_interval_ns = 1000
[[sensor]]
name = "H"
quantity = "strain"
component = "y"
face = "x-"
centre_rel = [0.0, 0.5, 0.5]
gauge_rel = 0.5
patch_mm = [1.5, 3.0]
sample_interval_ns = 1000
[test]
kind = "compression"
load = ["P_top", "P_bottom"]
axial = ["V"]
lateral = ["H"]
MODULUS_LEVELS
inertial_number_bound = 0.0
)";
  text.replace(text.find("MODULUS_LEVELS"), 14, modulus_levels);
  return text;
}

}  // namespace mesowave::dem::testing
