#include "mesowave/efg/bending_report.hpp"

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::efg {

ThreePointBendingOptions BendingCommandLine::resolve() const {
  ThreePointBendingOptions o = options;
  o.E_Pa = E_GPa * 1e9;
  o.f_t_Pa = f_t_MPa * 1e6;
  o.span_m = span_mm * 1e-3;
  o.depth_m = depth_mm * 1e-3;
  o.notch_m = notch_mm * 1e-3;
  o.thickness_m = thickness_mm * 1e-3;
  o.spacing_m = spacing_mm * 1e-3;
  o.load_width_m = load_width_mm * 1e-3;
  o.max_deflection_m = max_deflection_mm * 1e-3;
  o.crack_method = parse_crack_weight_method(crack_weight);
  if (notch_x_option && notch_x_option->count() > 0) o.notch_x_m = notch_x_mm * 1e-3;
  if (f_c_option && f_c_option->count() > 0) o.f_c_Pa = f_c_MPa * 1e6;
  for (const auto& [key, option] : law_key_options)
    if (option->count() > 0) o.law_keys[key] = law_key_values.at(key);  // the law refuses a key it does not have
  o.validate();
  return o;
}

void add_bending_options(CLI::App& app, BendingCommandLine& v) {
  ThreePointBendingOptions& o = v.options;
  app.add_option("--law", o.law, "Cohesive law: exponential (Eqs. 19-20) | bilinear (Eqs. 21-23)")->capture_default_str();
  for (const auto& law : cohesive_laws())
    for (const auto& key : law.keys) {
      if (v.law_key_options.count(key.key)) continue;  // a key two laws share: one option
      v.law_key_values[key.key] = key.fallback;
      v.law_key_options[key.key] =
          app.add_option("--" + law_key_option_name(key), v.law_key_values[key.key],
                         "The " + law.name + " law's " + key.key + ": " + key.meaning + " [default " +
                             format_number(key.fallback) + ", in [" + format_number(key.min) + ", " +
                             format_number(key.max) + "]]");
    }
  app.add_option("--E-GPa", v.E_GPa, "Young's modulus")->capture_default_str();
  app.add_option("--nu", o.nu, "Poisson's ratio")->capture_default_str();
  app.add_option("--f-t-MPa", v.f_t_MPa, "Tensile strength f_t")->capture_default_str();
  app.add_option("--G-f-N-m", o.G_f_J_m2, "Fracture energy G_f [N/m]")->capture_default_str();
  v.f_c_option = app.add_option("--f-c-MPa", v.f_c_MPa,
                                "Compressive strength f_c: the bilinear law's beta_t by Eq. (22) (not given: 0.25, "
                                "Eq. (22) below 30 MPa; the exponential law does not use it)");
  app.add_option("--span-mm", v.span_mm, "Span between the supports (the model's length)")->capture_default_str();
  app.add_option("--depth-mm", v.depth_mm, "Beam depth")->capture_default_str();
  app.add_option("--notch-mm", v.notch_mm, "Notch depth from the bottom face")->capture_default_str();
  v.notch_x_option = app.add_option("--notch-x-mm", v.notch_x_mm,
                                    "Where the notch opens on the bottom face, from the left support (default: mid-span; "
                                    "the load stays at mid-span; a quarter cell off the node columns)");
  app.add_option("--thickness-mm", v.thickness_mm, "Out-of-plane thickness (plane stress)")->capture_default_str();
  app.add_option("--load-width-mm", v.load_width_mm, "Distance of the two load points (a loading plate's edges)")
      ->capture_default_str();
  app.add_option("--spacing-mm", v.spacing_mm, "Node spacing (the cells along the span: the nearest odd count)")
      ->capture_default_str();
  app.add_option("--gauss", o.gauss, "Gauss points per cell direction (the paper: 2)")->capture_default_str();
  app.add_option("--support-scale", o.support_scale, "Support radius over the spacing, Eq. (10)")->capture_default_str();
  app.add_option("--crack-weight", v.crack_weight, "visibility | diffraction | transparency, Eq. (13)")
      ->capture_default_str();
  app.add_option("--max-deflection-mm", v.max_deflection_mm, "Last prescribed mid-span deflection")->capture_default_str();
  app.add_option("--steps", o.steps, "Deflection steps (equal, or growing by --step-ratio)")->capture_default_str();
  app.add_option("--step-ratio", o.step_ratio,
                 "Each deflection step this times the last, in [1, 2] (small through the peak, long in the tail)")
      ->capture_default_str();
  app.add_option("--stop-load-fraction", o.stop_load_fraction,
                 "Stop once the crack is through and the load is below this fraction of the peak (the complete "
                 "curve's end: 1e-4 leaves a tail below 0.5 % of G_f x ligament)")->capture_default_str();
  app.add_flag("--ligament-interface", o.ligament_interface,
               "The whole ligament a cohesive interface from the start (the complete curve to separation: the "
               "St. Venant crack cannot cut through the top face, efg/three_point_bending.hpp says why)");
  app.add_option("--fem-refinement", v.fem_refinement,
                 "Q4 reference: cells of load width / (2 x this) (0: no FEM run)")->capture_default_str();
}

std::string law_key_option_name(const CohesiveKeySpec& key) {
  std::string name = key.key;
  const std::string suffix = "_" + key.unit;
  const bool ends_in_unit = name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  if (!key.unit.empty() && key.unit != "1" && !ends_in_unit) name += suffix;
  for (char& c : name)
    if (c == '_') c = '-';
  return name;
}

BendingOutputs three_point_bending_outputs(const ThreePointBendingOptions& o, const ThreePointBendingResult& r,
                                           const BendingReference* ref) {
  BendingOutputs out;
  nlohmann::ordered_json& j = out.summary;
  j["law"] = o.law;
  j["law_keys"] = o.law_keys;  // given; the rest are the law's fallbacks
  j["law_parameters"] = r.law_parameters;
  j["w_max_mm"] = r.w_max_m * 1e3;
  j["geometry_mm"] = {{"span", o.span_m * 1e3}, {"depth", o.depth_m * 1e3}, {"notch", o.notch_m * 1e3},
                      {"notch_x", o.notch_position_m() * 1e3},
                      {"thickness", o.thickness_m * 1e3}};
  j["material"] = {{"E_GPa", o.E_Pa * 1e-9}, {"nu", o.nu}, {"f_t_MPa", o.f_t_Pa * 1e-6}, {"G_f_N_m", o.G_f_J_m2}};
  if (o.f_c_Pa) j["material"]["f_c_MPa"] = *o.f_c_Pa * 1e-6;
  j["discretisation"] = {{"spacing_mm", o.spacing_m * 1e3}, {"load_width_mm", o.load_width_m * 1e3}, {"gauss", o.gauss}, {"support_scale", o.support_scale},
                         {"cohesive_gauss", o.cohesive_gauss}, {"steps", o.steps}, {"step_ratio", o.step_ratio},
                         {"ligament_interface", o.ligament_interface}, {"stop_load_fraction", o.stop_load_fraction},
                         {"max_deflection_mm", o.max_deflection_m * 1e3}};
  j["peak_load_N"] = r.peak_load_N;
  j["deflection_at_peak_mm"] = r.deflection_at_peak_m * 1e3;
  // The identity: the work done on the beam until it carries nothing is G_f times the ligament area.
  const double ligament_work_J = o.G_f_J_m2 * (o.depth_m - o.notch_m) * o.thickness_m;
  j["work_of_fracture_Nmm"] = r.work_of_fracture_J * 1e3;
  j["G_f_times_ligament_Nmm"] = ligament_work_J * 1e3;
  j["work_of_fracture_ratio"] = r.work_of_fracture_J / ligament_work_J;
  j["dissipated_Nmm"] = r.dissipated_J * 1e3;
  j["final_load_fraction_of_peak"] = r.curve.empty() || r.peak_load_N <= 0 ? 0.0 : r.curve.back().load_N / r.peak_load_N;
  nlohmann::ordered_json k;
  k["efg_N_per_mm"] = r.elastic_stiffness_N_per_m * 1e-3;
  if (ref) {
    k["fem_notched_N_per_mm"] = ref->fem_notched_N_per_m * 1e-3;
    k["efg_over_fem"] = r.elastic_stiffness_N_per_m / ref->fem_notched_N_per_m;
    k["fem_unnotched_N_per_mm"] = ref->fem_unnotched_N_per_m * 1e-3;
    k["beam_theory_unnotched_N_per_mm"] = ref->beam_theory_N_per_m * 1e-3;
    k["beam_theory_plus_lefm_notch_N_per_mm"] = ref->beam_theory_notched_N_per_m * 1e-3;
    k["fem_mesh"] = std::to_string(ref->fem_cells_x) + " x " + std::to_string(ref->fem_cells_y) + " Q4, " +
                    std::to_string(ref->fem_nodes) + " nodes";
  }
  j["elastic_stiffness"] = k;
  j["completed"] = r.completed;
  j["stop_reason"] = r.stop_reason;
  j["cost"] = {{"nodes", r.nodes},
               {"gauss_points", r.gauss_points},
               {"dofs", r.dofs},
               {"cohesive_points", r.cohesive_points},
               {"curve_points", r.curve.size()},  // (0, 0), each step, and the state before each crack extension
               {"newton_iterations", r.newton_iterations},
               {"re_solves", r.re_solves},
               {"line_search_cuts", r.line_search_cuts},
               {"wall_s", r.wall_s}};

  out.curve_header = {"deflection_mm", "load_N", "iterations", "crack_tip_mm", "dissipated_Nmm"};
  io::PlotSeries series{o.law + " law (EFG)", {}, {}, "linespoints lw 2 pt 7 ps 0.5"};
  for (std::size_t i = 0; i < r.curve.size(); ++i) {
    const auto& p = r.curve[i];
    out.curve_rows.push_back({format_number(p.deflection_m * 1e3), format_number(p.load_N), std::to_string(p.iterations),
                              format_number(p.crack_tip_y_m * 1e3), format_number(p.dissipated_J * 1e3)});
    series.x.push_back(p.deflection_m * 1e3);
    series.y.push_back(p.load_N * 1e-3);
    if (i < r.crack_steps.size()) out.crack_steps.emplace_back(p.deflection_m * 1e3, r.crack_steps[i]);
  }
  out.crack_header = {"x_mm", "y_mm"};
  for (const auto& x : r.crack_path) out.crack_rows.push_back({format_number(x.x() * 1e3), format_number(x.y() * 1e3)});
  out.plot.title = "Three-point bending, Koermeling-Reinhardt beam: load against mid-span deflection";
  out.plot.x_label = "deflection [mm]";
  out.plot.y_label = "load [kN]";
  out.plot.series = {series};
  out.plot.key = "inside top right";
  return out;
}

}  // namespace mesowave::efg
