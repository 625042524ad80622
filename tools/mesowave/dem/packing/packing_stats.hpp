#pragma once
// What a packing is like: count, porosity, sizes, overlaps, coordination at
// the bond detection factor C_f, isotropy, and the particle density that
// gives the model the specimen's mass.
#include <cstddef>
#include <optional>

#include "mesowave/dem/packing/packing.hpp"

namespace mesowave::dem {

/// Sum of the sphere volumes, overlaps counted twice (4/3 pi sum r^3).
double solid_volume(const Packing& packing);
/// Concrete paper, Section 4.2: p = 1 - sum(V_sphere) / V_container.
double porosity(const Packing& packing);
/// rho_p = m_specimen / sum(V_sphere): the model weighs what the specimen
/// weighs (both papers). InputError if the mass is not positive.
double particle_density_for_mass(double specimen_mass_kg, const Packing& packing);
/// The specimen's mass from its material density and the container volume.
double specimen_mass(double material_density_kg_m3, const Container& container);

/// True if the sphere lies wholly inside the container, to `tolerance_m`.
bool sphere_inside(const Container& container, const std::array<double, 3>& centre_m, double radius_m,
                   double tolerance_m = 0);
/// The box that just holds every sphere (shape "box").
Container bounding_box(const Packing& packing);

struct PackingStats {
  std::size_t count = 0;
  double container_volume_m3 = 0;
  double solid_volume_m3 = 0;
  double porosity = 0;
  /// Porosity counted over the core (the container shrunk by 2 d_max on every
  /// side; centres decide membership): the wall layer is less dense. Absent
  /// for a line, or when the core would be thinner than 2 d_max.
  std::optional<double> core_porosity;
  double d_mean_m = 0, d_std_m = 0, d_min_m = 0, d_max_m = 0;
  std::size_t contacts = 0;  ///< overlapping or touching pairs (|x_i - x_j| <= r_i + r_j)
  double coordination_contacts = 0;
  double mean_overlap_ratio = 0;  ///< mean over contacts of delta / smaller radius
  double max_overlap_ratio = 0;
  double detection_factor = 1.1;  ///< C_f
  std::size_t bonds = 0;           ///< pairs with |x_i - x_j| <= C_f (r_i + r_j)
  double coordination = 0;         ///< 2 bonds / count
  /// Eigenvalues of the fabric tensor of the bond directions, sum n n^T / bonds
  /// (1/3 each for an isotropic packing).
  double fabric_min = 0, fabric_max = 0;
  std::size_t spheres_outside = 0;  ///< spheres not wholly inside the container (1e-9 relative tolerance)
};

/// InputError if `detection_factor` is not positive.
PackingStats packing_stats(const Packing& packing, double detection_factor = 1.1);

}  // namespace mesowave::dem
