#pragma once
// The ground truth written beside synthetic raw data: a lab-data TOML file
// (io/quantity_file.hpp layout) whose entries are labelled source = "synthetic"
// and cite the generating command, so that tests and people can compare a
// tool's result with what was put in.
#include <string>
#include <vector>

namespace mesowave::lab {

struct TruthEntry {
  std::string name;      ///< e.g. true_porosity
  double value = 0;
  std::string unit;      ///< "" for dimensionless
  std::string cite;      ///< what exactly the value is
  std::string source = "synthetic";  ///< synthetic (made by the generator) or paper/assumed for setup values
};

/// TOML text: a comment block (title, the command that made the data), every
/// entry declared foreign (`foreign_keys`: a tool reading the file with --from
/// takes what its options name and leaves the answers), then one table per
/// entry with value, unit, source and cite.
std::string truth_toml(const std::string& title, const std::string& command, const std::vector<TruthEntry>& entries);

/// The first line of a synthetic record (CSV: a comment the readers skip), so
/// that the file itself says it is not a measurement. It names no file: the
/// same seed gives the same bytes whatever the outputs are called.
std::string synthetic_record_label();

}  // namespace mesowave::lab
