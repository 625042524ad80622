#pragma once
// Flowchart step 1: density of a specimen from its mass and measured
// dimensions, rho = m / V, with the instruments' resolution propagated to a
// standard uncertainty (GUM: a reading with resolution d has a rectangular
// distribution of half-width d/2, standard uncertainty d / sqrt(12)).
#include <span>
#include <string>

namespace mesowave::lab {

enum class SpecimenShape { Cube, Prism, Cylinder };

SpecimenShape parse_specimen_shape(const std::string& name);  ///< cube | prism | cylinder
std::string to_string(SpecimenShape shape);

/// Measured dimensions in metres. Cube: side. Prism: length, width, height.
/// Cylinder: diameter, height.
struct SpecimenGeometry {
  SpecimenShape shape = SpecimenShape::Cube;
  double side_m = 0, length_m = 0, width_m = 0, height_m = 0, diameter_m = 0;
};

struct MeasurementResolution {
  double mass_kg = 0;    ///< smallest step of the scale
  double length_m = 0;   ///< smallest step of the caliper
};

struct SpecimenDensity {
  double volume_m3 = 0;
  double density_kg_m3 = 0;
  double u_density_kg_m3 = 0;  ///< standard uncertainty from the resolutions
};

/// Volume of the measured shape; InputError for a non-positive dimension.
double specimen_volume(const SpecimenGeometry& geometry);

/// rho = m / V with (u_rho/rho)^2 = (u_m/m)^2 + sum_i (n_i u_L / L_i)^2, n_i the
/// power of dimension L_i in V (3 for a cube's one side, 2 for a diameter).
SpecimenDensity specimen_density(double mass_kg, const SpecimenGeometry& geometry,
                                 const MeasurementResolution& resolution);

/// Several specimens of one batch.
struct DensitySummary {
  std::size_t count = 0;
  double mean_kg_m3 = 0;
  double std_kg_m3 = 0;           ///< sample standard deviation (n - 1); 0 for one specimen
  double sem_kg_m3 = 0;           ///< std / sqrt(n): scatter left in the mean
  double u_resolution_kg_m3 = 0;  ///< mean of the specimens' resolution uncertainties
  double u_mean_kg_m3 = 0;        ///< sqrt(sem^2 + u_resolution^2); resolution does not average out
  double min_kg_m3 = 0, max_kg_m3 = 0;
};

DensitySummary summarize_densities(std::span<const SpecimenDensity> specimens);

}  // namespace mesowave::lab
