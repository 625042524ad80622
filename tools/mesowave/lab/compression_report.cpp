#include "mesowave/lab/compression_report.hpp"

#include <cmath>

#include "mesowave/core/format.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/gnuplot.hpp"

namespace mesowave::lab {

namespace {

std::string cell(double v, int digits) { return std::isfinite(v) ? format_fixed(v, digits) : ""; }

double mean_of(const std::vector<double>& strain, const CyclicResult& r) {
  double sum = 0;
  int n = 0;
  for (std::size_t c = 0; c < r.channels.size(); ++c)
    if (r.channels[c].used) sum += strain[c], ++n;
  return n ? sum / n : NAN;
}

}  // namespace

nlohmann::ordered_json compression_summary(const CompressionAnalysis& a) {
  nlohmann::ordered_json j;
  std::vector<std::string> warnings, notes;
  if (a.cyclic) {
    const auto& r = *a.cyclic;
    const auto& ev = r.cycles[std::size_t(r.evaluated_cycle - 1)];
    j["E_st_GPa"] = r.E_st_Pa / 1e9;
    j["E_st_measured_GPa"] = r.E_st_Pa / 1e9;
    j["E_st_method"] = "EN 12390-13 clause 8.2: (sigma_a - sigma_b) / (eps_a,3 - eps_b,2), cycle " +
                       std::to_string(r.evaluated_cycle);
    j["cycles_found"] = r.cycles.size();
    j["evaluated_cycle"] = r.evaluated_cycle;
    j["sigma_a_MPa"] = r.sigma_a_Pa / 1e6;
    j["sigma_b_MPa"] = r.sigma_b_Pa / 1e6;
    j["eps_a_ustrain"] = r.eps_a * 1e6;
    j["eps_b_ustrain"] = r.eps_b * 1e6;
    j["hold_upper_s"] = ev.upper.hold ? ev.upper.hold_s : 0.0;
    j["hold_lower_s"] = ev.lower->hold ? ev.lower->hold_s : 0.0;
    j["reading_upper_s"] = ev.upper.t1_s - ev.upper.t0_s;
    j["loading_rate_MPa_s"] = ev.loading_rate_Pa_s / 1e6;
    auto per_cycle = nlohmann::ordered_json::array();  // null where a cycle could not be evaluated
    for (const auto& c : r.cycles) per_cycle.push_back(c.E_Pa ? nlohmann::ordered_json(*c.E_Pa / 1e9) : nullptr);
    j["E_cycles_GPa"] = per_cycle;
    if (r.cycles.front().E_ramp_Pa) j["E_first_ramp_GPa"] = *r.cycles.front().E_ramp_Pa / 1e9;
    auto used = nlohmann::ordered_json::array();
    for (const auto& c : r.channels)
      if (c.used) used.push_back(c.name);
    j["extensometers_used"] = used;
    j["gauge_length_mm"] = a.gauge_length_m * 1e3;
    warnings.insert(warnings.end(), r.warnings.begin(), r.warnings.end());
    notes.insert(notes.end(), a.cyclic_record->notes.begin(), a.cyclic_record->notes.end());
  }
  if (a.fit) {
    j["crosshead_multiplier"] = a.fit->multiplier;
    j["crosshead_multiplier_inverse"] = 1.0 / a.fit->multiplier;
    j["crosshead_fit_r2"] = a.fit->r2;
    j["crosshead_fit_rms_ustrain"] = a.fit->rms_strain * 1e6;
    j["crosshead_fit_points"] = a.fit->points;
    j["crosshead_fit_from_cycle"] = a.fit->from_cycle;
    if (a.fit->r2 < 0.99)
      warnings.push_back("the crosshead fit is loose (R^2 = " + format_fixed(a.fit->r2, 4) +
                         "): crosshead and extensometer strain are not proportional over the cycles");
  }
  if (a.failure) {
    const auto& f = *a.failure;
    j["sigma_max_MPa"] = f.sigma_max_Pa / 1e6;
    j["F_max_kN"] = f.sigma_max_Pa * a.area_m2 / 1e3;
    j["t_peak_s"] = f.t_peak_s;
    j["failure_detected"] = f.broke;
    if (a.multiplier) {
      j["multiplier_applied"] = *a.multiplier;
      j["multiplier_source"] = a.multiplier_source;
    }
    if (f.strain_at_peak) j["strain_at_peak_permille"] = *f.strain_at_peak * 1e3;
    warnings.insert(warnings.end(), f.warnings.begin(), f.warnings.end());
    notes.insert(notes.end(), a.failure_record->notes.begin(), a.failure_record->notes.end());
  }
  j["area_mm2"] = a.area_m2 * 1e6;
  if (a.specimen_height_m) j["specimen_height_mm"] = *a.specimen_height_m * 1e3;
  if (!a.geometry_note.empty()) notes.push_back(a.geometry_note);
  j["warnings"] = warnings;
  j["notes"] = notes;
  return j;
}

std::vector<std::string> compression_products(const CompressionAnalysis& a) {
  std::vector<std::string> products;
  if (a.cyclic) products.push_back("E_st_measured_GPa");
  if (a.failure) products.push_back("sigma_max_MPa");
  return products;
}

std::string cycles_csv(const CompressionAnalysis& a) {
  std::vector<std::vector<std::string>> rows;
  const auto& r = *a.cyclic;
  for (const auto& c : r.cycles) {
    const bool lower = c.lower.has_value();
    rows.push_back({std::to_string(c.number), lower ? cell(c.lower->t1_s, 2) : "",
                    lower ? cell(c.lower->stress_Pa / 1e6, 4) : "", lower ? cell(mean_of(c.lower->strain, r) * 1e6, 2) : "",
                    lower ? (c.lower->hold ? cell(c.lower->hold_s, 1) : "0") : "", cell(c.upper.t1_s, 2),
                    cell(c.upper.stress_Pa / 1e6, 4), cell(mean_of(c.upper.strain, r) * 1e6, 2),
                    c.upper.hold ? cell(c.upper.hold_s, 1) : "0", cell(c.loading_rate_Pa_s / 1e6, 4),
                    c.E_Pa ? cell(*c.E_Pa / 1e9, 4) : "", c.E_ramp_Pa ? cell(*c.E_ramp_Pa / 1e9, 4) : "", c.number == r.evaluated_cycle ? "yes" : "", c.note});
  }
  return io::to_csv({"cycle", "t_lower_s", "sigma_lower_MPa", "eps_lower_ustrain", "hold_lower_s", "t_upper_s",
                     "sigma_upper_MPa", "eps_upper_ustrain", "hold_upper_s", "loading_rate_MPa_s", "E_secant_GPa", "E_ramp_GPa",
                     "evaluated", "note"},
                    rows);
}

std::string cyclic_curve_csv(const CompressionAnalysis& a) {
  const auto& rec = *a.cyclic_record;
  const auto eps = mean_extensometer_strain(rec, *a.cyclic, a.gauge_length_m);
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < rec.t_s.size(); ++i) {
    std::vector<std::string> row = {cell(rec.t_s[i], 3), cell(rec.stress_Pa[i] / 1e6, 5), cell(eps[i] * 1e6, 3)};
    if (!rec.crosshead_m.empty() && a.specimen_height_m) {
      const double x = (rec.crosshead_m[i] - rec.crosshead_m.front()) / *a.specimen_height_m;
      row.push_back(cell(x * 1e6, 3));
      row.push_back(a.fit ? cell(a.fit->multiplier * x * 1e6, 3) : "");
    } else {
      row.insert(row.end(), {"", ""});
    }
    rows.push_back(row);
  }
  return io::to_csv({"t_s", "stress_MPa", "strain_extensometer_ustrain", "strain_crosshead_ustrain",
                     "strain_crosshead_corrected_ustrain"},
                    rows);
}

