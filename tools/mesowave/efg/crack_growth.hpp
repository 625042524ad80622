#pragma once
// Crack initiation and growth (the paper's Section 3.1, last paragraph): the
// St. Venant criterion - a crack starts or extends where the largest principal
// strain reaches f_t / E - and growth orthogonal to the direction of that
// principal strain (the crack opens along it), or in a prescribed direction:
// the paper limits the bending beam's crack to the vertical (Section 4.1),
// because the principal directions at mid-span, where the shear is small, are
// too sensitive to follow.
#include <optional>

#include <Eigen/Core>

#include "mesowave/efg/geometry.hpp"

namespace mesowave::efg {

/// Principal strains of a plane strain state (Voigt xx, yy, xy with engineering shear gamma_xy).
struct PrincipalStrain {
  double largest = 0, smallest = 0;
  Vec2 direction = Vec2::UnitX();  ///< unit vector of the largest principal strain
};
PrincipalStrain principal_strain(const Eigen::Vector3d& strain_voigt);

/// St. Venant: the largest principal strain at or above f_t / E.
bool st_venant_exceeded(const Eigen::Vector3d& strain_voigt, double f_t_Pa, double E_Pa);

enum class GrowthDirectionRule { principal_strain, prescribed };

struct CrackGrowthOptions {
  GrowthDirectionRule rule = GrowthDirectionRule::principal_strain;
  Vec2 prescribed = Vec2::UnitY();  ///< the direction under `prescribed` (the beam: vertical)
  double segment_length_m = 0;      ///< length of one new segment (> 0)
  /// The strain is read this far ahead of the tip (a fraction of segment_length_m): at the tip itself
  /// the MLS field is cut by the crack's own line.
  double probe_fraction = 0.25;
};

/// The direction a crack at `tip`, last heading `heading` (unit), grows under `options`: orthogonal to
/// the largest principal strain (the sign that keeps it going forward), or the prescribed one (likewise).
Vec2 growth_direction(const Eigen::Vector3d& strain_voigt, const Vec2& heading, const CrackGrowthOptions& options);

/// The new tip if the crack grows: St. Venant at the probe point ahead of the tip (strain_at(probe)),
/// the new segment of segment_length_m along growth_direction, cut at the body's boundary `inside`
/// (nullopt when it would leave the body at once). InputError for segment_length_m <= 0.
template <class StrainAt, class Inside>
std::optional<Vec2> grown_tip(const Vec2& tip, const Vec2& heading, double f_t_Pa, double E_Pa,
                              const CrackGrowthOptions& options, StrainAt strain_at, Inside inside);

/// InputError naming the value when segment_length_m <= 0 or probe_fraction outside (0, 1].
void validate(const CrackGrowthOptions& options);

template <class StrainAt, class Inside>
std::optional<Vec2> grown_tip(const Vec2& tip, const Vec2& heading, double f_t_Pa, double E_Pa,
                              const CrackGrowthOptions& options, StrainAt strain_at, Inside inside) {
  validate(options);
  const Vec2 probe = tip + options.probe_fraction * options.segment_length_m * heading;
  if (!inside(probe)) return std::nullopt;
  const Eigen::Vector3d strain = strain_at(probe);
  if (!st_venant_exceeded(strain, f_t_Pa, E_Pa)) return std::nullopt;
  const Vec2 dir = growth_direction(strain, heading, options);
  Vec2 next = tip + options.segment_length_m * dir;
  // stop at the boundary: halve back until inside (the tip stays inside the body)
  for (int k = 0; k < 30 && !inside(next); ++k) next = tip + 0.5 * (next - tip);
  if (!inside(next)) return std::nullopt;
  return next;
}

}  // namespace mesowave::efg
