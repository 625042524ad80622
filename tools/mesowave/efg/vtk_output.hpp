#pragma once
// ParaView snapshots of an EFG (or plane FEM) solution: per load step one file of the nodes and one
// of the cracks, both VTK XML PolyData (io/vtk_xml), and a .pvd that orders the steps (open the .pvd;
// the nodes are part 0, the cracks part 1).
//  - nodes: points at the reference position (z = 0), vertex cells; point data "displacement" [m]
//    (3 components, z = 0: "Warp By Vector" shows the deformed body), "stress" [Pa] as VTK's symmetric
//    tensor (xx, yy, zz, xy, yz, xz; zz = 0 as given in plane stress) and "max_principal_stress" [Pa],
//    the quantity the St. Venant criterion's crack growth follows (paper Section 2.3).
//  - cracks: every polyline's points, one line cell per segment; cell data, when given,
//    "opening_mm" (the normal opening w [mm]), "traction_MPa" (the cohesive law's normal traction
//    [MPa], paper Eqs. (19)-(23)) and "damage" (the share of f_t lost, 0 to 1: cohesive_crack.hpp).
//    These two are in the units the papers plot the softening curve in (w ~ 0.01-0.1 mm,
//    sigma ~ 1 MPa), their names saying so; the nodes' arrays stay SI.
//  - points (optional, a third part): any scattered points (e.g. the Gauss points) with named scalar
//    arrays as point data (the blasted slab's volumetric strains, efg/blast_slab).
// Stresses are sampled at the nodes: an MLS approximation is smooth there (no averaging needed); a
// Q4 mesh's nodal stresses are the element average (fem/plane_static).
#include <Eigen/Core>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace mesowave::efg {

struct NodeSnapshot {
  std::vector<Eigen::Vector2d> positions_m;       ///< reference positions
  std::vector<Eigen::Vector2d> displacement_m;    ///< per node, u^h at the node (not the MLS parameters)
  std::vector<Eigen::Vector3d> stress_Pa;         ///< per node (xx, yy, xy), or empty
};

struct CrackSnapshot {
  std::vector<std::vector<Eigen::Vector2d>> polylines;  ///< one per crack (a notch too), >= 2 points each
  std::vector<double> opening_m;    ///< per segment (cracks in order, then their segments), or empty
  std::vector<double> traction_Pa;  ///< per segment, or empty
  std::vector<double> damage;       ///< per segment, or empty
  std::size_t segment_count() const;
};

struct PointCloudSnapshot {
  std::vector<Eigen::Vector2d> positions_m;
  std::vector<std::pair<std::string, std::vector<double>>> scalars;  ///< (name, one value per point)
};

/// std::invalid_argument when the per-node or per-segment arrays do not match the counts.
void write_node_vtp(const std::filesystem::path& path, const NodeSnapshot& nodes, double step_time);
void write_crack_vtp(const std::filesystem::path& path, const CrackSnapshot& cracks, double step_time);
void write_point_vtp(const std::filesystem::path& path, const PointCloudSnapshot& points, double step_time);

/// A series of load steps under one folder: step k writes <stem>-nodes-<k>.vtp and
/// <stem>-cracks-<k>.vtp, finish() writes <stem>.pvd. `step_time` is what ParaView's time slider
/// shows (the load step's prescribed deflection, say).
/// `output` maps each final path to the path written (a tool passes app::Run::output, which stages
/// it until the run succeeds); the .pvd names the files relative to `folder`.
class VtkSeries {
 public:
  using OutputPath = std::function<std::filesystem::path(const std::filesystem::path&)>;
  VtkSeries(std::filesystem::path folder, std::string stem, OutputPath output = {});
  /// With `points`, <stem>-points-<k>.vtp as part 2 (give it at every step or at none).
  void add(double step_time, const NodeSnapshot& nodes, const CrackSnapshot& cracks,
           const PointCloudSnapshot* points = nullptr);
  /// Writes the .pvd (final path returned).
  std::filesystem::path finish() const;
  std::size_t steps() const { return steps_.size(); }

 private:
  std::filesystem::path folder_;
  std::string stem_;
  OutputPath output_;
  std::vector<double> steps_;
  bool points_ = false;
};

}  // namespace mesowave::efg
