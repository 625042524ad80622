#pragma once
// Numbers for people: shortest round-trip form for messages, fixed digits for tables.
#include <string>
#include <string_view>

namespace mesowave {

/// Text for messages: up to 10 significant digits, so that a value converted
/// to SI and back reads as typed ("30", not "29.999999999999996").
std::string format_number(double value);

/// Shortest decimal text that reads back as exactly the same double, for
/// values passed on between programs.
std::string format_exact(double value);

/// `format_number(value)` followed by the unit, if any ("35 us").
std::string format_quantity(double value, std::string_view unit);

/// `digits` significant digits, the shortest way ("27.41", "0.16", "1.5e-06").
std::string format_significant(double value, int digits);

/// Fixed-point text with `digits` decimals ("30.44").
std::string format_fixed(double value, int digits);

}  // namespace mesowave
