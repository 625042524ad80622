#include "mesowave/experiment/motion_quantity.hpp"

#include "mesowave/core/error.hpp"

namespace mesowave::experiment {

MotionQuantity parse_motion_quantity(const std::string& text, const std::string& who) {
  for (MotionQuantity q : motion_quantities)
    if (text == to_string(q)) return q;
  throw InputError(who + " (\"" + text + "\") must be acceleration, velocity or displacement");
}

std::string to_string(MotionQuantity q) {
  switch (q) {
    case MotionQuantity::acceleration: return "acceleration";
    case MotionQuantity::velocity: return "velocity";
    case MotionQuantity::displacement: return "displacement";
  }
  return "";  // not reached: every enumerator is named above
}

std::string si_unit(MotionQuantity q) {
  switch (q) {
    case MotionQuantity::acceleration: return "m/s^2";
    case MotionQuantity::velocity: return "m/s";
    case MotionQuantity::displacement: return "m";
  }
  return "";  // not reached
}

}  // namespace mesowave::experiment
