#pragma once
// Named values with units and their origin: the lab-data files (TOML) and the
// flat JSON objects the tools print. Both become option values of a later
// tool: an entry named t_p in unit "us" fills the option --t-p-us.
//
// TOML layout (lab-data/*.toml), one table per quantity:
//   [t_p]
//   value  = 35.0
//   unit   = "us"
//   source = "paper"      # paper | derived | synthetic | assumed | placeholder (scripts/new-study)
//   cite   = "concrete paper, Section 3.2"
// JSON layout (tool outputs): a flat object whose keys already end in their
// unit, {"E_d_GPa": 36.67, "nu_d": 0.1618}.
#include <filesystem>
#include <string>
#include <vector>

namespace mesowave::io {

struct Quantity {
  std::string name;    ///< as in the file ("t_p")
  std::string value;   ///< textual value as an option would receive it
  std::string unit;    ///< "" for dimensionless quantities
  std::string source;  ///< paper | derived | synthetic | assumed | placeholder | output
  std::string cite;    ///< where a paper value is printed, or why it was assumed

  /// The command-line option this quantity fills: "t_p" in "us" -> "t-p-us".
  std::string option_name() const;
};

/// Reads a TOML lab-data file or a flat JSON object (chosen by content).
/// Every TOML entry must carry a source of a known kind; paper, derived and
/// assumed values must say where they come from (cite). Errors name the file
/// and the entry.
std::vector<Quantity> read_quantity_file(const std::filesystem::path& path);
std::vector<Quantity> parse_quantity_text(const std::string& text, const std::string& origin);

}  // namespace mesowave::io
