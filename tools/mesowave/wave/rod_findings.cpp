#include "mesowave/wave/rod_findings.hpp"

#include <utility>

#include "mesowave/core/error.hpp"

namespace mesowave::wave {
namespace {

const std::vector<std::string> kPaperChains = {"0.95R", "1.03R", "1.05R", "1.15R"};
const std::vector<std::string> kUsableChains = {"1.03R", "1.05R", "1.15R"};

// A model's value in a table keyed by its first column.
double value_of(const io::CsvTable& table, const std::string& model, const std::string& column) {
  const auto col = table.column(column);
  for (std::size_t r = 0; r < table.rows.size(); ++r)
    if (table.text(r, 0) == model) return table.number(r, col);
  throw InputError(table.origin + " has no row for " + model);
}

// The model with the largest (or smallest) value; a tie goes to the name that
// sorts last (first), as `sort -g` of "value name" lines would order them.
std::string extreme(const io::CsvTable& table, const std::vector<std::string>& models, const std::string& column,
                    bool largest) {
  std::pair<double, std::string> best{value_of(table, models.front(), column), models.front()};
  for (const auto& m : models) {
    const std::pair<double, std::string> here{value_of(table, m, column), m};
    if (largest ? here > best : here < best) best = here;
  }
  return best.second;
}

std::string check(bool holds, const std::string& claim) {
  return holds ? "- [x] " + claim + "\n" : "- [ ] " + claim + " (NOT reproduced)\n";
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

RodFindings rod_findings(const io::CsvTable& velocity, const io::CsvTable& table1, const io::CsvTable& table2,
                         const std::string& fem_column) {
  if (velocity.rows.size() < 2)
    throw InputError(velocity.origin + ": the findings need at least two frequencies, it has " +
                     std::to_string(velocity.rows.size()));
  RodFindings f;
  f.fem_column = fem_column;
  const std::size_t last = velocity.rows.size() - 1;
  f.f_low_kHz = velocity.text(0, 0);
  f.f_high_kHz = velocity.text(last, 0);
  f.velocity_falls = true;
  std::vector<std::string> falling = kUsableChains;
  falling.push_back(fem_column);
  for (const auto& column : falling) {
    const auto c = velocity.column(column);
    if (!(velocity.number(last, c) < velocity.number(0, c))) f.velocity_falls = false;
  }
  f.largest_rss = extreme(table2, kPaperChains, "rss_m2_s2", true);
  f.lowest_pcc = extreme(table1, kPaperChains, "pcc_vs_fem_envelope", false);
  f.best_rss = extreme(table2, kUsableChains, "rss_m2_s2", false);
  f.best_pcc = extreme(table1, kUsableChains, "pcc_vs_fem_envelope", true);
  const auto a = velocity.column("1.03R"), b = velocity.column("1.05R"), c = velocity.column("1.15R");
  for (std::size_t r = 0; r < velocity.rows.size(); ++r) {
    const double ca = velocity.number(r, a), cb = velocity.number(r, b), cc = velocity.number(r, c);
    ++f.frequencies;
    if (ca > cb && cb > cc) ++f.ordered;
    if (ca > cb) ++f.faster_103_105;
    if (cb > cc) {
      ++f.faster_105_115;
      if (!f.faster_105_115_from_kHz) f.faster_105_115_from_kHz = velocity.text(r, 0);
    } else {
      f.faster_105_115_from_kHz.reset();
    }
  }
  return f;
}

std::string RodFindings::markdown() const {
  const std::string total = std::to_string(frequencies);
  std::string out;
  out += check(velocity_falls, "velocity falls with frequency (c_g at " + f_high_kHz + " kHz below " + f_low_kHz +
                                   " kHz for the FEM and the " + join(kUsableChains) + " chains)");
  out += check(largest_rss == "0.95R" && lowest_pcc == "0.95R",
               "0.95R is the outlier: largest RSS (" + largest_rss + ") and lowest PCC against the FEM (" + lowest_pcc +
                   ")");
  out += check(best_rss == "1.03R" && best_pcc == "1.03R", "1.03R is closest to theory and FEM among " +
                                                               join(kUsableChains) + " (lowest RSS: " + best_rss +
                                                               "; highest PCC: " + best_pcc + ")");
  out += check(ordered == frequencies, "denser spacing gives a higher group velocity: c_g(1.03R) > c_g(1.05R) > "
                                       "c_g(1.15R) at " +
                                           std::to_string(ordered) + " of " + total + " frequencies");
  out += "  - 1.03R faster than 1.05R at " + std::to_string(faster_103_105) + " of " + total +
         " frequencies; 1.05R faster than 1.15R at " + std::to_string(faster_105_115) + " of " + total +
         (faster_105_115_from_kHz ? " (from " + *faster_105_115_from_kHz + " kHz up)" : std::string()) + ".\n";
  return out;
}

}  // namespace mesowave::wave
