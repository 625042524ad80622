#include "mesowave/dem/calibration/uniaxial_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::dem {
namespace {

std::string mpa(double pa) { return format_number(std::round(pa / 1e4) / 100) + " MPa"; }

const signal::Signal& find_signal(const std::map<std::string, const signal::Signal*>& by_name, const std::string& name) {
  auto it = by_name.find(name);
  if (it == by_name.end()) throw InputError("[test] names sensor \"" + name + "\", which the run did not record");
  return *it->second;
}

/// Mean of the named signals, sample by sample, over the first n samples.
std::vector<double> mean_of(const std::map<std::string, const signal::Signal*>& by_name,
                            const std::vector<std::string>& names, std::size_t n) {
  std::vector<double> out(n, 0.0);
  for (const auto& name : names) {
    const auto& s = find_signal(by_name, name).samples;
    for (std::size_t i = 0; i < n; ++i) out[i] += s[i];
  }
  for (double& v : out) v /= double(names.size());
  return out;
}

/// First crossing of `level` by `stress` at or before `last`, as a fractional
/// sample index (linear between the samples around it); nullopt if none.
std::optional<double> first_crossing(const std::vector<double>& stress, double level, std::size_t last) {
  for (std::size_t i = 0; i <= last; ++i) {
    if (stress[i] < level) continue;
    if (i == 0) return 0.0;
    const double w = (level - stress[i - 1]) / (stress[i] - stress[i - 1]);
    return double(i - 1) + w;
  }
  return std::nullopt;
}

double at(const std::vector<double>& v, double index) {
  const auto i = std::size_t(std::floor(index));
  if (i + 1 >= v.size()) return v.back();
  const double w = index - double(i);
  return (1 - w) * v[i] + w * v[i + 1];
}

struct LineFit {
  double slope = 0, r2 = 0;
};
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y, std::size_t begin, std::size_t end) {
  const double n = double(end - begin);
  double mx = 0, my = 0;
  for (std::size_t i = begin; i < end; ++i) mx += x[i], my += y[i];
  mx /= n, my /= n;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = begin; i < end; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  LineFit f;
  f.slope = sxx > 0 ? sxy / sxx : 0;
  f.r2 = sxx > 0 && syy > 0 ? sxy * sxy / (sxx * syy) : 0;
  return f;
}

}  // namespace

std::vector<std::string> UniaxialTestSpec::sensor_names() const {
  std::vector<std::string> names = load;
  names.insert(names.end(), axial.begin(), axial.end());
  names.insert(names.end(), lateral.begin(), lateral.end());
  if (!broken_bonds.empty()) names.push_back(broken_bonds);
  return names;
}

bool UniaxialTestMonitor::stop_after(const std::vector<double>& loads) {
  double p = 0;
  for (double f : loads) p += f;
  const double stress = p / double(loads.size()) / area_;
  if (spec_.stop_at_Pa > 0 && stress >= spec_.stop_at_Pa) {
    reason_ = "the stress reached " + mpa(stress) + " (stop_at_MPa = " + mpa(spec_.stop_at_Pa) + ")";
    return true;
  }
  peak_ = std::max(peak_, stress);
  if (spec_.stop_drop > 0 && peak_ >= spec_.stop_armed_above_Pa && stress < (1 - spec_.stop_drop) * peak_) {
    reason_ = "the stress fell to " + mpa(stress) + ", " + format_number(spec_.stop_drop * 100) +
              " % below its peak " + mpa(peak_);
    return true;
  }
  return false;
}

