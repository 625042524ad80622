#include "mesowave/dem/engine/snapshot.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace mesowave::dem {
namespace {

void put(std::ofstream& out, double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g ", v);
  out << text;
}

}  // namespace

void write_vtp(const std::filesystem::path& path, const Model& model, double t_s) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  const std::size_t n = model.sphere_count();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n";
  out << "<FieldData><DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">";
  put(out, t_s);
  out << "</DataArray></FieldData>\n";
  out << "<Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n << "\">\n<Points>\n";
  out << "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 x = model.reference_position(k) + model.displacement(k);
    put(out, x.x), put(out, x.y), put(out, x.z);
    out << '\n';
  }
  out << "</DataArray>\n</Points>\n<PointData Scalars=\"radius\" Vectors=\"velocity\">\n";
  out << "<DataArray type=\"Float64\" Name=\"radius\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < n; ++k) put(out, model.radius(k));
  out << "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"packing_index\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < n; ++k) out << model.packing_index(k) << ' ';
  out << "\n</DataArray>\n";
  const char* names[2] = {"displacement", "velocity"};
  for (int q = 0; q < 2; ++q) {
    out << "<DataArray type=\"Float64\" Name=\"" << names[q] << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3 v = q == 0 ? model.displacement(k) : model.velocity(k);
      put(out, v.x), put(out, v.y), put(out, v.z);
      out << '\n';
    }
    out << "</DataArray>\n";
  }
  out << "</PointData>\n<Verts>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < n; ++k) out << k << ' ';
  out << "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < n; ++k) out << k + 1 << ' ';
  out << "\n</DataArray>\n</Verts>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void write_pvd(const std::filesystem::path& path, const std::vector<std::pair<double, std::string>>& entries) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [t, file] : entries) {
    char time[32];
    std::snprintf(time, sizeof time, "%.9g", t);
    out << "<DataSet timestep=\"" << time << "\" part=\"0\" file=\"" << file << "\"/>\n";
  }
  out << "</Collection>\n</VTKFile>\n";
}

}  // namespace mesowave::dem
