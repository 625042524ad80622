#pragma once
// The strip's compressive front against the method of characteristics (shock paper Section 4.2,
// docs/efg.md "Shock steepening"; efg/characteristics derives the reference). For a triangular
// pulse p(t) on x = 0 and a stiffening law p = f(s) under uniaxial strain:
//  - the first crossing of characteristics (x_b, t_b, the level that breaks first): where a shock
//    forms in the continuum;
//  - the front's width between two levels p_lo < p_hi: the simple wave carries each level at
//    c(s) = sqrt(f'(s) / rho), so width(x) = (p_hi - p_lo) / p_max t_r + x (1 / c_hi - 1 / c_lo)
//    until the two levels meet at x_meet = (p_hi - p_lo) / p_max t_r / (1 / c_lo - 1 / c_hi), at
//    t_meet = tau_hi + x_meet / c_hi; the strip's widths at the sensors before x_b (where no
//    characteristics have crossed yet) fitted by a line give the measured x_meet, t_meet;
//  - past it the front is a shock: its speed between the last two sensors, when both lie past
//    x_meet (the level midway between p_lo and p_hi timed), against the jump condition
//    U^2 = (p_hi - p_lo) / (rho (s_hi - s_lo)) between those FIXED levels, and against a second
//    method, a fine 1D bar of the same law (bar_1d_shock_speed below). The fixed-level jump condition
//    is not the continuum's speed where the last sensors lie (docs/efg.md "Shock viscosity": for the
//    Y-function the pulse's peak characteristic catches the shock near 100 mm and the pulse's fall
//    then eats it; the smooth law's shock is still growing there), so the bar is the reference the
//    study reads (shock_speed_over_bar); the jump condition stays beside it, named as what it is.
// The levels: p_hi = 0.9 p_max; p_lo = the larger of 0.1 p_max and the pressure where the law's
// tangent is least on [0, s(p_max)] (the Y-function's dip: levels below it travel in a spreading
// fan, not in the steepening front).
#include <vector>

#include "mesowave/efg/characteristics.hpp"
#include "mesowave/efg/explicit_dynamics.hpp"
#include "mesowave/efg/wave_strip.hpp"

namespace mesowave::efg {

struct FrontWidth {
  double x_m = 0;
  double width_s = 0;              ///< the strip's: arrival of p_hi minus arrival of p_lo (NaN: not reached)
  double simple_wave_width_s = 0;  ///< the characteristics' (negative past x_meet: multivalued)
  bool before_breaking = false;    ///< x < x_b: the simple wave holds exactly there
};

struct ShockFrontComparison {
  ShockFormation formation;        ///< the characteristics' first crossing
  double p_lo_Pa = 0, p_hi_Pa = 0, s_lo = 0, s_hi = 0, c_lo_m_s = 0, c_hi_m_s = 0;
  std::vector<FrontWidth> fronts;  ///< per sensor
  double meet_distance_m = 0, meet_time_s = 0;                 ///< characteristics: p_lo and p_hi meet
  double measured_meet_distance_m = 0, measured_meet_time_s = 0;  ///< the strip's (NaN: fewer than 2 sensors before x_b)
  int fitted_sensors = 0;
  double shock_speed_m_s = 0;      ///< the strip's, between the last two sensors (NaN: not both past x_meet, or not reached)
  double speed_level_Pa = 0;       ///< the level timed for it
  double jump_speed_m_s = 0;       ///< U of the jump condition between s_lo and s_hi
  double c_0_m_s = 0;              ///< sqrt(f'(0) / rho)
  /// the 1D bar's speed of speed_level_Pa between the same two sensors (bar_1d_shock_speed; NaN: the
  /// strip's speed not measured, the bar's level not reached, or no bar asked for)
  double bar_speed_m_s = 0;
  double bar_spacing_m = 0;        ///< its cell length (0: no bar)
};

/// The second method for the shock speed: the strip's uniaxial-strain bar as a 1D Lagrangian column
/// of the same law p = f(s) (cells of h, nodal masses rho h, halves at the ends; staggered central
/// differences; p = M s in tension, M = f'(0)), loaded by `pulse` on x = 0 and free at x = L, with the
/// von Neumann-Richtmyer viscosity q = rho h (C_0 h s_dot^2 + C_1 c s_dot) in compression (c = sqrt(f'(s)
/// / rho)) and its own step 0.5 h / (Q + sqrt(Q^2 + c^2)), Q = C_1 c + C_0 h s_dot (LS-DYNA's bound,
/// halved). Undamped the bar blows up at the shock, so it always carries q; the shock's speed does not
/// depend on q, only its width (docs/efg.md "Shock viscosity": 2385.3 / 2385.9 m/s with C_0 = 1.5 / 3 at
/// h = 0.1 mm for the study's Y-function strip, 2383.9 / 2385.3 / 2386.0 / 2386.3 m/s at h = 0.2 / 0.1 /
/// 0.05 / 0.025 mm). Returns the speed (x_b - x_a) / (t_b - t_a) of the level `level_Pa` of -sigma_xx
/// (interpolated between cell centres and in time) between the stations x_a < x_b; NaN when the level
/// does not reach x_b within `duration_s`. InputError: h, the length or the stations out of range.
struct BarShockSpeedOptions {
  double spacing_m = 0.2e-3;              ///< h (5-10 times finer than the study's strips)
  BulkViscosity viscosity{1.5, 0.06};     ///< LS-DYNA's C_0, C_1
};
double bar_1d_shock_speed(const CompressionLaw& law, double rho_kg_m3, const TriangularPulse& pulse, double length_m,
                          double duration_s, double x_a_m, double x_b_m, double level_Pa,
                          const BarShockSpeedOptions& bar = {});

/// The first time -sigma_xx at sensor k reaches `level` [Pa], linear between samples (NaN: never).
double arrival_time(const WaveStripResult& r, std::size_t k, double level_Pa);

/// The comparison above for the strip run `r` of options `o` (its triangular pulse and density)
/// with the uniaxial-strain law `law`. InputError unless o.pulse is triangular and starts at 0.
/// `bar`: also the 1D bar's speed of the same level between the same sensors (null: none; a law that
/// unloads on another path than `law` has no such bar).
ShockFrontComparison compare_front_with_characteristics(const WaveStripOptions& o, const WaveStripResult& r,
                                                        const CompressionLaw& law, const BarShockSpeedOptions* bar = nullptr);

}  // namespace mesowave::efg
