#pragma once
// The pieces of an mw-fem run that are not the solver: where the burst is
// applied, where signals are recorded, the time step and sampling, the
// space-time record file and the cost report.
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/wave/fem_solver.hpp"

namespace mesowave::wave {

/// "S=0,0,1000" or "B=25,50,25/y": a named point in mm with an optional
/// component (x | y | z | r | normal).
struct SensorSpec {
  std::string name;
  std::array<double, 3> position_m{};
  std::string component;  ///< "" = the caller's default
};
SensorSpec parse_sensor_spec(const std::string& text);
/// "25,50,0" in mm -> metres.
std::array<double, 3> parse_point_mm(const std::string& text, const std::string& what);

/// The axis (0, 1, 2) of the box face a point lies on (within tol), and whether
/// it is the upper face; nullopt for an interior point.
std::optional<std::pair<int, bool>> box_face_of(const std::array<double, 3>& p, const std::array<double, 3>& size,
                                                double tol);

/// Probes at the nodes nearest the sensor points; InputError for a point
/// farther than one mesh size from any node (outside the body). A component
/// "normal" on a box needs `box_size`.
std::vector<Probe> make_probes(const FemModel& model, const std::vector<SensorSpec>& sensors, Quantity quantity,
                               const std::string& default_component,
                               const std::optional<std::array<double, 3>>& box_size = std::nullopt);

/// A force on the plane coordinate[axis] = value at `point` in direction `component`
/// (0, 1, 2) pointing `sign` (+1 or -1): on the nearest node if radius == 0,
/// else a uniform traction over the face cells within `radius` of the point.
BurstLoad make_load(const FemModel& model, int axis, double value, const std::array<double, 3>& point,
                    double patch_radius_m, int component, double sign, const signal::HannBurst& burst);

/// Time step and sampling: dt = sample_dt / stride with the smallest stride that
/// keeps dt <= the stable step, or the given dt (InputError above the stable step
/// or when the sampling interval is not a whole number of steps).
struct Stepping {
  double dt_s = 0, sample_dt_s = 0;
  std::int64_t steps = 0, stride = 1;
};
Stepping choose_stepping(const FemModel& model, double duration_s, double sample_dt_s,
                         std::optional<double> dt_s = std::nullopt);

/// Space-time record along a line of nodes: HDF5 with /spacetime/samples
/// [time, position], attributes t0_s, dt_s, quantity, unit, component and the
/// dataset position_m.
void write_spacetime_file(const std::filesystem::path& path, const std::vector<double>& samples,
                          const SpaceTimeRequest& request, double dt_s, const std::string& component,
                          const std::map<std::string, std::string>& attributes);

/// Axial dofs of the rod axis nodes every `step_m` along z (rod models).
SpaceTimeRequest rod_axis_line(const FemModel& model, double step_m, Quantity quantity);

}  // namespace mesowave::wave
