#pragma once
// A packing of spheres: what mw-pack writes and the DEM engine starts from.
// Positions and radii in metres; ids are stable labels (sensors and
// actuators refer to spheres by position, not id, but ids survive the
// space-filling-curve renumbering the engine does for speed).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace mesowave::dem {

/// The container a packing was made for (its porosity refers to it).
struct Container {
  std::string shape = "box";              ///< box | cylinder | line
  std::array<double, 3> lower_m{0, 0, 0}; ///< box: lower corner
  std::array<double, 3> upper_m{0, 0, 0}; ///< box: upper corner
  double radius_m = 0;                    ///< cylinder: radius (axis along z from lower to upper)
};

struct Packing {
  std::vector<std::array<double, 3>> centres_m;
  std::vector<double> radii_m;
  std::vector<std::int64_t> ids;
  Container container;
  double particle_density_kg_m3 = 0;  ///< 0 if not chosen yet
  /// A piece of a packing file (read_packing_file's part of several): its rows
  /// [first_row, first_row + size()) of file_rows. A whole packing: 0 and 0.
  std::size_t first_row = 0, file_rows = 0;

  std::size_t size() const { return radii_m.size(); }
  bool is_piece() const { return file_rows != 0; }
};

}  // namespace mesowave::dem
