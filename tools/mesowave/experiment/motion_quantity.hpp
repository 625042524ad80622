#pragma once
// What a motion sensor records: the one name of the concept for the lab's
// transducers (experiment.hpp, Transducer::quantity), the DEM's motion sensors
// (dem/loading/motion_sensor.hpp) and the FEM's probes (fem/solver.hpp). It
// lives in experiment/ because the quantity is a property of the test as set
// up, not of a model of it, and both solvers may depend on experiment/ (never
// on each other: docs/architecture.md). The names are those of the signal
// files' `quantity` attribute (signal/signal_file.hpp, signal/signal_csv.hpp),
// the units those of their `unit` attribute, SI.
//
// A signal's quantity stays a string (signal::Signal::quantity): a signal file
// also holds force, strain, voltage, envelopes... which no motion sensor records.
#include <array>
#include <string>

namespace mesowave::experiment {

enum class MotionQuantity { acceleration, velocity, displacement };

/// Every value, in the order the error messages list them.
inline constexpr std::array<MotionQuantity, 3> motion_quantities{MotionQuantity::acceleration, MotionQuantity::velocity,
                                                                 MotionQuantity::displacement};

/// "acceleration" | "velocity" | "displacement"; InputError otherwise, one line
/// naming `who` (the key or option it came from): `who ("strain") must be acceleration, velocity or displacement`.
MotionQuantity parse_motion_quantity(const std::string& text, const std::string& who);
/// The name parse_motion_quantity reads (and a signal file's quantity attribute).
std::string to_string(MotionQuantity q);
/// Its SI unit as signal files write it: m/s^2, m/s, m.
std::string si_unit(MotionQuantity q);

}  // namespace mesowave::experiment
