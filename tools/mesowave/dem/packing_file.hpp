#pragma once
// Packing files (HDF5), written by mw-pack and read by mw-dem:
//
//   /centres_m   float64 [n, 3]
//   /radii_m     float64 [n]
//   /ids         int64   [n]
//   root attributes: format = "mesowave-packing", format_version = 1,
//     container_shape (box | cylinder | line), container_lower_m, container_upper_m (float64[3]),
//     container_radius_m, particle_density_kg_m3 (0 if not chosen)
#include <filesystem>

#include "mesowave/dem/packing.hpp"

namespace mesowave::dem {

void write_packing_file(const std::filesystem::path& path, const Packing& packing);
/// InputError for a missing file, another kind of file, or inconsistent sizes.
Packing read_packing_file(const std::filesystem::path& path);

}  // namespace mesowave::dem