UniaxialTestResult analyse_uniaxial_test(const std::vector<signal::Signal>& signals, const UniaxialTestSpec& spec,
                                         const UniaxialTestSpecimen& specimen) {
  std::map<std::string, const signal::Signal*> by_name;
  for (const auto& s : signals) by_name[s.name] = &s;
  const auto names = spec.sensor_names();
  std::size_t n = SIZE_MAX;
  const double dt = find_signal(by_name, names.front()).dt_s;
  for (const auto& name : names) {
    const auto& s = find_signal(by_name, name);
    if (std::abs(s.dt_s - dt) > 1e-9 * dt)
      throw InputError("[test]: sensor " + name + " samples every " + format_number(s.dt_s * 1e9) + " ns, " +
                       names.front() + " every " + format_number(dt * 1e9) + " ns; a test's sensors must sample together");
    n = std::min(n, s.size());
  }
  if (n < 3) throw InputError("[test]: the run recorded " + std::to_string(n) + " samples; a curve needs at least 3");

  UniaxialTestResult r;
  r.kind = spec.kind_name();
  r.area_m2 = specimen.area_m2;
  r.inertial_number_bound = spec.inertial_number_bound;
  const double sign = spec.kind == UniaxialTestSpec::Kind::compression ? -1.0 : 1.0;
  const std::vector<double> load = mean_of(by_name, spec.load, n);
  const std::vector<double> axial = mean_of(by_name, spec.axial, n);
  r.time_s.resize(n);
  r.stress_Pa.resize(n);
  r.axial_strain.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    r.time_s[i] = find_signal(by_name, spec.load.front()).time(i);
    r.stress_Pa[i] = load[i] / specimen.area_m2;
    r.axial_strain[i] = sign * axial[i];
  }
  if (!spec.lateral.empty()) r.lateral_strain = mean_of(by_name, spec.lateral, n);
  if (!spec.broken_bonds.empty()) r.broken_bonds = mean_of(by_name, {spec.broken_bonds}, n);

  r.peak_index = std::size_t(std::max_element(r.stress_Pa.begin(), r.stress_Pa.end()) - r.stress_Pa.begin());
  r.peak_stress_Pa = r.stress_Pa[r.peak_index];
  r.strain_at_peak = r.axial_strain[r.peak_index];
  r.time_at_peak_s = r.time_s[r.peak_index];
  r.peak_reached = r.stress_Pa.back() < 0.95 * r.peak_stress_Pa;
  if (!r.peak_reached)
    r.notes.push_back("the stress was still at its maximum when the run ended: peak_stress is the largest stress "
                      "reached, not a strength");
  if (!(r.peak_stress_Pa > 0)) throw InputError("[test]: the stress never became positive: check the load sensors");

  r.sigma_b_Pa = spec.levels_absolute ? spec.levels[0] : spec.levels[0] * r.peak_stress_Pa;
  r.sigma_a_Pa = spec.levels_absolute ? spec.levels[1] : spec.levels[1] * r.peak_stress_Pa;
  const auto ib = first_crossing(r.stress_Pa, r.sigma_b_Pa, r.peak_index);
  const auto ia = first_crossing(r.stress_Pa, r.sigma_a_Pa, r.peak_index);
  if (!ia || !ib)
    throw InputError("[test]: the stress reached only " + mpa(r.peak_stress_Pa) + ", below the upper modulus level " +
                     mpa(r.sigma_a_Pa) + "; run longer or lower modulus_levels_MPa");
  r.eps_b = at(r.axial_strain, *ib);
  r.eps_a = at(r.axial_strain, *ia);
  if (!(r.eps_a > r.eps_b))
    throw InputError("[test]: the axial strain does not grow between " + mpa(r.sigma_b_Pa) + " and " +
                     mpa(r.sigma_a_Pa) + " (" + format_number(r.eps_b) + " -> " + format_number(r.eps_a) +
                     "): check the extensometers' axis and the test kind");
  r.E_secant_Pa = (r.sigma_a_Pa - r.sigma_b_Pa) / (r.eps_a - r.eps_b);
  if (!r.lateral_strain.empty())
    r.nu_secant = -sign * (at(r.lateral_strain, *ia) - at(r.lateral_strain, *ib)) / (r.eps_a - r.eps_b);

  const auto begin = std::size_t(std::ceil(*ib)), end = std::size_t(std::floor(*ia)) + 1;
  r.fit_points = end > begin ? end - begin : 0;
  if (r.fit_points >= 3) {
    const LineFit e = fit_line(r.axial_strain, r.stress_Pa, begin, end);
    r.E_fit_Pa = e.slope;
    r.E_fit_r2 = e.r2;
    if (!r.lateral_strain.empty()) r.nu_fit = -sign * fit_line(r.axial_strain, r.lateral_strain, begin, end).slope;
  } else {
    r.notes.push_back("fewer than 3 samples between the modulus levels: no least-squares modulus (sample more often)");
  }

  const double t_b = at(r.time_s, *ib), t_a = at(r.time_s, *ia);
  r.strain_rate_1_s = t_a > t_b ? (r.eps_a - r.eps_b) / (t_a - t_b) : 0;
  for (std::size_t i = begin; i <= r.peak_index; ++i)
    if (r.stress_Pa[i] > 0)
      r.inertial_number_max =
          std::max(r.inertial_number_max, r.strain_rate_1_s * specimen.grain_diameter_m *
                                              std::sqrt(specimen.particle_density_kg_m3 / r.stress_Pa[i]));
  if (spec.inertial_number_bound > 0 && r.inertial_number_max > spec.inertial_number_bound)
    throw InputError("[test]: the inertial number reached " + format_number(r.inertial_number_max) +
                     " (strain rate " + format_number(r.strain_rate_1_s) + " 1/s), above the quasi-static bound " +
                     format_number(spec.inertial_number_bound) + ": load more slowly");
  if (!r.broken_bonds.empty()) {
    r.broken_bonds_at_peak = std::size_t(std::llround(r.broken_bonds[r.peak_index]));
    r.broken_bonds_final = std::size_t(std::llround(r.broken_bonds.back()));
  }
  return r;
}

std::string uniaxial_curves_csv(const UniaxialTestResult& r) {
  std::ostringstream out;
  out << "t_s,stress_MPa,axial_strain,lateral_strain,broken_bonds\n";
  for (std::size_t i = 0; i < r.time_s.size(); ++i) {
    out << format_exact(r.time_s[i]) << ',' << format_exact(r.stress_Pa[i] / 1e6) << ','
        << format_exact(r.axial_strain[i]) << ',';
    if (!r.lateral_strain.empty()) out << format_exact(r.lateral_strain[i]);
    out << ',';
    if (!r.broken_bonds.empty()) out << format_exact(r.broken_bonds[i]);
    out << '\n';
  }
  return out.str();
}

std::vector<signal::Signal> uniaxial_curve_signals(const UniaxialTestResult& r) {
  const double t0 = r.time_s.front(), dt = r.time_s.size() > 1 ? r.time_s[1] - r.time_s[0] : 0;
  auto make = [&](std::string name, std::string quantity, std::string unit, const std::vector<double>& v) {
    return signal::Signal{.name = std::move(name), .quantity = std::move(quantity), .unit = std::move(unit),
                          .component = std::string("test"), .t0_s = t0, .dt_s = dt, .samples = v,
                          .position_m = std::nullopt};
  };
  std::vector<signal::Signal> out = {make("test.stress", "stress", "Pa", r.stress_Pa),
                                     make("test.axial_strain", "strain", "1", r.axial_strain)};
  if (!r.lateral_strain.empty()) out.push_back(make("test.lateral_strain", "strain", "1", r.lateral_strain));
  return out;
}

}  // namespace mesowave::dem
