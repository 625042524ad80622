#pragma once
// A line of spheres under axial loading (the rod paper's DEM model): one
// degree of freedom per sphere, the displacement s along the line's axis e.
// With every centre on the line and every load along it, the full law keeps
// the transverse motion, the shear forces and the rotations exactly zero and
// its normal force is exactly linear, F_n = -K_n (s_j - s_i) (Eq. 1 in 1-D),
// so this model is the full law restricted to what moves, at a fraction of
// the cost. Bonds are the step-0 bonds (C_f rule), second neighbours included
// when they are in range (d < C_f R, e.g. the rod at d = 0.95 R with C_f 1.1).
#include "mesowave/dem/contact/bond_network.hpp"
#include "mesowave/dem/contact/material.hpp"
#include "mesowave/dem/engine/model.hpp"
#include "mesowave/dem/engine/sphere_part.hpp"

namespace mesowave::dem {

class AxialChain : public Model {
public:
  /// `axis`: unit vector along the line. Damping acts on the axial component,
  /// which equals Yade's per-component damping only for an axis along x, y or z
  /// (the model choice checks that). InputError for a rank's part: the chain runs on one process.
  AxialChain(SpherePart spheres, const BondNetwork& bonds, const CohesiveFrictionalMaterial& material, const Vec3& axis);

  std::string name() const override { return "chain"; }
  std::size_t sphere_count() const override { return spheres_.size(); }
  std::size_t bond_count() const override { return first_.size(); }
  std::size_t degrees_of_freedom() const override { return spheres_.size(); }
  Vec3 reference_position(std::size_t k) const override { return spheres_.centre_m[k]; }
  double radius(std::size_t k) const override { return spheres_.radius_m[k]; }
  double mass(std::size_t k) const override { return spheres_.mass_kg[k]; }
  std::uint32_t packing_index(std::size_t k) const override { return spheres_.packing_index[k]; }
  Vec3 displacement(std::size_t k) const override { return s_[k] * axis_; }
  Vec3 velocity(std::size_t k) const override { return v_[k] * axis_; }
  Vec3 acceleration(std::size_t k) const override { return a_[k] * axis_; }
  void add_external_force(std::size_t k, const Vec3& force) override;
  double impose_displacement(std::size_t k, const Vec3& e, double u_now, double u_next, double dt) override;
  void set_velocity(std::size_t k, const Vec3& v) override { v_[k] = dot(v, axis_); }
  void step(double dt, bool evaluate_energy) override;
  EnergyAccount energy() const override { return energy_; }
  double peak_force_ratio() const override { return peak_ratio_; }
  bool has_non_finite_state() const override;
  void scaled_stiffness_action(const double* x, double* y) const override;
  double scaled_stiffness_row_sum_bound() const override;
  std::size_t memory_bytes() const override;
  void save_state(StateGroup& group) const override;
  void load_state(const StateGroup& group) override;
  int threads() const override { return 1; }
  const Vec3& axis() const { return axis_; }

private:
  SphereSet spheres_;
  CohesiveFrictionalMaterial material_;
  Vec3 axis_;
  std::vector<std::uint32_t> first_, second_;
  std::vector<double> kn_, inv_strength_;
  std::vector<double> s_, v_, a_, a_undamped_, f_, f_ext_, inv_mass_;
  std::vector<std::uint32_t> forced_;
  std::vector<double> forced_v_before_;
  double peak_ratio_ = 0;
  EnergyAccount energy_;
};

}  // namespace mesowave::dem
