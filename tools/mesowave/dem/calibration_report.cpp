#include "mesowave/dem/calibration_report.hpp"

#include <cmath>

#include "mesowave/core/format.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/gnuplot.hpp"

namespace mesowave::dem {

std::string calibration_trials_csv(const std::vector<CalibrationTrial>& trials) {
  // Six significant digits: a log for people (the tolerances are 1 %, 0.01 and 2 %); each
  // trial's summary file has its numbers in full.
  auto n = [](double v) { return format_significant(v, 6); };
  std::vector<std::vector<std::string>> rows;
  for (const auto& t : trials) {
    const auto& p = t.parameters;
    const bool failure = t.kind == CalibrationTrial::Kind::failure;
    rows.push_back({std::to_string(t.number), t.kind_name(), t.model, n(p.E_dem_Pa / 1e9), n(p.nu_dem),
                    failure ? n(p.T_Pa / 1e6) : "", failure ? n(p.c_over_t * p.T_Pa / 1e6) : "", n(t.E_glob_Pa / 1e9),
                    n(t.nu_glob), failure ? n(t.peak_Pa / 1e6) : "", failure ? (t.peak_reached ? "yes" : "no") : "",
                    format_fixed(t.wall_s, 1), t.summary_file});
  }
  return io::to_csv({"trial", "kind", "model", "E_dem_GPa", "nu_dem", "T_MPa", "C_MPa", "E_glob_GPa", "nu_glob", "peak_MPa",
                     "peak_reached", "wall_s", "summary"},
                    rows);
}

std::string calibration_trajectory_script(const CompressionCalibration& c, const std::filesystem::path& png,
                                          const std::string& title) {
  const auto& tg = c.targets();
  const auto& tol = c.tolerances();
  std::vector<double> n, e, nu, en, enu, fn, fs;
  for (const auto& t : c.trials()) {
    const double k = t.number;
    (t.kind == CalibrationTrial::Kind::elastic ? en : fn).push_back(k);
    if (t.kind == CalibrationTrial::Kind::elastic) {
      e.push_back(100 * (t.E_glob_Pa / tg.E_Pa - 1));
      enu.push_back(t.nu_glob);
    } else {
      n.push_back(100 * (t.E_glob_Pa / tg.E_Pa - 1));
      nu.push_back(t.nu_glob);
      fs.push_back(100 * (t.peak_Pa / tg.sigma_Pa - 1));
    }
  }
  const double last = double(c.trials().size()) + 0.5;
  std::string s = "set terminal pngcairo size 1500,480 font 'Sans,11'\nset output " + io::gnuplot_quote(png) + "\n";
  s += io::gnuplot_datablock("el", {en, e, enu});
  s += io::gnuplot_datablock("fa", {fn, n, nu, fs});
  s += "set grid\nset xrange [0.5:" + format_number(last) + "]\nset xtics 1\nset xlabel 'trial'\n"
       "set style fill transparent solid 0.15 noborder\n";
  s += "set multiplot layout 1,3 title '" + title + "'\n";
  auto band = [&](double lo, double hi) {
    return "'+' using 1:(" + format_number(lo) + "):(" + format_number(hi) + ") with filledcurves lc rgb '#2e8b57' title 'tolerance', ";
  };
  const double te = 100 * tol.E_relative, ts = 100 * tol.sigma_relative;
  // Keys where the trials seldom go: the last trials sit at the targets (E: bottom right is
  // free), the first failure trial is never trial 1 (strength: bottom left), nu_glob starts
  // far from its band at most in trial 1 (top right).
  s += "set key bottom right\nset title 'E_{glob} against E_{st} = " + format_number(std::round(tg.E_Pa / 1e7) / 100) + " GPa'\n"
       "set ylabel 'E_{glob} / E_{st} - 1 [%]'\n"
       "plot " + band(-te, te) + "$el using 1:2 with linespoints pt 7 ps 1.4 lc rgb '#1f4e9c' title 'elastic trials', "
       "$fa using 1:2 with linespoints pt 5 ps 1.4 lc rgb '#c0392b' title 'failure trials'\n";
  s += "set key top right\nset title '{/Symbol n}_{glob} against {/Symbol n}_{st} = " + format_number(tg.nu) + "'\n"
       "set ylabel '{/Symbol n}_{glob}'\n"
       "plot " + band(tg.nu - tol.nu_absolute, tg.nu + tol.nu_absolute) +
       "$el using 1:3 with linespoints pt 7 ps 1.4 lc rgb '#1f4e9c' title 'elastic trials', "
       "$fa using 1:3 with linespoints pt 5 ps 1.4 lc rgb '#c0392b' title 'failure trials'\n";
  s += "set key bottom left\nset title '{/Symbol s}_{peak} against {/Symbol s}_{max} = " + format_number(std::round(tg.sigma_Pa / 1e4) / 100) +
       " MPa'\nset ylabel '{/Symbol s}_{peak} / {/Symbol s}_{max} - 1 [%]'\n"
       "plot " + band(-ts, ts) + "$fa using 1:4 with linespoints pt 5 ps 1.4 lc rgb '#c0392b' title 'failure trials'\n";
  s += "unset multiplot\n";
  return s;
}

std::string stress_strain_script(const StressStrainCurve& c, double E_target_Pa, double nu_target,
                                 const std::filesystem::path& png, const std::string& title) {
  std::vector<double> ax, lat, sig;
  for (std::size_t i = 0; i < c.stress_Pa.size(); ++i) {
    ax.push_back(c.axial[i] * 1e3);
    lat.push_back(c.lateral.empty() ? NAN : -c.lateral[i] * 1e3);
    sig.push_back(c.stress_Pa[i] / 1e6);
  }
  std::string s = "set terminal pngcairo size 1000,720 font 'Sans,11'\nset output " + io::gnuplot_quote(png) + "\n";
  s += io::gnuplot_datablock("c", {ax, lat, sig});
  // Lines through the lower reading (eps_b, sigma_b): slope E (axial) and E / nu (lateral).
  auto line = [&](double E, double nu, bool lateral) {
    const std::string slope = format_exact(lateral ? -E / nu / 1e9 : E / 1e9);  // MPa per 1e-3
    const std::string x0 = format_exact((lateral ? -c.eps_b * nu : c.eps_b) * 1e3);
    std::string expr = "(";
    expr.append(format_exact(c.sigma_b_Pa / 1e6)).append(" + ").append(slope).append(" * (x - ").append(x0).append("))");
    return expr;
  };
  // Each line from zero stress to just above the upper reading, on its own side of the strain axis.
  const std::string top = format_exact(1.05 * c.sigma_a_Pa / 1e6);
  auto segment = [&](double E, double nu, bool lateral) {
    const std::string f = line(E, nu, lateral);
    std::string expr = lateral ? "((x <= 0" : "((x >= 0";
    expr.append(" && ").append(f).append(" >= 0 && ").append(f).append(" <= ").append(top).append(") ? ").append(f).append(" : 1/0)");
    return expr;
  };
  auto gpa = [](double pa) { return format_number(std::round(pa / 1e7) / 100); };
  s += "set datafile missing 'nan'\nset grid\nset xlabel 'strain [10^{-3}] (lateral < 0 < axial)'\n"
       "set ylabel 'stress [MPa]'\nset yrange [0:*]\nset key below maxrows 4\nset title '" + title + "'\nset samples 800\n";
  s += "plot $c using 1:3 with lines lw 2 lc rgb '#1f4e9c' title 'axial strain', "
       "$c using 2:3 with lines lw 2 lc rgb '#8e44ad' title 'lateral strain', " +
       segment(c.E_glob_Pa, c.nu_glob, false) + " with lines dt 2 lw 2 lc rgb '#c0392b' title 'E_{glob} = " +
       gpa(c.E_glob_Pa) + " GPa (calibrated)', " + segment(E_target_Pa, nu_target, false) +
       " with lines dt 3 lw 2 lc rgb '#2e8b57' title 'E_{st} = " + gpa(E_target_Pa) + " GPa (target)', " +
       segment(c.E_glob_Pa, c.nu_glob, true) + " with lines dt 2 lw 2 lc rgb '#c0392b' title 'E_{glob} / {/Symbol n}_{glob}, {/Symbol n}_{glob} = " +
       format_number(std::round(c.nu_glob * 1000) / 1000) + "', " + segment(E_target_Pa, nu_target, true) +
       " with lines dt 3 lw 2 lc rgb '#2e8b57' title 'E_{st} / {/Symbol n}_{st}, {/Symbol n}_{st} = " + format_number(nu_target) + "', "
       "'+' using (" + format_exact(c.eps_b * 1e3) + "):(" + format_exact(c.sigma_b_Pa / 1e6) +
       ") with points pt 7 ps 1.5 lc rgb 'black' notitle, "
       "'+' using (" + format_exact(c.eps_a * 1e3) + "):(" + format_exact(c.sigma_a_Pa / 1e6) +
       ") with points pt 7 ps 1.5 lc rgb 'black' title 'secant readings (10 % and 1/3 of the peak)'\n";
  return s;
}

}  // namespace mesowave::dem
