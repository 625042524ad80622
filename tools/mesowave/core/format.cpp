#include "mesowave/core/format.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace mesowave {

std::string format_number(double value) {
  if (!std::isfinite(value)) return format_exact(value);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

std::string format_exact(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, end);
}

std::string format_significant(double value, int digits) {
  if (!std::isfinite(value)) return format_exact(value);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

std::string format_quantity(double value, std::string_view unit) {
  std::string text = format_number(value);
  if (!unit.empty()) {
    text += ' ';
    text += unit;
  }
  return text;
}

std::string format_fixed(double value, int digits) {
  if (!std::isfinite(value)) return format_number(value);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
  return buffer;
}

}  // namespace mesowave
