#include "mesowave/wave/dispersion_output.hpp"

#include <cmath>
#include <algorithm>
#include <map>
#include <numbers>

#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/hdf5.hpp"
#include "mesowave/wave/group_velocity.hpp"

namespace mesowave::wave {

namespace {
constexpr double two_pi = 2 * std::numbers::pi;
std::string num(double v) { return format_exact(v); }
}  // namespace

std::vector<double> frequency_grid(double f_min, double f_max, double df) {
  require_positive("frequency step", df, "Hz");
  require_positive("minimum frequency", f_min, "Hz");
  require_positive("maximum frequency", f_max, "Hz");
  if (f_min > f_max) throw InputError("minimum frequency (" + format_quantity(f_min / units::kHz, "kHz") +
                                      ") exceeds the maximum (" + format_quantity(f_max / units::kHz, "kHz") + ")");
  const auto n = static_cast<long>(std::floor((f_max - f_min) / df * (1 + 1e-12)));
  if (n > 10'000'000) throw InputError("frequency grid has more than 10 million points; use a larger step");
  std::vector<double> f;
  for (long i = 0; i <= n; ++i) f.push_back(f_min + double(i) * df);
  return f;
}

LatticeCurve lattice_curve(std::string label, const MassSpringChain& chain, const std::vector<double>& f_Hz) {
  validate(chain);
  LatticeCurve c{std::move(label), chain, {}};
  for (double f : f_Hz)
    if (const auto p = lattice_at_frequency(chain, two_pi * f)) c.points.push_back(*p);
  return c;
}

VelocityCurve read_velocity_curve(const std::filesystem::path& path, std::string label) {
  const auto t = io::read_csv(path);
  const auto fc = t.column("f_kHz"), cc = t.column("c_group_m_s");
  const auto mc = t.find_column("mode");
  VelocityCurve c{std::move(label), {}, {}};
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    if (mc && t.text(r, *mc) != "1" && t.text(r, *mc) != mode_name(1)) continue;
    c.f_Hz.push_back(t.number(r, fc) * units::kHz);
    c.c_group_m_s.push_back(t.number(r, cc));
  }
  if (c.f_Hz.empty()) throw InputError(path.string() + " has no rows to plot");
  return c;
}

std::string theory_csv(const std::vector<DispersionPoint>& pts, double a) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& p : pts)
    rows.push_back({mode_name(p.mode), std::to_string(p.branch), p.c_group_m_s < 0 ? "backward" : "forward",
                    num(p.f_Hz / units::kHz), num(p.k_rad_m), num(p.k_rad_m * a), num(p.c_phase_m_s),
                    num(p.c_group_m_s)});
  return io::to_csv({"mode", "branch", "direction", "f_kHz", "k_rad_m", "ka", "c_phase_m_s", "c_group_m_s"}, rows);
}

std::string lattice_csv(const LatticeCurve& c) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& p : c.points)
    rows.push_back({c.label, num(p.omega_rad_s / two_pi / units::kHz), num(p.k_rad_m),
                    num(p.k_rad_m * c.chain.spacing_m), num(p.c_phase_m_s), num(p.c_group_m_s)});
  return io::to_csv({"model", "f_kHz", "k_rad_m", "kd", "c_phase_m_s", "c_group_m_s"}, rows);
}

