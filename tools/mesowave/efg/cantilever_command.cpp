#include "mesowave/efg/cantilever_command.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/efg/vtk_output.hpp"
#include "mesowave/io/csv.hpp"

namespace mesowave::efg {

CantileverOptions CantileverCommandLine::resolve() const {
  require_positive("--spacing-m", spacing_m, "m");
  CantileverOptions o = options;
  o.cells_x = std::max(1, int(std::lround(beam.L_m / spacing_m)));
  o.cells_y = std::max(1, int(std::lround(beam.D_m / spacing_m)));
  o.mls.basis = parse_basis(basis);
  o.mls.weight = parse_weight_kind(weight);
  return o;
}

void add_cantilever_options(CLI::App& cant, CantileverCommandLine& v) {
  CantileverBeam& beam = v.beam;
  CantileverOptions& opt = v.options;
  cant.add_option("--length-m", beam.L_m, "Beam length L (clamped at x = 0, loaded at x = L)")->capture_default_str();
  cant.add_option("--depth-m", beam.D_m, "Beam depth D")->capture_default_str();
  cant.add_option("--thickness-m", beam.t_m, "Thickness t (plane stress)")->capture_default_str();
  cant.add_option("--E-Pa", beam.E_Pa, "Young's modulus")->capture_default_str();
  cant.add_option("--nu", beam.nu, "Poisson's ratio, in (-1, 0.5)")->capture_default_str();
  cant.add_option("--P-N", beam.P_N, "End load (the parabolic shear's resultant)")->capture_default_str();
  cant.add_option("--spacing-m", v.spacing_m,
                  "Node spacing of the coarsest run: cells round(L/s) x round(D/s), their corners the nodes")
      ->capture_default_str();
  cant.add_option("--refinements", v.refinements, "Times the spacing is halved (a run each; 0-6)")->capture_default_str();
  cant.add_option("--method", v.method, "efg | fem (the Q4 reference) | both")
      ->check(CLI::IsMember({"efg", "fem", "both"}))->capture_default_str();
  cant.add_option("--gauss", opt.gauss, "EFG Gauss points per cell direction (the paper: 2)")->capture_default_str();
  cant.add_option("--basis", v.basis, "MLS basis: linear (1, x, y) | quadratic, Eq. (2)")->capture_default_str();
  cant.add_option("--weight", v.weight, "MLS weight: quartic-spline (Eq. 12) | cubic-spline")->capture_default_str();
  cant.add_option("--support-scale", opt.support_scale,
                  "Support radius h_i = scale x spacing, Eq. (10) (2 to 3 for a linear basis)")->capture_default_str();
  cant.add_option("--support-count", opt.support_count,
                  "Instead: h_i = --support-factor x the distance to the count-th nearest node (the paper: 4-10)");
  cant.add_option("--support-factor", opt.support_factor, "With --support-count")->capture_default_str();
  cant.add_flag("--collocated-clamp", opt.collocated_clamp,
                "EFG: the clamp collocated at the edge's nodes instead of weakly (it fails the patch test)");
  cant.add_option("--table", v.table, "Runs as CSV: method, cells, nodes, Gauss points, errors, wall time, memory");
  cant.add_option("--snapshots", v.snapshots, "Folder for ParaView files of the last (finest) run: cantilever.pvd");
  cant.add_option("--threads", v.threads, "Threads (0: the cores the machine is not busy with, core/threads.hpp)");
}

void run_cantilever_command(const CantileverCommandLine& c, app::Run& run, const nlohmann::ordered_json& threads) {
  const auto study = run_cantilever_study(c.beam, c.resolve(), c.method != "fem", c.method != "efg", c.refinements);
  for (const auto& r : study.runs) {
    const std::string key = (r.method == "EFG" ? "efg_" : "fem_") + std::to_string(r.nodes) + "_nodes_";
    run.metric(key + "displacement_error", r.errors.displacement_L2, "");
    run.metric(key + "energy_error", r.errors.energy, "");
    run.metric(key + "wall", r.wall_s, "s");
  }
  if (!c.table.empty()) run.write_text(c.table, io::to_csv(study.table_header, study.table_rows));
  if (!c.snapshots.empty()) {
    VtkSeries series(c.snapshots, "cantilever", [&](const std::filesystem::path& p) { return run.output(p); });
    series.add(0.0, study.runs.back().snapshot, {});
    series.finish();
  }
  auto summary = study.summary;
  summary["threads"] = threads;
  run.emit_json(summary, c.out);
}

}  // namespace mesowave::efg
