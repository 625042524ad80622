#include "mesowave/lab/synthetic_truth.hpp"

#include <sstream>

#include "mesowave/core/format.hpp"
#include "mesowave/io/quantity_file.hpp"

namespace mesowave::lab {

using io::kForeignKeys;

namespace {
std::string toml_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}
// TOML floats need a decimal point or an exponent ("7" would be an integer).
std::string toml_float(double v) {
  std::string text = format_exact(v);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}
}  // namespace

std::string synthetic_record_label() {
  return "# source: synthetic - made by mesowave's generator (mw-synth) from the ground truth in the truth file "
         "written with it, not measured\n";
}

std::string truth_toml(const std::string& title, const std::string& command, const std::vector<TruthEntry>& entries) {
  std::ostringstream s;
  s << "# " << title << "\n"
    << "# source: synthetic - made by mesowave's generator from the values below, not measured.\n"
    << "# Regenerate with:\n#   " << command << "\n";
  // A truth file records what the generator put in, for tests and people: a
  // tool reading it with --from takes the set-up values it has options for
  // and leaves the rest (the answers above all) without an error.
  s << "\n# Every entry is foreign: --from takes those an option names, the rest is for comparison.\n"
    << kForeignKeys << " = [";
  for (std::size_t i = 0; i < entries.size(); ++i) s << (i ? ", " : "") << toml_string(entries[i].name);
  s << "]\n";
  for (const auto& e : entries) {
    s << "\n[" << e.name << "]\n"
      << "value = " << toml_float(e.value) << "\n"
      << "unit = " << toml_string(e.unit) << "\n"
      << "source = " << toml_string(e.source) << "\n"
      << "cite = " << toml_string(e.cite) << "\n";
  }
  return s.str();
}

}  // namespace mesowave::lab
