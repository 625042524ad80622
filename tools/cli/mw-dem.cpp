// mw-dem - wave propagation (and any loading) in a DEM packing: Yade's
// cohesive-frictional sphere model (concrete paper Eqs. 1-7), run on the
// cheapest model that is valid for the scene.
//
//   mw-dem info pipeline/concrete-cube/scenes/cube-wave.toml
//   mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --frequency-kHz 100
//       --signals results/concrete-cube/dem-100kHz.h5 --summary results/concrete-cube/dem-100kHz.json
//   mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --frequencies-kHz 100,300,500
//       --signals-pattern 'dem-{f}kHz.h5' --summary-pattern 'dem-{f}kHz.json'   (one run, every frequency)
//   mw-dem run ... --checkpoint run.ckpt.h5 --checkpoint-every-steps 10000   (and on SIGTERM/SIGINT)
//   mw-dem run ... --restart run.ckpt.h5      (the same options: continues to the same bits)
//   mpirun -np 4 mw-dem run ...               (4 ranks, the same bits as one process: docs/mpi.md)
#include <iostream>
#include <optional>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/dem/command/run_command.hpp"
#include "mesowave/dem/parallel/mpi_session.hpp"

using namespace mesowave;

int main(int argc, char** argv) {
  std::optional<dem::MpiSession> mpi;  // MPI only under an MPI launcher (mpirun)
  try {
    mpi.emplace(argc, argv);
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  app::Tool tool(
      "mw-dem",
      "Simulate a DEM scene (TOML: packing, material, time step, actuators, sensors) with Yade's cohesive-frictional "
      "contact law: F_n = K_n (u - u_0) (Eq. 1), incremental shear F_s = F_s,prev + K_s dX_s rotated with the contact "
      "(Eq. 2), K_n = E_dem 2 R_A R_B/(R_A + R_B), K_s = nu_dem K_n (Eq. 3), Mohr-Coulomb with strengths T R^2, C R^2 "
      "(Eqs. 4-6), local damping alpha_d (Eq. 7), leapfrog as Yade's NewtonIntegrator. The model is chosen for the "
      "scene and the summary says why: chain (a line of spheres loaded axially), linear (small-amplitude waves: "
      "peak bond force / strength below the bound, checked after the run) or full (contact detection, breakage, "
      "friction). A time step above the stable limit 2/sqrt((1 + alpha_d) lambda_max) is refused. With "
      "--frequencies-kHz the linear model runs once per actuator with a unit force impulse and each frequency's "
      "signals are the burst convolved with that response (superposition: exact to round-off without damping; "
      "the local damping is not additive, so its error is measured: --check-kHz).\n\n"
      "  mw-dem info pipeline/concrete-cube/scenes/cube-wave.toml\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --frequency-kHz 250 --signals cube-250kHz.h5\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --frequencies-kHz 100,300,500 "
      "--signals-pattern 'cube-{f}kHz.h5' --summary-pattern 'cube-{f}kHz.json' --check-kHz 300\n"
      "  mw-dem run pipeline/steel-rod/scenes/rod-wave.toml --model full --signals rod-full.h5 --summary rod-full.json\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --from calibration.json --signals cube.h5   "
      "(E_dem_GPa, nu_dem, T_MPa, C_MPa, friction_angle_deg from mw-calibrate)\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-compression.toml --signals c.h5 --curves c.csv   "
      "(a virtual compression test: E_glob, nu_glob, peak stress)\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-compression.toml --unbreakable-bonds --modulus-levels-MPa 5,16.67 "
      "--static --signals e.h5   (its elastic part as one static solve of the linearised network)");
  if (!mpi->is_root()) {  // one record of the run: rank 0's, or a failure rank 0 did not see
    tool.set_records_runs(false);
    tool.set_failure_recording([&] { return mpi->outlive_root_report(); });
  }
  tool.set_error_report([&](const std::string& line, int status) { mpi->report_error(line, status); });
  auto& cli = tool.cli();
  cli.require_subcommand(1);

  dem::RunCommandLine values;
  int threads = 0;
  const auto add_threads = [&](CLI::App* sub) {
    sub->add_option("--threads", threads,
                    "OpenMP threads (default: the cores the machine is not busy with; the results are the same bits "
                    "for any count)");
  };
  auto* info = cli.add_subcommand("info", "Counts, critical time step, the model it would choose and a memory estimate, without running");
  dem::add_scene_options(*info, values);
  add_threads(info);
  auto* run_cmd = cli.add_subcommand("run", "Run the scene and write the sensor signals");
  dem::add_scene_options(*run_cmd, values);
  add_threads(run_cmd);
  dem::add_run_options(*run_cmd, values);

  return tool.run(argc, argv, [&](app::Run& run) {
    const std::string threads_reason = use_threads(threads).reason;
    if (mpi->size() > 1) run.param("mpi_rank", mpi->rank());
    if (info->parsed()) return dem::run_info_command(values, run, threads_reason);
    dem::run_run_command(values, run, threads_reason, mpi->domain());
  });
}