void write_dispersion_h5(const std::filesystem::path& path, const PochhammerChree& pc,
                         const std::vector<DispersionPoint>& pts, const std::vector<LatticeCurve>& lattices) {
  namespace h5 = io::h5;
  auto file = h5::create_file(path);
  h5::set_attribute(file.id(), "format", std::string("mesowave-dispersion"));
  h5::set_attribute(file.id(), "format_version", std::int64_t(1));
  auto g = h5::create_group(file.id(), "theory");
  h5::set_attribute(g.id(), "model", std::string("Pochhammer-Chree, longitudinal modes L(0,n)"));
  h5::set_attribute(g.id(), "E_Pa", pc.material().E_Pa);
  h5::set_attribute(g.id(), "nu", pc.material().nu);
  h5::set_attribute(g.id(), "rho_kg_m3", pc.material().rho_kg_m3);
  h5::set_attribute(g.id(), "radius_m", pc.radius_m());
  h5::set_attribute(g.id(), "c0_m_s", pc.speeds().c0);
  std::vector<std::int64_t> mode, branch;
  std::vector<double> f, k, cp, cg;
  for (const auto& p : pts) {
    mode.push_back(p.mode);
    branch.push_back(p.branch);
    f.push_back(p.f_Hz);
    k.push_back(p.k_rad_m);
    cp.push_back(p.c_phase_m_s);
    cg.push_back(p.c_group_m_s);
  }
  h5::write_int64s(g.id(), "mode", mode);
  h5::write_int64s(g.id(), "branch", branch);
  h5::write_doubles(g.id(), "f_Hz", f);
  h5::write_doubles(g.id(), "k_rad_m", k);
  h5::write_doubles(g.id(), "c_phase_m_s", cp);
  h5::write_doubles(g.id(), "c_group_m_s", cg);
  if (lattices.empty()) return;
  auto lg = h5::create_group(file.id(), "lattice");
  for (const auto& c : lattices) {
    auto cgp = h5::create_group(lg.id(), c.label);
    h5::set_attribute(cgp.id(), "mass_kg", c.chain.mass_kg);
    h5::set_attribute(cgp.id(), "stiffness_N_m", c.chain.stiffness_N_m);
    h5::set_attribute(cgp.id(), "spacing_m", c.chain.spacing_m);
    std::vector<double> lf, lk, lcp, lcg;
    for (const auto& p : c.points) {
      lf.push_back(p.omega_rad_s / two_pi);
      lk.push_back(p.k_rad_m);
      lcp.push_back(p.c_phase_m_s);
      lcg.push_back(p.c_group_m_s);
    }
    h5::write_doubles(cgp.id(), "f_Hz", lf);
    h5::write_doubles(cgp.id(), "k_rad_m", lk);
    h5::write_doubles(cgp.id(), "c_phase_m_s", lcp);
    h5::write_doubles(cgp.id(), "c_group_m_s", lcg);
  }
}

io::PlotSpec group_velocity_plot(const std::string& title, const std::vector<DispersionPoint>& theory,
                             const std::vector<LatticeCurve>& lattices, const std::vector<VelocityCurve>& overlays) {
  io::PlotSpec spec;
  spec.title = title;
  spec.x_label = "frequency [kHz]";
  spec.y_label = "group velocity [m/s]";
  std::map<std::pair<int, int>, io::PlotSeries> branches;
  static const char* colours[] = {"#000000", "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#8c564b"};
  for (const auto& p : theory) {
    auto& s = branches[{p.mode, p.branch}];
    if (s.x.empty()) {
      const bool backward = p.c_group_m_s < 0;
      s.label = "theory " + mode_name(p.mode) + (p.branch > 0 || backward ? (backward ? " backward" : " forward") : "");
      s.style = std::string("lines lw 2 dt ") + (backward ? "2" : "1") + " lc rgb '" + colours[(p.mode - 1) % 6] + "'";
    }
    s.x.push_back(p.f_Hz / units::kHz);
    s.y.push_back(p.c_group_m_s);
  }
  for (auto& [key, s] : branches) spec.series.push_back(std::move(s));
  static const char* lattice_colours[] = {"#ff7f0e", "#17becf", "#e377c2", "#7f7f7f", "#bcbd22", "#2ca02c"};
  for (std::size_t i = 0; i < lattices.size(); ++i) {
    io::PlotSeries s;
    s.label = "DEM chain " + lattices[i].label + " (lattice)";
    s.style = std::string("lines lw 2 dt 4 lc rgb '") + lattice_colours[i % 6] + "'";
    for (const auto& p : lattices[i].points) {
      s.x.push_back(p.omega_rad_s / two_pi / units::kHz);
      s.y.push_back(p.c_group_m_s);
    }
    spec.series.push_back(std::move(s));
  }
  static const char* overlay_colours[] = {"#ff7f0e", "#bcbd22", "#17becf", "#e377c2", "#7f7f7f", "#2ca02c", "#8c564b"};
  for (std::size_t i = 0; i < overlays.size(); ++i) {
    const auto& o = overlays[i];
    io::PlotSeries s;
    s.label = o.label;
    // Dense tables (a lattice curve) as lines, sparse ones (measurements) as points.
    s.style = std::string(o.f_Hz.size() > 40 ? "lines lw 2.5 dt 2" : "linespoints lw 1.5 pt 7 ps 1") + " lc rgb '" +
              overlay_colours[i % 7] + "'";
    for (std::size_t j = 0; j < o.f_Hz.size(); ++j) {
      s.x.push_back(o.f_Hz[j] / units::kHz);
      s.y.push_back(o.c_group_m_s[j]);
    }
    spec.series.push_back(std::move(s));
  }
  return spec;
}

std::optional<std::string> signal_file_attribute(const std::filesystem::path& path, const std::string& name) {
  auto file = io::h5::open_file(path);
  if (!io::h5::has_attribute(file.id(), name)) return std::nullopt;
  return io::h5::string_attribute(file.id(), name);
}

