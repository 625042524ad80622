#include "mesowave/io/vtk_xml.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace mesowave::io {
namespace {

void put(std::ofstream& out, double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g ", v);
  out << text;
}

void put_array(std::ofstream& out, const VtkArray& a, std::size_t tuples, const std::string& where) {
  const std::size_t n = a.integer ? a.integers.size() : a.values.size();
  if (a.components < 1 || n != tuples * std::size_t(a.components))
    throw std::invalid_argument(where + " array " + a.name + " has " + std::to_string(n) + " values for " +
                                std::to_string(tuples) + " tuples of " + std::to_string(a.components));
  out << "<DataArray type=\"" << (a.integer ? "Int64" : "Float64") << "\" Name=\"" << a.name << '"';
  if (a.components > 1) out << " NumberOfComponents=\"" << a.components << '"';
  out << " format=\"ascii\">\n";
  for (std::size_t k = 0; k < n; ++k) {
    if (a.integer) out << a.integers[k] << ' ';
    else put(out, a.values[k]);
    if (a.components > 1 && (k + 1) % std::size_t(a.components) == 0) out << '\n';
  }
  out << (a.components > 1 ? "" : "\n") << "</DataArray>\n";
}

void put_cells(std::ofstream& out, const char* tag, const std::vector<std::vector<std::int64_t>>& cells) {
  out << '<' << tag << ">\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& c : cells)
    for (auto p : c) out << p << ' ';
  out << "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::int64_t offset = 0;
  for (const auto& c : cells) out << (offset += std::int64_t(c.size())) << ' ';
  out << "\n</DataArray>\n</" << tag << ">\n";
}

}  // namespace

void write_vtp(const std::filesystem::path& path, const VtkPolyData& d) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  const std::size_t n = d.points.size(), cells = d.verts.size() + d.lines.size();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n";
  if (d.has_time) {
    out << "<FieldData><DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">";
    put(out, d.time_s);
    out << "</DataArray></FieldData>\n";
  }
  out << "<Piece NumberOfPoints=\"" << n << '"';
  if (!d.verts.empty() || d.lines.empty()) out << " NumberOfVerts=\"" << d.verts.size() << '"';
  if (!d.lines.empty()) out << " NumberOfLines=\"" << d.lines.size() << '"';
  out << ">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& x : d.points) {
    put(out, x[0]), put(out, x[1]), put(out, x[2]);
    out << '\n';
  }
  out << "</DataArray>\n</Points>\n<PointData";
  if (!d.active_scalars.empty()) out << " Scalars=\"" << d.active_scalars << '"';
  if (!d.active_vectors.empty()) out << " Vectors=\"" << d.active_vectors << '"';
  out << ">\n";
  for (const auto& a : d.point_data) put_array(out, a, n, "point");
  out << "</PointData>\n";
  if (!d.cell_data.empty()) {
    out << "<CellData>\n";
    for (const auto& a : d.cell_data) put_array(out, a, cells, "cell");
    out << "</CellData>\n";
  }
  if (!d.verts.empty()) {
    std::vector<std::vector<std::int64_t>> verts;
    verts.reserve(d.verts.size());
    for (auto p : d.verts) verts.push_back({p});
    put_cells(out, "Verts", verts);
  }
  if (!d.lines.empty()) put_cells(out, "Lines", d.lines);
  out << "</Piece>\n</PolyData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void write_pvd(const std::filesystem::path& path, const std::vector<PvdEntry>& entries) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& e : entries) {
    char time[32];
    std::snprintf(time, sizeof time, "%.9g", e.time_s);
    out << "<DataSet timestep=\"" << time << "\" part=\"" << e.part << "\" file=\"" << e.file << "\"/>\n";
  }
  out << "</Collection>\n</VTKFile>\n";
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace mesowave::io
