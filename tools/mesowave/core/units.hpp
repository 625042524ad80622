#pragma once
// Unit factors for the edges of the program: options and file columns carry
// their unit in the name (--t-p-us, E_GPa); the library works in SI.
//   double t_p = t_p_us * units::us;     // to SI
//   double t_p_us = t_p / units::us;     // back
namespace mesowave::units {

inline constexpr double m = 1.0;
inline constexpr double mm = 1e-3;
inline constexpr double um = 1e-6;
inline constexpr double nm = 1e-9;

inline constexpr double s = 1.0;
inline constexpr double ms = 1e-3;
inline constexpr double us = 1e-6;
inline constexpr double ns = 1e-9;

inline constexpr double kg = 1.0;
inline constexpr double g = 1e-3;

inline constexpr double Pa = 1.0;
inline constexpr double kPa = 1e3;
inline constexpr double MPa = 1e6;
inline constexpr double GPa = 1e9;

inline constexpr double N = 1.0;
inline constexpr double kN = 1e3;

inline constexpr double Hz = 1.0;
inline constexpr double kHz = 1e3;
inline constexpr double MHz = 1e6;

inline constexpr double percent = 1e-2;

}  // namespace mesowave::units
