// mw-efg - the element-free Galerkin solver of the shock-wave concrete paper (Larcher and
// Stempniewski, Sections 2, 3.1 and 4.1): the elastic validation on Timoshenko & Goodier's
// cantilever (against the closed form and the Q4 FEM) and the static three-point bending test with
// a cohesive crack; the explicit dynamics (Sections 2.5, 3.2) on a roller strip under a pressure pulse;
// the contact detonation of a slab with growing cracks (Section 4.3).
//
//   mw-efg cantilever --spacing-m 1 --refinements 2 --method both --table cantilever.csv
//   mw-efg bending --from lab-data/shock-concrete/three-point-bending.toml --law exponential --curve ld.csv
//   mw-efg wave --length-mm 500 --pulse triangular --peak-MPa 100 --rise-us 10 --fall-us 10 --history h.csv
//   mw-efg blast --spacing-mm 5 --cracks c.csv --energy e.csv --plot slab.png --snapshots vtk --out blast.json
#include <cmath>
#include <optional>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/efg/bending_report.hpp"
#include "mesowave/efg/blast_command.hpp"
#include "mesowave/efg/cantilever_command.hpp"
#include "mesowave/efg/wave_report.hpp"
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
      "FEM and beam theory, the cost.\n"
      "  wave        explicit dynamics (central differences, lumped row-sum mass, the stable step by Lanczos): a "
      "plane-strain strip with rollers under a triangular, Friedlander or Hann-burst pressure on x = 0; sensor "
      "histories, the peak speed against c_p = sqrt(M/rho), the stencil's dispersion, the energy balance, ParaView "
      "snapshots; --fem-reference: mw-fem on the same bar; with --law quadratic | hugoniot (the Y-function, Section "
      "4.2) the front against the method of characteristics.\n"
      "  blast       the contact detonation of a plain concrete slab (Section 4.3), plane strain (a line charge): "
      "discrete cracks with the spacing, radius and 500 m/s speed limits, the Y-function with unloading, the strain "
      "rate effect, contact of closing faces; crack events, the compacted zone, energies, ParaView files, a figure.\n\n"
      "  mw-efg cantilever --spacing-m 2 --refinements 2 --method both --table cantilever.csv --out cantilever.json\n"
      "  mw-efg cantilever --spacing-m 1 --basis quadratic --weight cubic-spline --support-scale 3.5 --gauss 4\n"
      "  mw-efg cantilever --spacing-m 1 --snapshots vtk   (ParaView: open vtk/cantilever.pvd)\n"
      "  mw-efg bending --from lab-data/shock-concrete/three-point-bending.toml --law bilinear --spacing-mm 5 "
      "--curve ld.csv --plot ld.png --crack-path crack.csv --snapshots vtk --out bending.json\n"
      "  mw-efg wave --spacing-mm 2.5 --pulse friedlander --peak-MPa 50 --positive-us 20 --history h.csv --snapshots vtk\n"
      "  mw-efg wave --law hugoniot --unloading 0 --length-mm 300 --width-mm 12 --spacing-mm 1 --peak-MPa 2000 "
      "--rise-us 20 --fall-us 20 --profiles p.csv --profile-us 20 --profile-us 60 --out shock.json\n"
      "  mw-efg blast --from lab-data/shock-concrete/blast-slab.toml --spacing-mm 5 --cracks c.csv --plot slab.png --out blast.json");
  auto& cli = tool.cli();
  cli.require_subcommand(1);
  fs::path out, table, snapshots, curve, plot, crack_path;
  int threads = 0;

  efg::CantileverCommandLine cant_cl;  // cantilever
  auto* cant = cli.add_subcommand("cantilever", "EFG (and FEM) against Timoshenko & Goodier's cantilever");
  efg::add_cantilever_options(*cant, cant_cl);
  app::add_out_option(*cant, cant_cl.out);

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

  efg::WaveCommandLine wave_cl;  // wave
  auto* wave = cli.add_subcommand("wave", "Explicit dynamics: a pressure pulse along a roller strip");
  efg::add_wave_options(*wave, wave_cl);
  app::add_out_option(*wave, wave_cl.out);
  efg::BlastCommandLine blast_cl;  // blast
  auto* blast = cli.add_subcommand("blast", "Contact detonation of a concrete slab: cracks, compaction (Section 4.3)");
  efg::add_blast_options(*blast, blast_cl);
  app::add_out_option(*blast, blast_cl.out);

  return tool.run(argc, argv, [&](app::Run& run) {
    // same bits for any count (efg/elastic_model.hpp, efg/explicit_dynamics.hpp)
    const ThreadChoice thread_choice = use_threads(wave->parsed()    ? wave_cl.threads
                                                   : cant->parsed()  ? cant_cl.threads
                                                   : blast->parsed() ? blast_cl.threads
                                                                     : threads);
    const nlohmann::ordered_json thread_json = {{"count", thread_choice.count}, {"reason", thread_choice.reason}};
    if (blast->parsed()) return efg::run_blast_command(blast_cl, run, thread_json);
    if (wave->parsed()) {
      const auto w = efg::run_wave_command(wave_cl);
      const auto& o = w.outputs;
      const auto& result = w.result;
      for (const auto& [name, value, unit] : o.metrics) run.metric(name, value, unit);
      if (!wave_cl.history.empty()) run.write_text(wave_cl.history, io::to_csv(o.history_header, o.history_rows));
      if (!wave_cl.profiles.empty()) run.write_text(wave_cl.profiles, io::to_csv(o.profile_header, o.profile_rows));
      if (!wave_cl.fronts.empty()) {
        if (o.front_rows.empty()) throw InputError("--fronts needs a stiffening --law (quadratic | hugoniot) and the triangular pulse");
        run.write_text(wave_cl.fronts, io::to_csv(o.front_header, o.front_rows));
      }
      if (!wave_cl.snapshots.empty()) {
        efg::VtkSeries series(wave_cl.snapshots, "wave", [&](const fs::path& p) { return run.output(p); });
        for (const auto& [t_s, nodes] : result.run.snapshots) series.add(t_s * 1e6, nodes, {});
        series.finish();
      }
      auto summary = o.summary;
      summary["threads"] = thread_json;
      return run.emit_json(summary, wave_cl.out);
    }
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
    if (cant->parsed()) efg::run_cantilever_command(cant_cl, run, thread_json);
  });
}