std::string failure_curve_csv(const CompressionAnalysis& a) {
  const auto& rec = *a.failure_record;
  const auto& f = *a.failure;
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < rec.t_s.size(); ++i)
    rows.push_back({cell(rec.t_s[i], 3), cell(rec.stress_Pa[i] / 1e6, 5),
                    f.crosshead_strain.empty() ? "" : cell(f.crosshead_strain[i] * 1e6, 3),
                    f.strain.empty() ? "" : cell(f.strain[i] * 1e6, 3)});
  return io::to_csv({"t_s", "stress_MPa", "strain_crosshead_ustrain", "strain_corrected_ustrain"}, rows);
}

std::string figure5_script(const CompressionAnalysis& a, const std::filesystem::path& png, const std::string& title) {
  std::string s = "set terminal pngcairo size 1400,560 font 'Sans,11'\nset output " + io::gnuplot_quote(png) + "\n";
  const bool two = a.cyclic.has_value();
  if (two) {
    const auto& rec = *a.cyclic_record;
    const auto eps = mean_extensometer_strain(rec, *a.cyclic, a.gauge_length_m);
    std::vector<double> t, sig, e, x;
    // Up to the end of the last cycle: what follows (unloading, sensors taken
    // off) is not part of the test.
    const std::size_t last = std::min(rec.t_s.size() - 1, a.cyclic->cycles.back().end + 1);
    // From the start - or, when an extensometer was zeroed as the first ramp
    // began, from the end of the first lower reading.
    bool zeroed = false;
    for (const auto& c : a.cyclic->cycles) zeroed = zeroed || c.note.find("jumps") != std::string::npos;
    const auto& c1 = a.cyclic->cycles.front();
    const std::size_t first = zeroed && c1.lower ? c1.lower->last + 1 : 0;
    for (std::size_t i = first; i <= last; ++i) {
      t.push_back(rec.t_s[i]);
      sig.push_back(rec.stress_Pa[i] / 1e6);
      e.push_back(std::isfinite(eps[i]) ? eps[i] * 1e3 : NAN);
      x.push_back(!rec.crosshead_m.empty() && a.specimen_height_m
                      ? (rec.crosshead_m[i] - rec.crosshead_m[first]) / *a.specimen_height_m * 1e3
                      : NAN);
    }
    // Strains from the first plotted sample, so that the curves start at the origin.
    const double e0 = std::isfinite(e.front()) ? e.front() : a.cyclic->eps_b * 1e3;
    for (double& v : e) v -= e0;
    s += io::gnuplot_datablock("cyc", {t, sig, e, x});
    std::vector<double> rt, rs;
    for (const auto& c : a.cyclic->cycles) {
      if (c.lower) rt.push_back(0.5 * (c.lower->t0_s + c.lower->t1_s)), rs.push_back(c.lower->stress_Pa / 1e6);
      rt.push_back(0.5 * (c.upper.t0_s + c.upper.t1_s));
      rs.push_back(c.upper.stress_Pa / 1e6);
    }
    s += io::gnuplot_datablock("reads", {rt, rs});
  }
  if (a.failure) {
    const auto& rec = *a.failure_record;
    std::vector<double> sig, e;
    // Up to the first sample after the peak below 20 % of it: the crushed
    // specimen and the retracting crosshead tell nothing more.
    std::size_t last = a.failure->peak_index;
    const auto& fs = a.failure->strain;
    while (last + 1 < rec.t_s.size() && rec.stress_Pa[last] >= 0.2 * a.failure->sigma_max_Pa &&
           (fs.empty() || fs[last + 1] >= fs[last]))
      ++last;
    for (std::size_t i = 0; i <= last; ++i) {
      sig.push_back(rec.stress_Pa[i] / 1e6);
      e.push_back(a.failure->strain.empty() ? NAN : a.failure->strain[i] * 1e3);
    }
    s += io::gnuplot_datablock("fail", {e, sig});
  }
  s += "set datafile missing 'nan'\nset grid\n";
  if (!title.empty()) s += "set multiplot layout 1," + std::string(two ? "2" : "1") + " title '" + title + "'\n";
  else s += "set multiplot layout 1," + std::string(two ? "2" : "1") + "\n";
  if (two) {
    s += "set title '(a) cyclic test: stress-time'\nset xlabel 'time [s]'\nset ylabel 'stress [MPa]'\n"
         "set key top center horizontal\nset offsets 0, 0, graph 0.22, 0\n"
         "plot $cyc using 1:2 with lines lw 2 lc rgb '#1f4e9c' title 'stress', "
         "$reads using 1:2 with points pt 7 ps 1.2 lc rgb '#d35400' title 'readings (EN 12390-13)'\n";
  }
  s += "set title '(" + std::string(two ? "b" : "a") + ") stress-strain'\nset xlabel 'strain [per mille]'\n"
       "set ylabel 'stress [MPa]'\nset key left top Left reverse\nset offsets 0, 0, 0, 0\nplot ";
  std::string plots;
  if (two) {
    plots += "$cyc using 3:2 with lines lw 2 lc rgb '#1f4e9c' title 'cyclic test, extensometers'";
    if (a.cyclic_record->crosshead_m.size() && a.specimen_height_m)
      plots += ", $cyc using 4:2 with lines lw 1.5 lc rgb '#c2189b' title 'cyclic test, crosshead'";
  }
  if (a.failure && !a.failure->strain.empty()) {
    if (!plots.empty()) plots += ", ";
    plots += "$fail using 1:2 with lines lw 2 lc rgb '#c0392b' title sprintf('failure test, crosshead x %.4f (1/%.2f)', " +
             format_exact(*a.multiplier) + ", " + format_exact(1.0 / *a.multiplier) + ")";
  }
  if (plots.empty()) plots = "$fail using 0:2 with lines lw 2 lc rgb '#c0392b' title 'failure test (no strain)'";
  s += plots + "\nunset multiplot\n";
  return s;
}

}  // namespace mesowave::lab
