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
// unit, {"E_d_GPa": 36.67, "nu_d": 0.1618}; nested values (arrays, objects)
// are data, not option values, and are skipped.
//
// Foreign keys (the --from contract, app/tool.hpp): a tool reading a file with
// --from must take every entry, or fail naming it, unless the file declares the
// entry foreign - carried for another reader or for humans - with a top-level
// array of the entries' names, in either format:
//   foreign_keys = ["p_transducer_frequency", "hold"]        (TOML)
//   {"E_dem_GPa": 30.2, "E_glob_GPa": 31.9, "foreign_keys": ["E_glob_GPa"]}
// A tool that has an option for a foreign entry still takes it.
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

/// A --from file: its quantities and the entries it declares foreign.
struct QuantityFile {
  std::vector<Quantity> quantities;
  std::vector<std::string> foreign_keys;  ///< entry names as in the file ("hold", "E_glob_GPa")
};

/// The top-level key that declares a file's foreign entries.
inline constexpr const char* kForeignKeys = "foreign_keys";

/// Reads a TOML lab-data file or a flat JSON object (chosen by content).
/// Every TOML entry must carry a source of a known kind; paper, derived and
/// assumed values must say where they come from (cite). Errors name the file
/// and the entry.
std::vector<Quantity> read_quantity_file(const std::filesystem::path& path);
std::vector<Quantity> parse_quantity_text(const std::string& text, const std::string& origin);
/// The same, with the foreign_keys declaration; every name it lists must be an
/// entry of the file (a stale declaration is an error naming it).
QuantityFile read_quantity_document(const std::filesystem::path& path);
QuantityFile parse_quantity_document(const std::string& text, const std::string& origin);

}  // namespace mesowave::io
