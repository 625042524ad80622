#include "mesowave/dem/engine/snapshot.hpp"

#include "mesowave/io/vtk_xml.hpp"

namespace mesowave::dem {

void write_vtp(const std::filesystem::path& path, const Model& model, double t_s) {
  const std::size_t n = model.sphere_count();
  io::VtkPolyData d;
  d.has_time = true;
  d.time_s = t_s;
  d.active_scalars = "radius";
  d.active_vectors = "velocity";
  io::VtkArray radius{"radius", 1, {}, false, {}}, index{"packing_index", 1, {}, true, {}};
  io::VtkArray displacement{"displacement", 3, {}, false, {}}, velocity{"velocity", 3, {}, false, {}};
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 u = model.displacement(k), v = model.velocity(k);
    const Vec3 x = model.reference_position(k) + u;
    d.points.push_back({x.x, x.y, x.z});
    d.verts.push_back(std::int64_t(k));
    radius.values.push_back(model.radius(k));
    index.integers.push_back(std::int64_t(model.packing_index(k)));
    displacement.values.insert(displacement.values.end(), {u.x, u.y, u.z});
    velocity.values.insert(velocity.values.end(), {v.x, v.y, v.z});
  }
  d.point_data = {radius, index, displacement, velocity};
  io::write_vtp(path, d);
}

void write_pvd(const std::filesystem::path& path, const std::vector<std::pair<double, std::string>>& entries) {
  std::vector<io::PvdEntry> pvd;
  for (const auto& [t, file] : entries) pvd.push_back({t, 0, file});
  io::write_pvd(path, pvd);
}

}  // namespace mesowave::dem
