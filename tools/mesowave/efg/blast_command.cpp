#include "mesowave/efg/blast_command.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/efg/viscosity_command.hpp"
#include "mesowave/io/csv.hpp"

namespace mesowave::efg {

namespace {
std::string num(double v, int digits = 6) { return format_significant(v, digits); }
}  // namespace

BlastSlabOptions BlastCommandLine::resolve() const {
  BlastSlabOptions o;
  o.span_m = span_mm * 1e-3;
  o.thickness_m = thickness_mm * 1e-3;
  o.spacing_m = spacing_mm * 1e-3;
  o.support_scale = support_scale;
  o.gauss = gauss;
  o.concrete = {E_GPa * 1e9, nu, 1.0, density_kg_m3, PlaneState::plane_strain};
  if (unloading != 0 && unloading != 1) throw InputError("--unloading (" + std::to_string(unloading) + ") must be 1 (Eq. 27) or 0");
  if (strain_rate != 0 && strain_rate != 1) throw InputError("--strain-rate (" + std::to_string(strain_rate) + ") must be 1 or 0");
  o.hugoniot = hugoniot;
  o.hugoniot.unloading = unloading == 1;
  DynamicCrackOptions& c = o.cracks;
  c.law = law;
  c.cohesive.f_t_Pa = f_t_MPa * 1e6;
  c.cohesive.G_f_J_m2 = G_f_N_m;
  if (f_c_MPa != 0) c.cohesive.f_c_Pa = require_positive("--f-c-MPa", f_c_MPa, "MPa") * 1e6;
  c.strain_rate_effect = strain_rate == 1;
  c.project_fields = parse_field_projection(project_fields);
  c.strain_rate.f_cm_Pa = f_cm_MPa * 1e6;
  c.strain_rate.max_strain_rate_1_s = max_strain_rate_1_s;
  c.strain_rate.tension = parse_tensile_dif_law(tensile_dif);
  if (!(crack_speed_limit_m_s >= 0))
    throw InputError("--crack-speed-limit-m-s (" + format_number(crack_speed_limit_m_s) + ") must be > 0 (0: no limit)");
  c.crack_speed_limit_m_s = crack_speed_limit_m_s == 0 ? std::numeric_limits<double>::infinity() : crack_speed_limit_m_s;
  c.segment_length_m = segment_mm * 1e-3;
  c.min_crack_spacing_m = min_crack_spacing_mm * 1e-3;
  c.min_crack_radius_m = min_crack_radius_mm * 1e-3;
  c.penalty_factor = penalty_factor;
  o.charge = {charge_width_mm * 1e-3, charge_thickness_mm * 1e-3, explosive_density_kg_m3, detonation_velocity_m_s,
              gamma, fall_transits, peak_MPa * 1e6};
  o.duration_s = duration_us * 1e-6;
  o.dt_fraction = dt_fraction;
  o.dt_s = dt_us * 1e-6;
  o.viscosity = {viscosity_quadratic, viscosity_linear};
  o.crushing_eps_v = crushing_eps_v;
  o.sample_stride = sample_stride;
  o.snapshot_stride = snapshot_stride == 0 && !snapshots.empty() ? 20 : snapshot_stride;
  o.validate();
  return o;
}

void add_blast_options(CLI::App& app, BlastCommandLine& v) {
  app.add_option("--span-mm", v.span_mm, "Slab span L (assumed: the paper gives no dimensions); the charge sits at L/2")->capture_default_str();
  app.add_option("--thickness-mm", v.thickness_mm, "Slab thickness H (top face y = H loaded, every face free)")->capture_default_str();
  app.add_option("--spacing-mm", v.spacing_mm, "Node spacing h (cells L/h x H/h, corners the nodes; crack segment a = h)")->capture_default_str();
  app.add_option("--support-scale", v.support_scale, "MLS support radius over the spacing, Eq. (10)")->capture_default_str();
  app.add_option("--gauss", v.gauss, "Gauss points per cell direction (the paper: 2)")->capture_default_str();
  app.add_option("--E-GPa", v.E_GPa, "Young's modulus (plane strain, per metre of charge length)")->capture_default_str();
  app.add_option("--nu", v.nu, "Poisson's ratio")->capture_default_str();
  app.add_option("--density-kg-m3", v.density_kg_m3, "Concrete density")->capture_default_str();
  app.add_option("--law", v.law, "Cohesive law of the crack faces: exponential (Eqs. 19-20) | bilinear (Eqs. 21-23)")->capture_default_str();
  app.add_option("--f-t-MPa", v.f_t_MPa, "Static tensile strength f_t (St. Venant: sigma_1 >= f_t,dyn = DIF f_t)")->capture_default_str();
  app.add_option("--G-f-N-m", v.G_f_N_m, "Fracture energy G_f [N/m], Eq. (20)")->capture_default_str();
  app.add_option("--f-c-MPa", v.f_c_MPa, "Compressive strength f_c for the bilinear law's beta_t, Eq. (22) (0: unset, beta_t = 0.25)");
  app.add_option("--f-cm-MPa", v.f_cm_MPa, "Mean compressive strength f_cm of the CEB-FIP DIF (efg/strain_rate)")->capture_default_str();
  app.add_option("--max-strain-rate-1-s", v.max_strain_rate_1_s, "The DIF's cap (Section 3.3: no strengths measured above 100 1/s)")->capture_default_str();
  app.add_option("--tensile-dif", v.tensile_dif, "ceb-fip-1990 | malvar-ross-1998")->capture_default_str();
  app.add_option("--strain-rate", v.strain_rate, "1: f_t,dyn = DIF(rate) f_t (Section 3.3); 0: the static f_t")->capture_default_str();
  app.add_option("--crack-speed-limit-m-s", v.crack_speed_limit_m_s,
                 "A tip moves at most this fast (Curbach: 500 m/s, Section 4.3); 0: no limit")->capture_default_str();
  app.add_option("--segment-mm", v.segment_mm, "Crack growth step a (0: the spacing)")->capture_default_str();
  app.add_option("--min-crack-spacing-mm", v.min_crack_spacing_mm, "No crack starts closer to another (0: 2 a, assumed)")->capture_default_str();
  app.add_option("--min-crack-radius-mm", v.min_crack_radius_mm,
                 "Smallest radius of a crack's path R_min: a turn <= 2 asin(a / (2 R_min)) per segment (0: a, assumed)")->capture_default_str();
  app.add_option("--project-fields", v.project_fields,
                 "At each crack change, project onto the cut shape functions (mass-weighted L2, efg/field_projection): none | u | u-v")
      ->capture_default_str();
  app.add_option("--penalty-factor", v.penalty_factor, "Face penalty k = factor E / a: initial secant and contact of closing faces")->capture_default_str();
  HugoniotParameters& h = v.hugoniot;
  app.add_option("--e-v-th", h.e_v_th, "Y-function: threshold volumetric strain, Eq. (26)")->capture_default_str();
  app.add_option("--e-v", h.e_v, "Y-function: e_v, Eq. (26)")->capture_default_str();
  app.add_option("--a-v", h.a_v, "Y-function: a_v, Eq. (26)")->capture_default_str();
  app.add_option("--b-v", h.b_v, "Y-function: b_v, Eq. (26)")->capture_default_str();
  app.add_option("--unloading", v.unloading, "1: unloading by Eq. (27) (the paper's slab); 0: Eq. (25) both ways")->capture_default_str();
  app.add_option("--charge-width-mm", v.charge_width_mm, "Charge width w_c: the loaded segment of the top face (assumed)")->capture_default_str();
  app.add_option("--charge-thickness-mm", v.charge_thickness_mm, "Charge thickness l_c: the pulse rises in l_c / D and falls in fall-transits x l_c / D")->capture_default_str();
  app.add_option("--explosive-density-kg-m3", v.explosive_density_kg_m3, "Explosive density rho_e (TNT)")->capture_default_str();
  app.add_option("--detonation-velocity-m-s", v.detonation_velocity_m_s, "Detonation velocity D (TNT)")->capture_default_str();
  app.add_option("--gamma", v.gamma, "p_CJ = rho_e D^2 / (gamma + 1)")->capture_default_str();
  app.add_option("--fall-transits", v.fall_transits, "Fall time of the triangular pulse in charge transits l_c / D (the rise: one transit)")->capture_default_str();
  app.add_option("--peak-MPa", v.peak_MPa,
                 "Peak pressure on the charge's segment (0: the CJ pressure times the acoustic transmission 2 Z_c / (Z_c + rho_e D))")
      ->capture_default_str();
  app.add_option("--duration-us", v.duration_us, "Simulated time")->capture_default_str();
  app.add_option("--dt-fraction", v.dt_fraction, "Fraction of the stable step 2/omega_max, in (0, 1]")->capture_default_str();
  app.add_option("--dt-us", v.dt_us,
                 "Time step (0: --dt-fraction x the stable step; above the stable step: refused; shrunk as the law stiffens and cracks form)")
      ->capture_default_str();
  add_viscosity_options(app, v.viscosity_quadratic, v.viscosity_linear);
  app.add_option("--crushing-eps-v", v.crushing_eps_v,
                 "Crater: crushed where |eps_v| reached this (efg/crater.hpp; 0: the Y-function's minimum, 0.0475 by Eq. 26)")
      ->capture_default_str();
  app.add_option("--sample-stride", v.sample_stride, "Steps between the energy CSV's rows")->capture_default_str();
  app.add_option("--cracks", v.cracks_csv, "Crack events CSV: t_us, crack, initiation, from_x_mm, from_y_mm, to_x_mm, to_y_mm, length_mm, speed_m_s, ...");
  app.add_option("--energy", v.energy_csv, "Energies over time CSV [J per metre of charge]: KE, W_int, W_ext, W_damp, faces' work, dissipated, stored, jump, balances");
  app.add_option("--snapshots", v.snapshots, "Folder for ParaView files (blast.pvd): nodes, crack faces (polylines), Gauss points (eps_v, compacted)");
  app.add_option("--snapshot-stride", v.snapshot_stride, "Steps between snapshots (default 20 with --snapshots)");
  app.add_option("--plot", v.plot, "Figure of the crack pattern over the compacted zone (.png | .svg, gnuplot)");
  app.add_option("--threads", v.threads, "Threads (0: the cores the machine is not busy with, core/threads.hpp)");
}

BlastOutputs blast_outputs(const BlastSlabOptions& o, const BlastSlabResult& r) {
  BlastOutputs w;
  const DynamicsResult& d = r.run;
  nlohmann::ordered_json cracks = nlohmann::ordered_json::array();
  double longest = 0, total = 0;
  for (std::size_t k = 0; k < r.crack_length_m.size(); ++k) {
    longest = std::max(longest, r.crack_length_m[k]);
    total += r.crack_length_m[k];
    cracks.push_back({{"crack", k}, {"length_mm", r.crack_length_m[k] * 1e3}});
  }
  std::size_t grown = 0;
  for (const CrackEvent& e : r.events) grown += e.initiation ? 0 : 1;
  const BlastEnergySample last = r.energy.empty() ? BlastEnergySample{} : r.energy.back();
  const double scale = std::max(last.external_work_J, 1e-300);
  w.summary = {
      {"tool_summary", "contact detonation of a plain concrete slab, plane strain (a line charge), explicit EFG with discrete cracks"},
      {"slab", {{"span_mm", o.span_m * 1e3}, {"thickness_mm", o.thickness_m * 1e3}, {"faces", "all free"},
                {"E_GPa", o.concrete.E_Pa * 1e-9}, {"nu", o.concrete.nu}, {"density_kg_m3", o.concrete.density_kg_m3}}},
      {"charge", {{"width_mm", o.charge.width_m * 1e3}, {"thickness_mm", o.charge.thickness_m * 1e3},
                  {"cj_pressure_GPa", o.charge.cj_pressure_Pa() * 1e-9}, {"peak_MPa", r.pulse.peak_Pa * 1e-6},
                  {"rise_us", r.pulse.rise_s * 1e6}, {"fall_us", r.pulse.fall_s * 1e6},
                  {"impulse_Pa_s", 0.5 * r.pulse.peak_Pa * r.pulse.fall_s}}},
      {"spacing_mm", o.spacing_m * 1e3},
      {"nodes", r.nodes},
      {"gauss_points", r.points},
      {"crack_count", r.crack_length_m.size()},
      {"crack_growths", grown},
      {"longest_crack_mm", longest * 1e3},
      {"total_crack_length_mm", total * 1e3},
      {"max_crack_speed_m_s", r.max_crack_speed_m_s},
      {"crack_speed_limit_m_s", std::isfinite(o.cracks.crack_speed_limit_m_s) ? nlohmann::ordered_json(o.cracks.crack_speed_limit_m_s)
                                                                               : nlohmann::ordered_json("none")},
      {"refused_changes", r.refused},
      {"segment_mm", r.segment_length_m * 1e3},
      {"min_crack_spacing_mm", r.min_spacing_m * 1e3},
      {"min_crack_radius_mm", r.min_radius_m * 1e3},
      {"max_turn_deg", r.max_turn_rad * 180 / std::numbers::pi},
      {"penalty_Pa_per_m", r.penalty_Pa_per_m},
      {"project_fields", std::string(to_string(o.cracks.project_fields))},
      {"cracks", cracks},
      {"compacted", {{"threshold_pressure_MPa", r.threshold_pressure_Pa * 1e-6}, {"points", r.compacted_points},
                     {"depth_mm", r.compacted_depth_m * 1e3}, {"width_mm", r.compacted_width_m * 1e3},
                     {"x_min_mm", r.compacted_x_min_m * 1e3}, {"x_max_mm", r.compacted_x_max_m * 1e3},
                     {"max_compression_eps_v", r.max_compression_eps_v}, {"area_cm2", r.compacted_area_m2 * 1e4},
                     {"joined_depth_mm", r.compacted_joined_depth_m * 1e3}, {"joined_area_cm2", r.compacted_joined_area_m2 * 1e4}}},
      {"crater", {{"definition", "crushed points (|min eps_v| >= crushing_eps_v) joined to the loaded face, and the loose pieces "
                                 "that fully opened crack segments cut off at the loaded face (efg/crater.hpp)"},
                  {"crushing_eps_v", r.crushing_eps_v},
                  {"depth_mm", r.crater.depth_m * 1e3}, {"width_mm", r.crater.width_m * 1e3},
                  {"x_min_mm", r.crater.x_min_m * 1e3}, {"x_max_mm", r.crater.x_max_m * 1e3},
                  {"area_cm2", r.crater.area_m2 * 1e4}, {"crushed_area_cm2", r.crater.crushed_area_m2 * 1e4},
                  {"fragment_area_cm2", r.crater.fragment_area_m2 * 1e4}, {"crushed_points", r.crater.crushed_points},
                  {"fragments", r.crater.crater_fragments}, {"fragment_points", r.crater.crater_fragment_points},
                  {"pieces", r.crater.pieces}, {"spall_fragments", r.crater.spall_fragments},
                  {"spall_area_cm2", r.crater.spall_area_m2 * 1e4}, {"spall_depth_mm", r.crater.spall_depth_m * 1e3},
                  {"loose_inside_points", r.crater.loose_inside_points}, {"open_segments", r.open_segments.size()}}},
      {"energy", {{"external_work_J", last.external_work_J}, {"kinetic_J", last.kinetic_J},
                  {"internal_work_J", last.internal_work_J}, {"bulk_work_J", last.bulk_work_J()},
                  {"faces_work_J", last.faces_work_J}, {"dissipated_J", last.dissipated_J}, {"stored_J", last.stored_J},
                  {"energy_jump_J", last.energy_jump_J}, {"kinetic_jump_J", last.kinetic_jump_J},
                  {"faces_jump_J", last.faces_jump_J}, {"damping_J", last.damping_J}, {"viscous_J", last.viscous_J},
                  {"balance_over_W_ext", last.balance_J() / scale},
                  {"balance_less_faces_jump_over_W_ext", last.balance_less_faces_jump_J() / scale},
                  {"max_balance_over_W_ext", r.max_abs_balance_J / scale},
                  {"run_drift", d.energy_drift}, {"unit", "J per metre of charge length"}}},
      {"steps", d.steps},
      {"t_end_us", d.t_end_s * 1e6},
      {"dt_us", d.dt_first_s * 1e6},
      {"dt_min_us", d.dt_min_s * 1e6},
      {"stable_dt_us", d.stable.dt_critical_s * 1e6},
      {"max_modulus_scale", d.max_modulus_scale},
      {"viscosity", viscosity_summary(o.viscosity, d)},
      {"cost", {{"setup_s", r.setup_s}, {"run_s", d.wall_s}, {"wall_s", r.wall_s}, {"threads_used", d.threads}}}};

  w.crack_header = {"t_us", "crack", "initiation", "end", "from_x_mm", "from_y_mm", "to_x_mm", "to_y_mm",
                    "length_mm", "speed_m_s", "stress_ratio", "f_t_dyn_MPa"};
  for (const CrackEvent& e : r.events)
    w.crack_rows.push_back({num(e.t_s * 1e6, 8), std::to_string(e.crack), e.initiation ? "1" : "0", e.at_end ? "end" : "start",
                            num(e.from.x() * 1e3), num(e.from.y() * 1e3), num(e.to.x() * 1e3), num(e.to.y() * 1e3),
                            num(e.length_m * 1e3), num(e.speed_m_s), num(e.stress_ratio, 4), num(e.f_t_dyn_Pa * 1e-6, 4)});
  w.energy_header = {"t_us", "kinetic_J", "internal_work_J", "external_work_J", "damping_J", "faces_work_J",
                     "dissipated_J", "stored_J", "energy_jump_J", "bulk_work_J", "run_balance_J", "balance_J", "kinetic_jump_J",
                     "viscous_J"};
  for (const BlastEnergySample& e : r.energy)
    w.energy_rows.push_back({num(e.t_s * 1e6, 8), num(e.kinetic_J, 8), num(e.internal_work_J, 8), num(e.external_work_J, 8),
                             num(e.damping_J, 8), num(e.faces_work_J, 8), num(e.dissipated_J, 8), num(e.stored_J, 8),
                             num(e.energy_jump_J, 8), num(e.bulk_work_J(), 8), num(e.run_balance_J(), 4), num(e.balance_J(), 4),
                             num(e.kinetic_jump_J, 8), num(e.viscous_J, 8)});

  // The figure: the slab's outline, the charge, the compacted Gauss points, the cracks (in mm).
  io::PlotSpec& f = w.figure;
  const double L = o.span_m * 1e3, H = o.thickness_m * 1e3;
  f.title = "Contact detonation, plane strain, h = " + format_number(o.spacing_m * 1e3) + " mm, t = " +
            format_number(std::round(d.t_end_s * 1e7) / 10) + " us: cracks over the compacted zone and the crater (cf. the paper's Fig. 12)";
  f.x_label = "x [mm]";
  f.y_label = "y [mm]";
  f.x_range = {{-5, L + 5}};
  f.y_range = {{-5, H + 15}};
  f.width_px = 1400;
  f.height_px = int(std::lround(1400 * (H + 20) / (L + 10))) + 140;
  f.key = "outside bottom center horizontal";
  f.series.push_back({"slab", {0, L, L, 0, 0}, {0, 0, H, H, 0}, "lines lw 1 lc rgb 'black'"});
  const double c0 = 0.5 * (L - o.charge.width_m * 1e3), c1 = 0.5 * (L + o.charge.width_m * 1e3);
  f.series.push_back({"charge", {c0, c1, c1, c0, c0}, {H, H, H + o.charge.thickness_m * 1e3, H + o.charge.thickness_m * 1e3, H},
                      "lines lw 2 lc rgb 'red'"});
  io::PlotSeries compacted{"compacted (|eps_v| passed e_v,th)", {}, {}, "points pt 7 ps 0.5 lc rgb '#e69f00'"};
  const GaussPointSnapshot& g = r.final_points;
  for (std::size_t k = 0; k < g.x.size(); ++k)
    if (g.min_eps_v[k] < -o.hugoniot.e_v_th) compacted.x.push_back(g.x[k].x() * 1e3), compacted.y.push_back(g.x[k].y() * 1e3);
  if (compacted.x.empty()) compacted.label = "compacted: none", compacted.x = {NAN}, compacted.y = {NAN};
  f.series.push_back(compacted);
  io::PlotSeries crater{"crater: crushed and cut-loose points (depth " + format_number(std::round(r.crater.depth_m * 1e4) / 10) + " mm)",
                        {}, {}, "points pt 5 ps 0.9 lc rgb '#d55e00'"};
  io::PlotSeries spall{"spall (cut loose at the far face)", {}, {}, "points pt 5 ps 0.6 lc rgb '#009e73'"};
  for (std::size_t k = 0; k < g.x.size() && k < g.crater.size(); ++k) {
    const CraterLabel l = g.crater[k];
    if (l == CraterLabel::crushed || l == CraterLabel::crater_fragment) crater.x.push_back(g.x[k].x() * 1e3), crater.y.push_back(g.x[k].y() * 1e3);
    if (l == CraterLabel::spall) spall.x.push_back(g.x[k].x() * 1e3), spall.y.push_back(g.x[k].y() * 1e3);
  }
  if (crater.x.empty()) crater.label = "crater: none", crater.x = {NAN}, crater.y = {NAN};
  if (spall.x.empty()) spall.label = "spall: none", spall.x = {NAN}, spall.y = {NAN};
  f.series.push_back(crater);
  f.series.push_back(spall);
  io::PlotSeries lines{"cracks (" + std::to_string(r.crack_polylines.size()) + ")", {}, {}, "lines lw 2 lc rgb '#0072b2'"};
  for (const auto& p : r.crack_polylines) {
    for (const Vec2& x : p) lines.x.push_back(x.x() * 1e3), lines.y.push_back(x.y() * 1e3);
    lines.x.push_back(NAN), lines.y.push_back(NAN);
  }
  if (lines.x.empty()) lines.x = {NAN}, lines.y = {NAN};
  f.series.push_back(lines);
  io::PlotSeries open{"fully open faces, past w_max (" + std::to_string(r.open_segments.size()) + ")", {}, {},
                      "lines lw 4 lc rgb '#cc79a7'"};
  const Rect body{0, 0, o.span_m, o.thickness_m};
  for (const Segment& s : r.open_segments) {
    Vec2 a = s.a, b = s.b;
    if (!clip_segment_to(body, a, b)) continue;
    open.x.insert(open.x.end(), {a.x() * 1e3, b.x() * 1e3, NAN}), open.y.insert(open.y.end(), {a.y() * 1e3, b.y() * 1e3, NAN});
  }
  if (open.x.empty()) open.label = "fully open faces: none", open.x = {NAN}, open.y = {NAN};
  f.series.push_back(open);
  return w;
}

void run_blast_command(const BlastCommandLine& cl, app::Run& run, const nlohmann::ordered_json& threads) {
  BlastSlabOptions o = cl.resolve();
  if (!cl.plot.empty()) io::require_plot_extension(cl.plot);  // before the run, not after it
  const BlastSlabResult r = run_blast_slab(o);
  const BlastOutputs w = blast_outputs(o, r);
  run.metric("crack_count", double(r.crack_length_m.size()), "");
  run.metric("max_crack_speed", r.max_crack_speed_m_s, "m/s");
  run.metric("compacted_depth", r.compacted_depth_m * 1e3, "mm");
  run.metric("crater_depth", r.crater.depth_m * 1e3, "mm");
  run.metric("wall", r.wall_s, "s");
  if (!cl.cracks_csv.empty()) run.write_text(cl.cracks_csv, io::to_csv(w.crack_header, w.crack_rows));
  if (!cl.energy_csv.empty()) run.write_text(cl.energy_csv, io::to_csv(w.energy_header, w.energy_rows));
  if (!cl.plot.empty()) io::render_plot(w.figure, cl.plot, run.output(cl.plot));
  if (!cl.snapshots.empty()) {
    VtkSeries series(cl.snapshots, "blast", [&](const std::filesystem::path& p) { return run.output(p); });
    for (const BlastSnapshot& s : r.snapshots) {
      PointCloudSnapshot points;
      std::vector<double> compacted, crater;
      for (std::size_t k = 0; k < s.points.x.size(); ++k) {
        points.positions_m.push_back(s.points.x[k]);
        compacted.push_back(s.points.min_eps_v[k] < -o.hugoniot.e_v_th ? 1.0 : 0.0);
        crater.push_back(k < s.points.crater.size() ? double(int(s.points.crater[k])) : 0.0);
      }
      // crater: 0 intact, 1 crushed, 2 a cut-loose crater fragment, 3 spall, 4 loose inside (efg/crater.hpp)
      points.scalars = {{"eps_v", s.points.eps_v}, {"min_eps_v", s.points.min_eps_v}, {"compacted", compacted},
                        {"max_Y", s.points.max_Y}, {"crater", crater}};
      series.add(s.t_s * 1e6, s.nodes, s.cracks, &points);
    }
    series.finish();
  }
  auto summary = w.summary;
  summary["threads"] = threads;
  run.emit_json(summary, cl.out);
}

}  // namespace mesowave::efg
