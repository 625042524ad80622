#pragma once
// The contact detonation of a plain concrete slab (shock paper Section 4.3, Fig. 12): a charge on the
// top face loads the slab with a shock; "the blasting results in a crater beneath the explosive. The
// concrete underneath the crater is highly compacted. Below this compacted range the concrete is
// damaged by cracks." The model runs EVERY part of the paper's list at once: EFG with discrete cracks
// (efg/dynamic_cracks: St. Venant on the principal stress), the crack spacing limit, the direction
// (crack radius) limit, the 500 m/s speed limit (Curbach), the Y-function with unloading (efg/hugoniot,
// Eqs. (24)-(27)), the strain-rate effect (f_t,dyn by the capped CEB-FIP DIF, efg/strain_rate) and the
// contact of closing faces (penalty k, dynamic_cracks.hpp), in the explicit solver of
// efg/explicit_dynamics.
//
// Formulation: PLANE STRAIN, per metre of charge length. The paper gives no dimensions. A charge on the
// slab's axis is axisymmetric, but a 2D discrete-crack model in the r-z plane turns every crack into a
// cone or a cylinder and cannot show the radial cracks a point charge makes; plane strain is exact for a
// LINE (strip) charge across the slab, which is what this models. What that does to the result: a line
// charge's wave spreads over a cylinder, its amplitude decaying geometrically as about r^-1/2 instead of
// a point charge's r^-1, so the depths of compaction and of cracking here are upper bounds for a point
// charge of the same surface pressure.
//
// Slab (assumed, the paper gives none): span L x thickness H (default 400 x 100 mm), the top face y = H,
// the charge's segment centred on x = L / 2. All faces are FREE: the run lasts a few passages of the wave
// through the thickness (about 100 us), far shorter than the slab's bending response, so supports under
// the ends would carry nothing yet (and efg/explicit_dynamics refuses constraint rows with growing
// cracks). The full span is modelled, without the mirror plane x = L / 2: a crack on the axis (the first
// one a line charge makes, under the charge's centre) must be possible.
//
// Charge (assumed - the paper names no explosive): a contact charge of width w_c and thickness l_c
// whose detonation products press on the segment with the triangular history of efg/pressure_load,
//   peak p_0 = T p_CJ,   p_CJ = rho_e D^2 / (gamma + 1)  (gamma = 3, the usual value for condensed
//   explosives: Cooper, "Explosives Engineering", 1996),
//   T = 2 Z_c / (Z_c + Z_e),  Z_c = rho c_p of the concrete, Z_e = rho_e D (the acoustic transmission
//   of the CJ state into the concrete: a first estimate, the products' impedance taken at rho_e D),
//   rise t_r = l_c / D (one transit of the charge; assumed), fall t_f = fall_transits x l_c / D (the
//   rarefaction from the charge's free back, assumed 2 transits; the Taylor wave's decay is not modelled).
// Defaults: TNT, rho_e = 1630 kg/m3, D = 6930 m/s (the handbook values), l_c = 40 mm, w_c = 30 mm: rise
// 5.8 us, fall 11.5 us. Why so thick a charge: the EFG's stable step is long (2.5 us at h = 5 mm), and a
// pulse of a 10 mm sheet (1.4 + 2.9 us) would be one step, i.e. not resolved at all.
// `peak_Pa` > 0 sets the peak directly (e.g. the tests' below-threshold pulse). The T p_CJ default (15.4 GPa
// for TNT) is beyond the small-strain Y-function: at h = 10 mm it drove |eps_v| to 5 and the run gained
// energy, so the study sets 1 GPa (lab-data/shock-concrete/blast-slab.toml, docs/efg.md).
//
// Compacted zone: the Gauss points whose most compressive volumetric strain passed -e_v,th (they left
// Y = 1 onto the Y-function's loading branch, Eq. (25); PointState::min_eps_v); its depth below the top
// face and its width, its area (the points' Gauss weights), and the depth and area of its part joined to the
// loaded face through compacted points (a point a crack's cut marked compacted deep in the slab, docs/efg.md,
// moves the first depth, not the joined one). The threshold surface pressure p_th = M P(e_v,th) = M e_v,th (M = E (1 - nu) /
// ((1 + nu)(1 - 2 nu)); uniaxial strain, the state right under a wide charge) is the pressure below which
// no point can pass it in a linear elastic, non-overshooting response (the closed-form check of the tests).
//
// Crater (efg/crater.hpp states it and its sources): the run erodes nothing; the crater is read off the state
// the run leaves (and each snapshot's) - the crushed points (|min eps_v| past eps_crush, by default the
// Y-function's minimum, 0.0475) joined to the loaded face, and the loose pieces that fully opened crack segments
// (every face point past its law's w_max) cut off and that touch the loaded face; the pieces cut off at the far
// face are spall. Its depth, width and area; the points are joined within one node spacing.
//
// Energies: the run's own identity KE + W_int + W_damp = W_ext (W_int the work of all internal forces,
// the faces' included; efg/explicit_dynamics) holds to round-off. W_faces, the work of the faces'
// forces, is accumulated here by the run's own rule (f^n . (dt_n / 2)(v^{n-1/2} + v^{n+1/2})), so that
// W_bulk = W_int - W_faces is the continuum's share (elastic + the compaction the Y-function's unloading
// leaves behind). The cracks' own terms: dissipated_J + stored_J (the face law's state, dynamic_cracks)
// against W_faces, and energy_jump_J (the energy the cuts add at a fixed u, which no force does; reported,
// not part of the force balance). `balance_J` = KE + W_bulk + dissipated + stored + W_damp - W_ext, the
// run's identity with the faces' work replaced by their law's energy. With the field projection
// (DynamicCrackOptions::project_fields) both balances subtract the kinetic energy the projection changed at
// fixed times (kinetic_jump_J, known exactly; the bulk's share of the change is not: W_bulk is the work of
// the bulk's forces and does not see a change of u at a fixed time, which energy_jump_J measures linearly).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "mesowave/efg/crater.hpp"
#include "mesowave/efg/dynamic_cracks.hpp"
#include "mesowave/efg/explicit_dynamics.hpp"
#include "mesowave/efg/hugoniot.hpp"
#include "mesowave/efg/vtk_output.hpp"

