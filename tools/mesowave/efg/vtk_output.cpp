#include "mesowave/efg/vtk_output.hpp"

#include <Eigen/Eigenvalues>
#include <stdexcept>

#include "mesowave/core/units.hpp"
#include "mesowave/io/vtk_xml.hpp"

namespace mesowave::efg {

std::size_t CrackSnapshot::segment_count() const {
  std::size_t n = 0;
  for (const auto& p : polylines) n += p.size() > 1 ? p.size() - 1 : 0;
  return n;
}

void write_node_vtp(const std::filesystem::path& path, const NodeSnapshot& nodes, double step_time) {
  const std::size_t n = nodes.positions_m.size();
  if (nodes.displacement_m.size() != n || (!nodes.stress_Pa.empty() && nodes.stress_Pa.size() != n))
    throw std::invalid_argument("node snapshot: " + std::to_string(n) + " nodes, " +
                                std::to_string(nodes.displacement_m.size()) + " displacements, " +
                                std::to_string(nodes.stress_Pa.size()) + " stresses");
  io::VtkPolyData d;
  d.has_time = true;
  d.time_s = step_time;
  d.active_vectors = "displacement";
  io::VtkArray u{"displacement", 3, {}, false, {}}, stress{"stress", 6, {}, false, {}},
      principal{"max_principal_stress", 1, {}, false, {}};
  for (std::size_t k = 0; k < n; ++k) {
    d.points.push_back({nodes.positions_m[k].x(), nodes.positions_m[k].y(), 0.0});
    d.verts.push_back(std::int64_t(k));
    u.values.insert(u.values.end(), {nodes.displacement_m[k].x(), nodes.displacement_m[k].y(), 0.0});
    if (nodes.stress_Pa.empty()) continue;
    const Eigen::Vector3d& s = nodes.stress_Pa[k];
    stress.values.insert(stress.values.end(), {s(0), s(1), 0.0, s(2), 0.0, 0.0});
    Eigen::Matrix2d m;
    m << s(0), s(2), s(2), s(1);
    principal.values.push_back(Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(m, Eigen::EigenvaluesOnly).eigenvalues()(1));
  }
  d.point_data.push_back(u);
  if (!nodes.stress_Pa.empty()) {
    d.active_scalars = "max_principal_stress";
    d.point_data.push_back(stress);
    d.point_data.push_back(principal);
  }
  io::write_vtp(path, d);
}

void write_crack_vtp(const std::filesystem::path& path, const CrackSnapshot& cracks, double step_time) {
  const std::size_t segments = cracks.segment_count();
  for (const auto* v : {&cracks.opening_m, &cracks.traction_Pa, &cracks.damage})
    if (!v->empty() && v->size() != segments)
      throw std::invalid_argument("crack snapshot: " + std::to_string(segments) + " segments, " +
                                  std::to_string(v->size()) + " values");
  io::VtkPolyData d;
  d.has_time = true;
  d.time_s = step_time;
  for (const auto& line : cracks.polylines) {
    const auto first = std::int64_t(d.points.size());
    for (const auto& x : line) d.points.push_back({x.x(), x.y(), 0.0});
    for (std::size_t k = 0; k + 1 < line.size(); ++k) d.lines.push_back({first + std::int64_t(k), first + std::int64_t(k) + 1});
  }
  auto scaled = [](std::vector<double> v, double factor) {
    for (double& x : v) x *= factor;
    return v;
  };
  if (!cracks.opening_m.empty()) d.cell_data.push_back({"opening_mm", 1, scaled(cracks.opening_m, 1 / units::mm), false, {}});
  if (!cracks.traction_Pa.empty()) d.cell_data.push_back({"traction_MPa", 1, scaled(cracks.traction_Pa, 1 / units::MPa), false, {}});
  if (!cracks.damage.empty()) d.cell_data.push_back({"damage", 1, cracks.damage, false, {}});
  io::write_vtp(path, d);
}

void write_point_vtp(const std::filesystem::path& path, const PointCloudSnapshot& points, double step_time) {
  const std::size_t n = points.positions_m.size();
  io::VtkPolyData d;
  d.has_time = true;
  d.time_s = step_time;
  for (std::size_t k = 0; k < n; ++k) {
    d.points.push_back({points.positions_m[k].x(), points.positions_m[k].y(), 0.0});
    d.verts.push_back(std::int64_t(k));
  }
  for (const auto& [name, values] : points.scalars) {
    if (values.size() != n)
      throw std::invalid_argument("point snapshot: " + std::to_string(n) + " points, " + std::to_string(values.size()) +
                                  " values of " + name);
    d.point_data.push_back({name, 1, values, false, {}});
  }
  if (!points.scalars.empty()) d.active_scalars = points.scalars.front().first;
  io::write_vtp(path, d);
}

VtkSeries::VtkSeries(std::filesystem::path folder, std::string stem, OutputPath output)
    : folder_(std::move(folder)), stem_(std::move(stem)), output_(std::move(output)) {
  if (!output_) output_ = [](const std::filesystem::path& p) { return p; };
}

void VtkSeries::add(double step_time, const NodeSnapshot& nodes, const CrackSnapshot& cracks, const PointCloudSnapshot* points) {
  const std::string k = std::to_string(steps_.size());
  if (!steps_.empty() && points_ != (points != nullptr))
    throw std::invalid_argument("VTK series: point snapshots at some steps but not at others");
  points_ = points != nullptr;
  write_node_vtp(output_(folder_ / (stem_ + "-nodes-" + k + ".vtp")), nodes, step_time);
  write_crack_vtp(output_(folder_ / (stem_ + "-cracks-" + k + ".vtp")), cracks, step_time);
  if (points) write_point_vtp(output_(folder_ / (stem_ + "-points-" + k + ".vtp")), *points, step_time);
  steps_.push_back(step_time);
}

std::filesystem::path VtkSeries::finish() const {
  std::vector<io::PvdEntry> entries;
  for (std::size_t k = 0; k < steps_.size(); ++k) {
    entries.push_back({steps_[k], 0, stem_ + "-nodes-" + std::to_string(k) + ".vtp"});
    entries.push_back({steps_[k], 1, stem_ + "-cracks-" + std::to_string(k) + ".vtp"});
    if (points_) entries.push_back({steps_[k], 2, stem_ + "-points-" + std::to_string(k) + ".vtp"});
  }
  const auto pvd = folder_ / (stem_ + ".pvd");
  io::write_pvd(output_(pvd), entries);
  return pvd;
}

}  // namespace mesowave::efg
