#pragma once
// Snapshots ParaView opens: one VTK XML PolyData file (.vtp) per instant,
// spheres as points with radius, id, displacement and velocity, and a .pvd
// collection that orders them in time (open the .pvd; render the points as
// spheres with the Point Gaussian representation scaled by "radius").
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "mesowave/dem/engine/model.hpp"

namespace mesowave::dem {

void write_vtp(const std::filesystem::path& path, const Model& model, double t_s);
/// `entries`: (time, file name relative to the .pvd's folder).
void write_pvd(const std::filesystem::path& path, const std::vector<std::pair<double, std::string>>& entries);

}  // namespace mesowave::dem
