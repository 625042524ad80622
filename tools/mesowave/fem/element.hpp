#pragma once
// Element matrices of the continuum reference solver (mw-fem):
//  - Hex8: trilinear 8-node hexahedron, full 2x2x2 Gauss integration (no hourglass
//    modes, so no hourglass control to tune; the Abaqus model of the rod paper used
//    C3D8R, one point with hourglass control - see docs/models.md for the comparison).
//  - Quad4Axisymmetric: bilinear 4-node ring element in (r, z) for torsionless
//    axisymmetric motion, strains (e_rr, e_zz, e_tt = u_r / r, g_rz), 2x2 Gauss, weight 2 pi r.
// Lumped masses are the row sums of the consistent mass (rho integral of N_a),
// positive for these elements. Matrices are dense row-major.
#include <array>
#include <vector>

#include "mesowave/wave/elastic.hpp"

namespace mesowave::fem {

// E, nu and rho as the dispersion theory has them (wave/elastic.hpp): one definition for both.
using wave::IsotropicMaterial;

/// 24 x 24 stiffness of a hexahedron, dofs (u_x, u_y, u_z) per node; nodes in the
/// usual order (bottom face counter-clockwise seen from +z, then the top face).
std::vector<double> hex8_stiffness(const std::array<std::array<double, 3>, 8>& x, const IsotropicMaterial& m);
std::array<double, 8> hex8_lumped_mass(const std::array<std::array<double, 3>, 8>& x, double rho);

/// 8 x 8 stiffness of an axisymmetric ring element, dofs (u_r, u_z) per node; nodes
/// counter-clockwise in the (r, z) plane.
std::vector<double> quad4_axisymmetric_stiffness(const std::array<std::array<double, 2>, 4>& x,
                                                 const IsotropicMaterial& m);
std::array<double, 4> quad4_axisymmetric_lumped_mass(const std::array<std::array<double, 2>, 4>& x, double rho);

/// Largest eigenvalue of M^-1 K for one element with its lumped mass (rad^2/s^2).
/// By the Irons-Treharne bound no assembled mesh has a higher frequency, so
/// dt <= 2 / sqrt(max over elements) is stable for central differences.
double element_max_eigenvalue(const std::vector<double>& K, const std::vector<double>& lumped_mass_per_dof);

}  // namespace mesowave::fem
