#pragma once
// One wave experiment as a lab sets it up, independent of any solver: the
// specimen (a box or a cylinder), the transducers on its surface (actuators
// and sensors), the burst that drives the actuators and the record the
// sensors take. One file per study, lab-data/<study>/experiment.toml
// (docs/formats.md), read here and nowhere else: the DEM scenes reference it
// ([experiment] file, dem/scene/scene.hpp), mw-fem box and mw-fem cylinder
// take it (--experiment, fem/case.hpp), and so does every later solver. A
// rod is a cylinder whose file prints its material (rod_of): mw-fem rod,
// mw-pack line, mw-calibrate rod and mw-dispersion take it (--experiment).
//
// Coordinates are the specimen's own frame, in metres: a box spans [0, X] x
// [0, Y] x [0, Z]; a cylinder has its axis along z through (D/2, D/2) and
// spans [0, D] x [0, D] x [0, L] (its bounding box; mw-pack's cylinder axis is
// z too). A transducer sits on a face: x-, x+, y-, y+, z-, z+ (a box's faces, a
// cylinder's flat ends are z- and z+) or "curved" (a cylinder's lateral face).
//
// Every numeric value carries its origin as lab-data files do: a table
// {value = ..., source = "paper" | "derived" | "assumed" | "placeholder", cite = "..."};
// a transducer's source and cite cover its whole placement.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/experiment/motion_quantity.hpp"

namespace mesowave::experiment {

struct Specimen {
  enum class Shape { box, cylinder } shape = Shape::box;
  std::array<double, 3> size_m{};  ///< the bounding box: a box's X, Y, Z; a cylinder's D, D, L
  std::optional<double> density_kg_m3;  ///< where the study knows it up front (a steel rod); else a solver's input
  std::optional<double> E_Pa, nu;       ///< the material's elastic constants, where they are printed (the rod)
  double radius_m() const { return 0.5 * size_m[0]; }  ///< cylinder
  double length_m() const { return size_m[2]; }        ///< cylinder: along z
  std::string describe() const;  ///< "50 x 50 x 50 mm box", "100 x 200 mm cylinder"
};

/// A transducer glued on the specimen: an actuator driven by the burst (a force
/// pushing along `direction`, "inward" = into the body) or a sensor recording
/// `quantity` (motion_quantity.hpp: acceleration | velocity | displacement) along `component`
/// ("normal" = the face's outward normal, or x | -x | y | ... | magnitude).
struct Transducer {
  enum class Role { actuator, sensor } role = Role::sensor;
  std::string name;
  std::string face;                ///< x- ... z+, or curved
  std::array<double, 3> centre_m{};  ///< on the face, in the specimen's frame
  std::array<double, 2> patch_m{};   ///< a box face: along its two in-plane axes in increasing order;
                                     ///< curved: around the circumference, along the axis
  MotionQuantity quantity = MotionQuantity::acceleration;  ///< sensors
  std::string component = "normal";       ///< sensors
  std::string direction = "inward";       ///< actuators
  std::string source, cite;
};

/// A Hann-windowed tone burst (signal/burst.hpp) of force on every actuator.
struct Burst {
  double frequency_hz = 0;  ///< the default centre frequency (a study sweeps it: --frequency-kHz)
  double cycles = 5;
  double amplitude_N = 0;
  double delay_s = 0;
};

/// What the sensors record: how long, and the sampling interval of the lab's
/// acquisition (a solver whose own step is finer may record every step; mw-pcc resamples).
struct Record {
  double duration_s = 0;
  double sample_interval_s = 0;
};

struct Experiment {
  std::filesystem::path source;  ///< the file it was read from, if any
  Specimen specimen;
  std::vector<Transducer> transducers;  ///< in file order
  Burst burst;
  Record record;
  std::vector<const Transducer*> actuators() const;
  std::vector<const Transducer*> sensors() const;
};

/// InputError (one line, naming the file, the table and the value) for bad TOML,
/// an unknown key, a value without its source, a transducer off its face or
/// outside it, a face the shape does not have, a duplicate name, no actuator or
/// no sensor.
Experiment parse_experiment(const std::string& text, const std::string& origin);
Experiment read_experiment_file(const std::filesystem::path& path);

/// The face's outward unit normal at the transducer's centre (a curved face's is radial there).
std::array<double, 3> outward_normal(const Specimen& specimen, const Transducer& t);
/// The azimuth (rad, from +x towards +y) of a point about a cylinder's axis.
double azimuth(const Specimen& specimen, const std::array<double, 3>& point_m);
/// A point as fractions of the specimen's bounding box (0 = lower face, 1 = upper face):
/// how a DEM scene places the transducers on a packing of any size.
std::array<double, 3> relative_position(const Specimen& specimen, const std::array<double, 3>& point_m);
/// The same experiment on a specimen `factor` times the size (positions scaled, patches
/// kept: they are the transducer's size), for a smaller model of the same test.
Experiment scaled(const Experiment& e, double factor);
/// The equal-area disc radius of a transducer's patch (a solver that loads discs).
double patch_disc_radius_m(const Transducer& t);

/// What every rod tool needs of an elastic rod, in SI: the specimen of a study that knows its
/// material up front (the rod paper, Section 4.1).
struct Rod {
  double radius_m = 0, length_m = 0;
  double E_Pa = 0, nu = 0, density_kg_m3 = 0;
};
/// The specimen as a rod: InputError, naming the file and what is missing, unless it is a
/// cylinder whose [specimen] gives E_GPa, nu and density_kg_m3.
Rod rod_of(const Experiment& e);
/// The same experiment on a cylinder of another length (the quick pipeline's shorter rod): the
/// diameter kept, every transducer at the same fraction of the length (an end stays an end),
/// as the DEM scene places transducers on a packing of another size. InputError for a box
/// or a length that is not positive.
Experiment with_length(const Experiment& e, double length_m);

}  // namespace mesowave::experiment
