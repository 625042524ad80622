#pragma once
// Packing files (HDF5), written by mw-pack and read by mw-dem:
//
//   /centres_m   float64 [n, 3]
//   /radii_m     float64 [n]
//   /ids         int64   [n]
//   root attributes: format = "mesowave-packing", format_version = 1,
//     container_shape (box | cylinder | line), container_lower_m, container_upper_m (float64[3]),
//     container_radius_m, particle_density_kg_m3 (0 if not chosen)
//   /origin      optional group; its attributes record how the packing was made
//                (mw-pack writes method, seed, targets, size distribution, ...);
//                readers that do not know it ignore it (format_version stays 1).
//
// Containers: a box is its lower and upper corners. A cylinder has its axis
// parallel to z through the centre of its x-y bounding box; lower/upper are
// that bounding box (so x and y span 2 R) and the axis runs from lower z to
// upper z. A line (the rod model) is stored like a cylinder: the rod it
// stands for (radius = rod radius), the spheres on its axis.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "mesowave/dem/packing/packing.hpp"

namespace mesowave::dem {

void write_packing_file(const std::filesystem::path& path, const Packing& packing);

/// How a packing was made: attributes of the /origin group, text and numbers.
struct PackingOrigin {
  std::vector<std::pair<std::string, std::string>> text;
  std::vector<std::pair<std::string, double>> numbers;
  bool empty() const { return text.empty() && numbers.empty(); }
};
/// Writes the packing and, under /origin, how it was made.
void write_packing_file(const std::filesystem::path& path, const Packing& packing, const PackingOrigin& origin);
/// The /origin attributes (empty if the file has none), in name order.
PackingOrigin read_packing_origin(const std::filesystem::path& path);
/// InputError for a missing file, another kind of file, or inconsistent sizes.
Packing read_packing_file(const std::filesystem::path& path);
/// Part `part` of `parts` of the file's spheres: rows [n part / parts, n (part + 1) / parts),
/// read as hyperslabs (an MPI rank's share: docs/mpi.md), with the container and density.
Packing read_packing_file(const std::filesystem::path& path, int part, int parts);

}  // namespace mesowave::dem