namespace mesowave::efg {

struct ContactCharge {
  double width_m = 0.03;            ///< w_c, the loaded segment of the top face (assumed)
  double thickness_m = 0.04;        ///< l_c (assumed)
  double density_kg_m3 = 1630;      ///< rho_e, TNT (assumed explosive)
  double detonation_velocity_m_s = 6930;  ///< D, TNT
  double gamma = 3;                 ///< p_CJ = rho_e D^2 / (gamma + 1)
  double fall_transits = 2;         ///< t_f = fall_transits l_c / D (assumed)
  double peak_Pa = 0;               ///< > 0: the peak itself instead of T p_CJ
  double cj_pressure_Pa() const;
};

struct BlastSlabOptions {
  double span_m = 0.4, thickness_m = 0.1;  ///< L x H (assumed)
  double spacing_m = 5e-3;                 ///< node spacing (cells L/h x H/h)
  double support_scale = 2.5;              ///< MLS support radius / spacing
  int gauss = 2;                           ///< per cell direction (the paper's 2 x 2)
  ElasticMaterial2D concrete{20e9, 0.2, 1.0, 2400, PlaneState::plane_strain};  ///< forced to plane strain
  HugoniotParameters hugoniot;             ///< Eq. (26), with Eq. (27)
  /// f_t, G_f, DIF, limits (the caller fills f_t, G_f, f_cm). penalty_factor keeps DynamicCrackOptions'
  /// default 10; mw-efg blast and the tests set 1 (k = E / a, the reasoning of dynamic_cracks.hpp)
  DynamicCrackOptions cracks;
  ContactCharge charge;
  double duration_s = 100e-6;
  double dt_fraction = 0.9;
  /// > 0: the time step (DynamicsOptions::dt_s; refused above the stable step of the start); it is still
  /// shrunk by the Y-function's stiffening, the viscosity and the faces' penalty as cracks form. The
  /// default step leaves the 17 us pulse 2-5 steps (docs/efg.md, "The slab's time step, its spacing and its cost").
  double dt_s = 0;
  int stiffness_check_every = 1;           ///< the Y-function stiffens within a step or two under the charge
  std::int64_t sample_stride = 10;         ///< energies every this many steps
  std::int64_t snapshot_stride = 0;        ///< VTK snapshots every this many steps (0: none)
  BulkViscosity viscosity{};               ///< shock viscosity of the explicit solver (default off)
  /// eps_crush of the crater (efg/crater.hpp), a magnitude; 0: the Y-function's minimum (default_crushing_eps_v)
  double crushing_eps_v = 0;
  std::size_t min_points_per_thread = 2000;
  std::function<void(std::int64_t step, double t_s)> progress;
  /// InputError naming the value (one line each).
  void validate() const;
};

/// p_th = M e_v,th: the surface pressure of uniaxial strain at the threshold (see the header).
double hugoniot_threshold_pressure_Pa(const ElasticMaterial2D& concrete, const HugoniotParameters& p);
/// T p_CJ or charge.peak_Pa, and the history on the top face.
TriangularPulse contact_pulse(const ContactCharge& charge, const ElasticMaterial2D& concrete);

struct BlastEnergySample {
  double t_s = 0;
  double kinetic_J = 0, internal_work_J = 0, external_work_J = 0, damping_J = 0;
  double faces_work_J = 0, dissipated_J = 0, stored_J = 0, energy_jump_J = 0;
  /// the kinetic energy the field projection changed at the cracks' changes (EnergySample; 0 without it);
  /// part of energy_jump_J too
  double kinetic_jump_J = 0;
  /// the faces' share of energy_jump_J (DynamicCracks::faces_jump_J): their law energy moved at fixed times
  double faces_jump_J = 0;
  /// the shock viscosity's work (EnergySample::viscous_J; 0 when off)
  double viscous_J = 0;
  double bulk_work_J() const { return internal_work_J - faces_work_J; }
  double run_balance_J() const {
    return kinetic_J + internal_work_J + damping_J + viscous_J - external_work_J - kinetic_jump_J;
  }
  double balance_J() const {
    return kinetic_J + bulk_work_J() + dissipated_J + stored_J + damping_J + viscous_J - external_work_J - kinetic_jump_J;
  }
  /// balance_J less the faces' jump: what the faces' law energy misses of their force work over the steps
  double balance_less_faces_jump_J() const { return balance_J() - faces_jump_J; }
};

struct GaussPointSnapshot {
  std::vector<Vec2> x;
  std::vector<double> eps_v, min_eps_v, max_Y;
  std::vector<CraterLabel> crater;  ///< what measure_crater made of each point at that time
};

struct BlastSnapshot {
  double t_s = 0;
  NodeSnapshot nodes;
  CrackSnapshot cracks;
  GaussPointSnapshot points;
};

struct BlastSlabResult {
  std::size_t nodes = 0, points = 0;
  TriangularPulse pulse;
  double threshold_pressure_Pa = 0;
  std::vector<CrackEvent> events;
  std::vector<std::vector<Vec2>> crack_polylines;  ///< clipped to the slab
  std::vector<double> crack_length_m;              ///< per crack, in the slab
  double max_crack_speed_m_s = 0;                  ///< over the growth events
  std::size_t refused = 0;
  // the compacted zone (see the header)
  std::size_t compacted_points = 0;
  double compacted_depth_m = 0, compacted_width_m = 0, compacted_x_min_m = 0, compacted_x_max_m = 0;
  double max_compression_eps_v = 0;               ///< the largest |min_eps_v|
  double compacted_area_m2 = 0;                   ///< the compacted points' Gauss weights
  /// the compacted points joined to the loaded face through compacted points (measure_crater's flood fill):
  /// the depth and area of that part
  double compacted_joined_depth_m = 0, compacted_joined_area_m2 = 0;
  double crushing_eps_v = 0;                      ///< eps_crush in force
  CraterMeasure crater;                           ///< of the final state (labels in final_points.crater)
  std::vector<Segment> open_segments;             ///< face segments past w_max at the end (the crater's cuts)
  GaussPointSnapshot final_points;
  std::vector<BlastEnergySample> energy;
  std::vector<BlastSnapshot> snapshots;
  double max_abs_balance_J = 0, max_abs_run_balance_J = 0;  ///< over the samples
  double penalty_Pa_per_m = 0, segment_length_m = 0, min_spacing_m = 0, min_radius_m = 0, max_turn_rad = 0;
  DynamicsResult run;  ///< steps, dt, stable step, wall, threads (sensors none)
  double setup_s = 0, wall_s = 0;
};

/// The part of a -> b inside the rectangle (Liang-Barsky); false when none (the figures' crack lines).
bool clip_segment_to(const Rect& r, Vec2& a, Vec2& b);

/// Builds the slab and runs it. InputError: bad options (one line each), a blow-up (explicit_dynamics).
BlastSlabResult run_blast_slab(const BlastSlabOptions& o);

}  // namespace mesowave::efg
