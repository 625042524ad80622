// mw-fem - explicit linear-elastic continuum reference (the rod paper's
// Abaqus/Explicit role, Section 4.3.1): a Hann-burst force on a rod or a box,
// signals at chosen points in the mesowave signal file layout; a study's experiment
// (--experiment, experiment/experiment.hpp) places the transducers. Examples: --help.
#include <optional>

#include "mesowave/app/process_info.hpp"
#include "mesowave/app/progress.hpp"
#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/experiment/experiment.hpp"
#include "mesowave/signal/signal_file.hpp"
#include "mesowave/fem/case.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  app::Tool tool(
      "mw-fem",
      "Explicit finite-element reference for wave signals: linear elastic, lumped mass, central differences,\n"
      "Rayleigh mass-proportional damping (M a = F - K u - alpha M v, beta = 0), a force F(t) = five-cycle Hann burst.\n"
      "rod: a solid rod along z (end faces z = 0 and z = L), axisymmetric ring elements (default; cheap) or 3D\n"
      "  hexahedra; force at the centre of the z = 0 end (or a traction patch), default sensor S at the centre of the\n"
      "  far end, as in the rod paper. box: a block of identical hexahedra (the concrete cube), force normal to the face\n"
      "  the source point lies on, sensors anywhere (component 'normal' = the outward normal of their face, as in mw-dem).\n"
      "cylinder: an --experiment's cylinder as axisymmetric rings (the actuator on the axis of its z- end).\n"
      "Elements: fully integrated trilinear hexahedra (2x2x2 Gauss) or bilinear rings; stiffness precomputed per element\n"
      "shape. The stable step comes from a rigorous eigenvalue bound of the mesh; a --dt-us above it is refused.\n\n"
      "  mw-fem rod --E-GPa 208.72 --nu 0.3 --density-kg-m3 7850.66 --radius-mm 5.1 --length-mm 1000 --mesh-mm 1 "
      "--frequency-kHz 100 --alpha-damping 2000 --signals rod.h5\n"
      "  mw-fem rod --experiment lab-data/steel-rod/experiment.toml --patch-radius-mm 0 --alpha-damping 2000 --signals rod.h5\n"
      "  mw-fem box --E-GPa 36.67 --nu 0.162 --density-kg-m3 2129.56 --size-mm 50 --mesh-mm 1 --source-mm 25,25,0 "
      "--sensor B=25,25,50 --sensor C=0,25,25 --frequency-kHz 100 --signals cube.h5\n"
      "  mw-fem --from results/concrete-cube/upv.json box --experiment lab-data/concrete-cube/experiment.toml --signals c.h5\n"
      "    (E_d, nu_d and the density from mw-upv; the cube, transducers, burst and record from the experiment)");
  auto& cli = tool.cli();
  cli.require_subcommand(1);
  double mesh_mm = 1, alpha = 0;
  // Unset: the experiment's (--experiment), else FemCase's defaults (100 kHz, 5 cycles, 1 N, 1.5 ms, 0.1 us, a point).
  std::optional<double> E_GPa, nu, rho, dt_us, f_kHz, cycles, force_N, duration_ms, sample_dt_us, patch_mm;
  int threads = 0;
  bool quiet = false;
  std::optional<std::string> quantity;
  std::vector<std::string> sensors;
  fs::path signals_path, out, experiment_path;
  const auto common = [&](CLI::App* sub) {
    // The second names are mw-upv's: a wave test's continuum reference takes the dynamic moduli, and
    // `mw-fem --from upv.json box ...` fills them (and --density-kg-m3) from its E_d_GPa and nu_d.
    sub->add_option("--E-GPa,--E-d-GPa", E_GPa, "Young's modulus [GPa] (--from mw-upv's JSON fills it with E_d)");
    sub->add_option("--nu,--nu-d", nu, "Poisson ratio (-1 < nu < 0.5) (--from mw-upv's JSON fills it with nu_d)");
    sub->add_option("--density-kg-m3", rho, "Density [kg/m3] (these three: or the --experiment's specimen's)");
    sub->add_option("--mesh-mm", mesh_mm, "Element size [mm]")->capture_default_str();
    sub->add_option("--experiment", experiment_path, "The study's experiment (lab-data/<study>/experiment.toml): "
                    "specimen, transducers, burst and record; the options below beat its values");
    sub->add_option("--frequency-kHz", f_kHz, "Centre frequency of the Hann burst [kHz] (100)");
    sub->add_option("--cycles", cycles, "Cycles in the burst (5)");
    sub->add_option("--force-N", force_N, "Peak force amplitude [N] (1)");
    sub->add_option("--alpha-damping", alpha, "Rayleigh mass-proportional damping alpha [1/s] (rod paper: 2000)")
        ->capture_default_str();
    sub->add_option("--duration-ms", duration_ms, "Simulated time [ms] (1.5, or --experiment's record)");
    sub->add_option("--sample-dt-us", sample_dt_us, "Sampling interval of the signals [us] (0.1)");
    sub->add_option("--dt-us", dt_us, "Time step [us] (default: the largest that divides the sampling interval "
                                      "and stays below the stable step)");
    sub->add_option("--quantity", quantity, "Recorded quantity: displacement | velocity | acceleration (acceleration)");
    sub->add_option("--sensor", sensors, "NAME=X,Y,Z in mm, optionally /x|/y|/z|/r|/normal; repeatable");
    sub->add_option("--patch-radius-mm", patch_mm,
                    "Spread the force as a uniform traction over the face within this radius (0: point force)");
    sub->add_option("--signals", signals_path, "Signal file to write (HDF5, mesowave signal layout)")->required();
    sub->add_option("--threads", threads,
                    "OpenMP threads (default: the cores the machine is not busy with; same bits for any count)");
    sub->add_flag("--quiet", quiet, "No progress bar");
    app::add_out_option(*sub, out, "the JSON report (cost, stable step)");
  };

  auto* rod = cli.add_subcommand("rod", "Solid rod along z, force at the end z = 0");
  common(rod);
  std::optional<double> radius_mm, length_mm;
  double st_step_mm = 0;
  std::string model_kind = "axisymmetric";
  fs::path spacetime_path;
  rod->add_option("--radius-mm", radius_mm, "Rod radius [mm] (or --experiment's)");
  rod->add_option("--length-mm", length_mm, "Rod length [mm] (with --experiment: its rod at this length)");
  rod->add_option("--model", model_kind, "axisymmetric | 3d")->capture_default_str();
  rod->add_option("--spacetime", spacetime_path, "Also record the axial quantity along the axis (HDF5, for a 2D FFT)");
  rod->add_option("--spacetime-step-mm", st_step_mm, "Spacing of the space-time record [mm] (default: mesh size)");

  auto* box = cli.add_subcommand("box", "Block [0,X] x [0,Y] x [0,Z], force normal to a face");
  common(box);
  std::string size_text, source_text;
  box->add_option("--size-mm", size_text, "Edge length, or X,Y,Z [mm] (with --experiment: its box scaled to this edge X)");
  box->add_option("--source-mm", source_text, "Where the force acts, a point on a face X,Y,Z [mm] (or --experiment's actuator)");
  auto* cylinder = cli.add_subcommand("cylinder", "An --experiment's cylinder: axisymmetric rings, the actuator on the axis "
                                      "of its z- end, sensors on the ends and the curved face");
  common(cylinder);

  return tool.run(argc, argv, [&](app::Run& run) {
    fem::FemCase c;
    std::optional<experiment::Experiment> lab;
    if (!experiment_path.empty()) {
      run.input(experiment_path);
      lab = experiment::read_experiment_file(experiment_path);
      if (rod->parsed()) lab = fem::rod_experiment(*lab, radius_mm, length_mm);
      const double scale = size_text.empty() ? 1.0 : std::stod(size_text) / (lab->specimen.size_m[0] / units::mm);
      if (!source_text.empty() || !sensors.empty()) throw InputError("--experiment places the transducers: no --source-mm, --sensor");
      fem::apply_experiment(c, *lab, scale);
    } else if (cylinder->parsed()) throw InputError("mw-fem cylinder needs --experiment (the cylinder and its transducers)");
    c.material = fem::material_of(E_GPa, nu, rho, lab ? &lab->specimen : nullptr);
    c.mesh_m = require_positive("--mesh-mm", mesh_mm, "mm") * units::mm;
    if (f_kHz) c.frequency_hz = require_positive("--frequency-kHz", *f_kHz, "kHz") * units::kHz;
    if (cycles) c.cycles = require_positive("--cycles", *cycles);
    if (force_N) c.force_N = require_finite("--force-N", *force_N, "N");
    if (patch_mm) c.patch_radius_m = *patch_mm * units::mm;
    c.alpha_damping_per_s = alpha;
    if (duration_ms) c.duration_s = require_positive("--duration-ms", *duration_ms, "ms") * units::ms;
    if (sample_dt_us) c.sample_dt_s = *sample_dt_us * units::us;
    if (dt_us) c.dt_s = *dt_us * units::us;
    if (quantity) c.quantity = experiment::parse_motion_quantity(*quantity, "--quantity");
    for (const auto& s : sensors) c.probe_points.push_back(fem::parse_probe_point(s));
    c.threads = threads;
    if (rod->parsed()) {
      if (!lab) fem::set_rod_size(c, radius_mm, length_mm);
      c.rod_model = model_kind;
      if (!spacetime_path.empty()) c.spacetime_step_m = st_step_mm * units::mm;
    } else if (experiment_path.empty()) {
      if (size_text.empty() || source_text.empty()) throw InputError("mw-fem box needs --size-mm and --source-mm, or --experiment");
      c.body = fem::FemCase::Body::box;
      if (size_text.find(',') == std::string::npos) c.size_m.fill(std::stod(size_text) * units::mm);
      else c.size_m = fem::parse_point_mm(size_text, "--size-mm");
      c.source_m = fem::parse_point_mm(source_text, "--source-mm");
    }
    const fem::FemSetup setup = fem::assemble_fem_case(c);
    app::Progress progress("mw-fem " + setup.model.description, setup.stepping.steps, "steps", !quiet);
    const fem::FemRun fem = fem::run_fem_case(setup, [&](std::int64_t n) { progress.update(n); });
    progress.finish();

    signal::write_signal_file(run.output(signals_path), fem.result.signals, fem.attributes);
    if (setup.spacetime)
      fem::write_spacetime_file(run.output(spacetime_path), fem.result.spacetime, *setup.spacetime,
                                 setup.stepping.sample_dt_s, "z", fem.attributes);
    const auto j = fem::fem_report(setup, fem, double(app::resource_usage().peak_rss_kib) / 1024.0, signals_path);
    run.metric("wall", fem.result.wall_s, "s");
    run.metric("steps per second", j["steps_per_s"], "1/s");
    run.metric("stable dt", j["stable_dt_us"], "us");
    run.metric("peak RSS", j["peak_rss_MiB"], "MiB");
    run.emit_json(j, out);
  });
}
