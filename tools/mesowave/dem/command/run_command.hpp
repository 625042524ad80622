#pragma once
// mw-dem's subcommands as library calls (tools/cli/mw-dem.cpp is their narrative): the options a user
// types and what `info` and `run` do with them. `run` is one of three runs of the same scene:
//  - direct (engine/simulation): every step, optional ParaView snapshots, checkpoints and restarts
//    (engine/checkpoint: on SIGTERM/SIGINT and every N steps; a restart continues to the same bits;
//    an intact checkpoint, the last before the first bond breaks, starts a run with stronger bonds);
//  - static (--static, calibration/static_elastic): a compression [test]'s elastic part as one
//    solve of the linearised network;
//  - superposed (--frequencies-kHz, engine/superposition): every burst frequency from one
//    unit-impulse run per actuator.
// Everything is staged through app::Run: a bad value or a failed run writes nothing.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "mesowave/app/tool.hpp"
#include "mesowave/dem/scene/scene_overrides.hpp"

namespace mesowave::dem {

class Domain;

struct RunCommandLine {
  std::filesystem::path scene_path, signals_path, summary_path, snapshot_dir, csv_path, curves_path;
  std::filesystem::path checkpoint_path, restart_path;
  std::filesystem::path intact_checkpoint_path, restart_stronger_path;  ///< engine/checkpoint.hpp: stronger bonds
  std::string model = "auto";
  SceneOverrides overrides;
  bool quiet = false, static_solve = false, check_unproven = false;
  std::int64_t checkpoint_every = 0, intact_checkpoint_every = 1000;
  std::vector<double> frequencies_kHz, check_kHz;
  std::string signals_pattern, summary_pattern;
  std::string static_preconditioner = "jacobi";  ///< --static's (StaticElasticOptions::preconditioner)
};

/// The scene and what changes it (both subcommands): the scene file, --model, the scene overrides.
void add_scene_options(CLI::App& sub, RunCommandLine& values);
/// `run`'s outputs and run modes (add_scene_options first: some options exclude --frequency-kHz).
void add_run_options(CLI::App& run, RunCommandLine& values);

/// `info`: counts, the critical step, the model it would choose, a memory estimate; printed as JSON.
void run_info_command(RunCommandLine values, app::Run& run, const std::string& threads_reason);
/// `run`: the direct, static or superposed run, its files, metrics and summary. With `domain`
/// (several MPI ranks, docs/mpi.md) a direct run only: every rank steps, rank 0 alone writes.
void run_run_command(RunCommandLine values, app::Run& run, const std::string& threads_reason,
                     Domain* domain = nullptr);

}  // namespace mesowave::dem
