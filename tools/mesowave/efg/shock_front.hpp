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
//    U^2 = (p_hi - p_lo) / (rho (s_hi - s_lo)).
// The levels: p_hi = 0.9 p_max; p_lo = the larger of 0.1 p_max and the pressure where the law's
// tangent is least on [0, s(p_max)] (the Y-function's dip: levels below it travel in a spreading
// fan, not in the steepening front).
#include <vector>

#include "mesowave/efg/characteristics.hpp"
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
};

/// The first time -sigma_xx at sensor k reaches `level` [Pa], linear between samples (NaN: never).
double arrival_time(const WaveStripResult& r, std::size_t k, double level_Pa);

/// The comparison above for the strip run `r` of options `o` (its triangular pulse and density)
/// with the uniaxial-strain law `law`. InputError unless o.pulse is triangular and starts at 0.
ShockFrontComparison compare_front_with_characteristics(const WaveStripOptions& o, const WaveStripResult& r,
                                                        const CompressionLaw& law);

}  // namespace mesowave::efg
