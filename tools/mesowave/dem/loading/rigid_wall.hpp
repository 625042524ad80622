#pragma once
// A rigid, frictionless plane wall: a platen of the concrete paper's virtual
// compression test (Section 4.2: "the upper wall was moved at a constant
// velocity ... Both walls were frictionless thus horizontal movement was
// possible"). It starts in the plane of one face of the packing's bounding box,
// touching the outermost sphere, so the specimen starts free of force, and moves
// along its inward normal at a constant velocity (0: a fixed wall), reached
// over a ramp (velocity_ramp.hpp). A sphere
// whose surface crosses the plane is pushed back along the normal with
//     F = k_w u,   u = overlap with the plane,   k_w = E_dem r,
// the stiffness Yade's Ip2_CohFrictMat_CohFrictMat_CohFrictPhys gives a
// Wall-Sphere contact of the same material (Eq. 3 with both radii r: measured
// on Yade 2023.02a, docs/models.md). A wall pushes only: it neither glues nor
// shears a sphere.
#include <vector>

#include "mesowave/dem/loading/actuator.hpp"
#include "mesowave/dem/loading/sphere_selection.hpp"
#include "mesowave/dem/loading/velocity_ramp.hpp"

namespace mesowave::dem {

class RigidWall : public Actuator {
public:
  /// `face`: the face of `box` the wall starts on; `velocity_m_s` along the
  /// inward normal from `delay_s` on; `reach_m`: how far the wall may travel in
  /// the run (spheres farther from the face than their radius plus this, plus a
  /// margin for their own motion, are never tested). Of a rank's part of the spheres, collective:
  /// the candidates come from every rank, with their statics.
  RigidWall(std::string name, SpherePart& spheres, const Box& box, Face face, double E_dem_Pa,
            const VelocityRamp& motion, double reach_m);

  const std::string& name() const override { return name_; }
  void before_step(Model& model, double t_s, double dt_s) override;
  const std::vector<std::size_t>& spheres() const override { return candidates_; }
  std::string description() const override;
  /// The total force the wall exerts on the specimen along its inward normal [N].
  double applied_force() const override { return last_force_; }
  /// Its load is a function of time alone: only the last force carries over.
  void save_state(StateGroup& group) const override { group.write("last_force_N", last_force_); }
  void load_state(const StateGroup& group) override { last_force_ = group.read_double("last_force_N"); }
  double added_stiffness_per_mass() const override { return max_stiffness_per_mass_; }

  /// Position of the plane along its axis at time t [m].
  double plane_at(double t_s) const;

  // The contact geometry, for the static solve (static_elastic.hpp).
  const Face& face() const { return face_; }
  double inward() const { return inward_; }  ///< +1 pushes toward +axis, -1 toward -axis
  const VelocityRamp& motion() const { return motion_; }
  /// k_w of each candidate sphere (spheres() order).
  const std::vector<double>& contact_stiffness() const { return stiffness_; }
  /// Surface-to-plane gap of each candidate at step 0 (>= 0; spheres() order).
  double initial_gap_m(std::size_t i) const { return inward_ * (centre0_[i] - plane0_) - radius_[i]; }

private:
  std::string name_;
  Face face_;
  double inward_ = 1;  ///< +1: the wall pushes toward +axis (a lower face), -1 (an upper face)
  double plane0_ = 0;
  VelocityRamp motion_;
  std::vector<std::size_t> candidates_;
  std::vector<double> stiffness_;  ///< k_w per candidate
  std::vector<double> radius_, centre0_;
  double max_stiffness_per_mass_ = 0;
  double last_force_ = 0;
};

}  // namespace mesowave::dem