SpaceTimeRecord read_spacetime_file(const std::filesystem::path& path) {
  namespace h5 = io::h5;
  auto file = h5::open_file(path);
  auto g = h5::open_group(file.id(), "spacetime", path.string());
  SpaceTimeRecord r;
  std::vector<hsize_t> shape;
  r.samples = h5::read_doubles(g.id(), "samples", &shape);
  if (shape.size() != 2) throw InputError(path.string() + ": /spacetime/samples must be 2-D (time x position)");
  r.times = shape[0];
  r.positions = shape[1];
  r.dt_s = h5::double_attribute(g.id(), "dt_s");
  const auto x = h5::read_doubles(g.id(), "position_m");
  if (x.size() != r.positions || x.size() < 2) throw InputError(path.string() + ": position_m does not match the samples");
  r.dx_m = (x.back() - x.front()) / double(x.size() - 1);
  for (std::size_t j = 1; j < x.size(); ++j)
    if (std::abs(x[j] - x[j - 1] - r.dx_m) > 1e-6 * r.dx_m)
      throw InputError(path.string() + ": the space-time positions are not uniformly spaced");
  return r;
}

std::vector<double> l01_group_velocity(const PochhammerChree& pc, const std::vector<double>& f_Hz) {
  if (f_Hz.empty()) return {};
  TraceOptions opt;
  opt.f_max_Hz = *std::max_element(f_Hz.begin(), f_Hz.end()) * 1.01;
  const auto trace = trace_longitudinal_modes(pc, opt);
  std::vector<double> out;
  for (double f : f_Hz) {
    double c = 0;
    for (const auto& p : sample_at_frequencies(pc, trace, {f}))
      if (p.mode == 1) c = p.c_group_m_s;
    out.push_back(c);
  }
  return out;
}

std::function<double(double)> theory_from_csv(const std::filesystem::path& csv) {
  const auto curve = read_velocity_curve(csv, "theory");
  return [curve, csv](double f) {
    const auto& x = curve.f_Hz;
    if (f < x.front() * (1 - 1e-12) || f > x.back() * (1 + 1e-12))
      throw InputError(format_quantity(f / units::kHz, "kHz") + " lies outside the theory table " + csv.string());
    const auto it = std::lower_bound(x.begin(), x.end(), f);
    if (it == x.begin()) return curve.c_group_m_s.front();
    const std::size_t j = std::size_t(it - x.begin());
    if (j >= x.size()) return curve.c_group_m_s.back();
    const double w = (f - x[j - 1]) / (x[j] - x[j - 1]);
    return (1 - w) * curve.c_group_m_s[j - 1] + w * curve.c_group_m_s[j];
  };
}

nlohmann::ordered_json theory_summary(const PochhammerChree& pc, const DispersionTrace& trace) {
  nlohmann::ordered_json j;
  const auto& c = pc.speeds();
  j["c0_m_s"] = c.c0;
  j["cP_m_s"] = c.cP;
  j["cS_m_s"] = c.cS;
  j["cR_m_s"] = c.cR;
  auto modes = nlohmann::ordered_json::array();
  int last_mode = 0;
  for (const auto& curve : trace.modes) {
    if (curve.mode == last_mode) continue;  // later pieces of the same mode
    last_mode = curve.mode;
    nlohmann::ordered_json m;
    m["mode"] = mode_name(curve.mode);
    m["cutoff_kHz"] = curve.points.front().k_rad_m == 0 ? curve.points.front().f_Hz / units::kHz : 0.0;
    auto zgv = nlohmann::ordered_json::array();
    for (const auto& p : curve.points)
      if (p.c_group_m_s == 0 && p.k_rad_m > 0)
        zgv.push_back({{"f_kHz", p.f_Hz / units::kHz}, {"k_rad_m", p.k_rad_m}, {"ka", p.k_rad_m * pc.radius_m()}});
    m["zero_group_velocity"] = zgv;
    modes.push_back(m);
  }
  j["modes"] = modes;
  if (const auto m = l01_group_velocity_minimum(pc, trace)) {  // refined off the trace's ka grid
    j["L01_min_group_velocity_m_s"] = m->c_group_m_s;
    j["L01_min_group_velocity_over_c0"] = m->c_group_m_s / c.c0;
    j["L01_min_group_velocity_f_kHz"] = m->f_Hz / units::kHz;
    j["L01_min_group_velocity_ka"] = m->k_rad_m * pc.radius_m();
  }
  j["trace_step_refinements"] = trace.step_refinements;
  return j;
}

}  // namespace mesowave::wave
