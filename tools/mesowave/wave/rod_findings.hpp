#pragma once
// The rod paper's findings (Knak et al. 2022, Section 5), checked on a study's
// own tables, so that the summary says "reproduced" or "NOT reproduced" from
// the numbers it prints:
//   1. the group velocity falls with frequency (the FEM and the usable chains);
//   2. 0.95R is the outlier: the largest RSS to theory (Table 2) and the lowest
//      PCC against the FEM (Table 1, envelopes, as the paper's Fig. 8b);
//   3. 1.03R is closest to theory and FEM among 1.03R, 1.05R, 1.15R;
//   4. denser spacing gives a higher group velocity, c_g(1.03R) > c_g(1.05R) >
//      c_g(1.15R), at every frequency (with the pairwise counts behind it).
// The tables are those the steel-rod study writes: velocities (key f_kHz, one
// column per model, theory and the FEM), table1 (model, ..., pcc_vs_fem_envelope)
// and table2 (model, rss_m2_s2).
#include <optional>
#include <string>
#include <vector>

#include "mesowave/io/csv.hpp"

namespace mesowave::wave {

struct RodFindings {
  std::string fem_column;             ///< the FEM's column of the velocity table ("FEM 1 mm")
  std::string f_low_kHz, f_high_kHz;  ///< the first and last frequency of the velocity table
  bool velocity_falls = false;        ///< finding 1: c_g(f_high) < c_g(f_low), FEM and usable chains
  std::string largest_rss, lowest_pcc;  ///< finding 2, among the paper's four chains
  std::string best_rss, best_pcc;       ///< finding 3, among the three usable chains
  int frequencies = 0;                ///< rows of the velocity table
  int ordered = 0;                    ///< finding 4: rows with c(1.03R) > c(1.05R) > c(1.15R)
  int faster_103_105 = 0, faster_105_115 = 0;  ///< the pairwise counts
  std::optional<std::string> faster_105_115_from_kHz;  ///< start of the last run of 1.05R > 1.15R to the end

  /// The findings as a Markdown check list ("- [x] ...", "- [ ] ... (NOT reproduced)").
  std::string markdown() const;
};

/// InputError naming the table for a missing model, column or frequency row.
RodFindings rod_findings(const io::CsvTable& velocity, const io::CsvTable& table1, const io::CsvTable& table2,
                         const std::string& fem_column);

}  // namespace mesowave::wave
