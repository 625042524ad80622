// mw-efg - the element-free Galerkin solver of the shock-wave concrete paper (Larcher and
// Stempniewski, Sections 2, 3.1 and 4.1): the elastic validation on Timoshenko & Goodier's
// cantilever (against the closed form and the Q4 FEM) and the static three-point bending test with
// a cohesive crack.
//
//   mw-efg cantilever --spacing-m 1 --refinements 2 --method both --table cantilever.csv
//   mw-efg bending --from lab-data/shock-concrete/three-point-bending.toml --law exponential --curve ld.csv
#include <cmath>
#include <optional>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/efg/bending_report.hpp"
#include "mesowave/efg/cantilever.hpp"
#include "mesowave/io/csv.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  app::Tool tool(
      "mw-efg",
      "Element-free Galerkin (EFG) solver of the shock-wave concrete paper: moving-least-squares shape functions "
      "(Eqs. 1-12), cracks that cut the weights (Eq. 13), plane stress/strain (Eqs. 14-18), cohesive cracks "
      "(Eqs. 19-23).\n"
      "  cantilever  the elastic validation: Timoshenko & Goodier's cantilever under a parabolic end shear, the "
      "EFG (and with --method both the Q4 FEM on the same cells) against the closed form, the node spacing halved "
      "--refinements times; prints the errors, their observed orders and the cost.\n"
      "  bending     the notched three-point bending beam of Koermeling and Reinhardt under displacement control "
      "(Section 4.1) with a cohesive crack growing from the notch: load-deflection curve and plot, crack path, "
      "ParaView files of the crack, work of fracture against G_f x ligament, the elastic stiffness against the Q4 "
      "FEM and beam theory, the cost.\n\n"
      "  mw-efg cantilever --spacing-m 2 --refinements 2 --method both --table cantilever.csv --out cantilever.json\n"
      "  mw-efg cantilever --spacing-m 1 --basis quadratic --weight cubic-spline --support-scale 3.5 --gauss 4\n"
      "  mw-efg cantilever --spacing-m 1 --snapshots vtk   (ParaView: open vtk/cantilever.pvd)\n"
      "  mw-efg bending --from lab-data/shock-concrete/three-point-bending.toml --law bilinear --spacing-mm 5 "
      "--curve ld.csv --plot ld.png --crack-path crack.csv --snapshots vtk --out bending.json");
  auto& cli = tool.cli();
  cli.require_subcommand(1);
  fs::path out, table, snapshots, curve, plot, crack_path;
  int threads = 0;

  // cantilever
  efg::CantileverBeam beam;
  efg::CantileverOptions opt;
  double spacing = 2.0;
  int refinements = 0;
  std::string method = "efg", basis = "linear", weight = "quartic-spline";
  auto* cant = cli.add_subcommand("cantilever", "EFG (and FEM) against Timoshenko & Goodier's cantilever");
  cant->add_option("--length-m", beam.L_m, "Beam length L (clamped at x = 0, loaded at x = L)")->capture_default_str();
  cant->add_option("--depth-m", beam.D_m, "Beam depth D")->capture_default_str();
  cant->add_option("--thickness-m", beam.t_m, "Thickness t (plane stress)")->capture_default_str();
  cant->add_option("--E-Pa", beam.E_Pa, "Young's modulus")->capture_default_str();
  cant->add_option("--nu", beam.nu, "Poisson's ratio, in (-1, 0.5)")->capture_default_str();
  cant->add_option("--P-N", beam.P_N, "End load (the parabolic shear's resultant)")->capture_default_str();
  cant->add_option("--spacing-m", spacing,
                   "Node spacing of the coarsest run: cells round(L/s) x round(D/s), their corners the nodes")
      ->capture_default_str();
  cant->add_option("--refinements", refinements, "Times the spacing is halved (a run each; 0-6)")->capture_default_str();
  cant->add_option("--method", method, "efg | fem (the Q4 reference) | both")
      ->check(CLI::IsMember({"efg", "fem", "both"}))->capture_default_str();
  cant->add_option("--gauss", opt.gauss, "EFG Gauss points per cell direction (the paper: 2)")->capture_default_str();
  cant->add_option("--basis", basis, "MLS basis: linear (1, x, y) | quadratic, Eq. (2)")->capture_default_str();
  cant->add_option("--weight", weight, "MLS weight: quartic-spline (Eq. 12) | cubic-spline")->capture_default_str();
  cant->add_option("--support-scale", opt.support_scale,
                   "Support radius h_i = scale x spacing, Eq. (10) (2 to 3 for a linear basis)")->capture_default_str();
  cant->add_option("--support-count", opt.support_count,
                   "Instead: h_i = --support-factor x the distance to the count-th nearest node (the paper: 4-10)");
  cant->add_option("--support-factor", opt.support_factor, "With --support-count")->capture_default_str();
  cant->add_flag("--collocated-clamp", opt.collocated_clamp,
                 "EFG: the clamp collocated at the edge's nodes instead of weakly (it fails the patch test)");
  cant->add_option("--table", table, "Runs as CSV: method, cells, nodes, Gauss points, errors, wall time, memory");
  cant->add_option("--snapshots", snapshots, "Folder for ParaView files of the last (finest) run: cantilever.pvd");
  cant->add_option("--threads", threads, "Threads (0: the cores the machine is not busy with, core/threads.hpp)");
  app::add_out_option(*cant, out);

  // bending
  efg::BendingCommandLine bending;
  auto* bend = cli.add_subcommand("bending", "The notched three-point bending beam with a cohesive crack");
  efg::add_bending_options(*bend, bending);
  bend->add_option("--curve", curve, "Load-deflection CSV: deflection_mm, load_N, iterations, crack_tip_mm, dissipated_Nmm");
  bend->add_option("--plot", plot, "Load-deflection plot (.png | .svg, gnuplot)");
  bend->add_option("--crack-path", crack_path, "Crack path CSV: x_mm, y_mm (mouth, notch tip, grown points)");
  bend->add_option("--snapshots", snapshots, "Folder for ParaView files per curve point: nodes (displacement, stress) and the crack (bending.pvd)");
  bend->add_option("--threads", threads, "Threads (0: the cores the machine is not busy with, core/threads.hpp)");
  app::add_out_option(*bend, out);

  return tool.run(argc, argv, [&](app::Run& run) {
    const ThreadChoice thread_choice = use_threads(threads);  // same bits for any count (efg/elastic_model.hpp)
    const nlohmann::ordered_json thread_json = {{"count", thread_choice.count}, {"reason", thread_choice.reason}};
    if (bend->parsed()) {
      auto bo = bending.resolve();
      bo.node_snapshots = !snapshots.empty();
      if (!plot.empty()) io::require_plot_extension(plot);
      std::optional<efg::BendingReference> ref;
      if (bending.fem_refinement > 0) ref = efg::three_point_bending_reference(bo, bending.fem_refinement);
      const auto result = efg::run_three_point_bending(bo);
      const auto o = efg::three_point_bending_outputs(bo, result, ref ? &*ref : nullptr);
      run.metric("peak_load", result.peak_load_N, "N");
      run.metric("work_of_fracture", result.work_of_fracture_J * 1e3, "N mm");
      run.metric("elastic_stiffness", result.elastic_stiffness_N_per_m * 1e-3, "N/mm");
      run.metric("wall", result.wall_s, "s");
      if (!curve.empty()) run.write_text(curve, io::to_csv(o.curve_header, o.curve_rows));
      if (!crack_path.empty()) run.write_text(crack_path, io::to_csv(o.crack_header, o.crack_rows));
      if (!plot.empty()) io::render_plot(o.plot, plot, run.output(plot));
      if (!snapshots.empty()) {
        efg::VtkSeries series(snapshots, "bending", [&](const fs::path& p) { return run.output(p); });
        for (std::size_t i = 0; i < o.crack_steps.size(); ++i)
          series.add(o.crack_steps[i].first, result.node_steps.at(i), o.crack_steps[i].second);
        series.finish();
      }
      auto summary = o.summary;
      summary["threads"] = thread_json;
      run.emit_json(summary, out);
      return;
    }
    if (cant->parsed()) {
      require_positive("--spacing-m", spacing, "m");
      opt.cells_x = std::max(1, int(std::lround(beam.L_m / spacing)));
      opt.cells_y = std::max(1, int(std::lround(beam.D_m / spacing)));
      opt.mls.basis = efg::parse_basis(basis);
      opt.mls.weight = efg::parse_weight_kind(weight);
      const auto study = efg::run_cantilever_study(beam, opt, method != "fem", method != "efg", refinements);
      for (const auto& r : study.runs) {
        const std::string key = (r.method == "EFG" ? "efg_" : "fem_") + std::to_string(r.nodes) + "_nodes_";
        run.metric(key + "displacement_error", r.errors.displacement_L2, "");
        run.metric(key + "energy_error", r.errors.energy, "");
        run.metric(key + "wall", r.wall_s, "s");
      }
      if (!table.empty()) run.write_text(table, io::to_csv(study.table_header, study.table_rows));
      if (!snapshots.empty()) {
        efg::VtkSeries series(snapshots, "cantilever", [&](const fs::path& p) { return run.output(p); });
        series.add(0.0, study.runs.back().snapshot, {});
        series.finish();
      }
      auto summary = study.summary;
      summary["threads"] = thread_json;
      run.emit_json(summary, out);
    }
  });
}
