#pragma once
// VTK XML files ParaView opens: PolyData (.vtp) with points, vertex and line cells, point and cell
// data in ASCII, and the .pvd collection that orders files in time. One writer for every solver's
// snapshots (the DEM's spheres, the EFG's nodes and cracks); format: "VTK File Formats", VTK User's
// Guide (Kitware), Section "XML File Formats".
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace mesowave::io {

/// A data array: `components` values per tuple, Float64 from `values` or, when `integer`, Int64
/// from `integers`. Scalars go on one line, vectors and tensors one tuple per line.
struct VtkArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
  bool integer = false;
  std::vector<std::int64_t> integers;
};

struct VtkPolyData {
  std::vector<std::array<double, 3>> points;
  std::vector<std::int64_t> verts;               ///< one vertex cell per listed point
  std::vector<std::vector<std::int64_t>> lines;  ///< one polyline cell per entry
  std::vector<VtkArray> point_data;
  std::vector<VtkArray> cell_data;               ///< per cell: the vertices first, then the lines (VTK's order)
  std::string active_scalars, active_vectors;    ///< PointData's Scalars= / Vectors= ("" for none)
  bool has_time = false;
  double time_s = 0;                             ///< FieldData TimeValue when has_time
};

/// std::runtime_error when the file cannot be written; std::invalid_argument when an array's
/// length is not its tuple count times its components.
void write_vtp(const std::filesystem::path& path, const VtkPolyData& data);

/// A .pvd entry: time, part (several files of one instant), file name relative to the .pvd's folder.
struct PvdEntry {
  double time_s = 0;
  int part = 0;
  std::string file;
};
void write_pvd(const std::filesystem::path& path, const std::vector<PvdEntry>& entries);

}  // namespace mesowave::io
