#pragma once
// mw-fem's explicit solver on the same bar as the EFG strip (efg/wave_strip), for the linear check
// of `mw-efg wave --fem-reference`: one row of hexahedra of the strip's spacing h along x
// (fem::box_hexahedra, L x h x h), u_y = u_z held at every node (the strip's rollers: the same
// uniaxial strain), the lumped-mass central differences of fem::run_explicit at 0.9 of its stable
// step, the same Hann burst as a force per area on the face x = 0 (the pressure times h^2, spread
// by fem::surface_patch), v_x recorded at the node nearest each sensor x. The FEM's Hann burst is
// its only load (fem::BurstLoad), hence the EFG run's --pulse hann. tests/efg/wave_strip_test.cpp
// (HannBurstAgreesWithTheFemOnTheSameBar) makes the same comparison by hand.
#include <vector>

#include "mesowave/efg/wave_strip.hpp"
#include "mesowave/signal/hann_burst.hpp"

namespace mesowave::efg {

struct FemBarReference {
  std::size_t elements = 0;
  double dt_s = 0, wall_s = 0;
  std::vector<double> sensor_x_m;             ///< the FEM nodes' x (equal to the EFG sensors' on a whole spacing)
  std::vector<std::vector<double>> v_x_m_s;   ///< [sensor][EFG sample]: the FEM's v_x at the EFG's sample times
  /// per sensor, the rms over the EFG's samples (before the FEM's record ends) divided by the closed
  /// form's peak |v|: EFG against the closed form, the FEM against it, and the two against each other
  std::vector<double> efg_error, fem_error, efg_fem_difference;
};

/// The FEM bar of `o` (its length, spacing, E, nu, density) under `burst` [Pa] over the EFG run
/// `efg`'s duration, sampled at its times. InputError for sizes the FEM refuses.
FemBarReference fem_bar_reference(const WaveStripOptions& o, const signal::HannBurst& burst, const WaveStripResult& efg);

/// v_x(x, t) of the linear continuum for p(t) on x = 0: the pulse and its reflection from the free
/// end x = L (the velocity doubles there), [p(t - x/c) + p(t - (2L - x)/c)] / (rho c).
double continuum_velocity_m_s(const WaveStripOptions& o, double c_m_s, double x_m, double t_s);

}  // namespace mesowave::efg
