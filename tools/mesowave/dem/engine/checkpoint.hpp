#pragma once
// Checkpoint and restart of a DEM run (mw-dem run --checkpoint FILE
// --checkpoint-every-steps N; --restart FILE): the run's state after a step,
// written so that a run restarted from it continues to the same bits as one
// that never stopped. One HDF5 file:
//
//   /           attributes format = "mesowave-dem-checkpoint", format_version,
//               scene_sha256, packing_sha256, experiment_sha256 (the files'
//               contents) and options (JSON: the options that change results)
//   /run        steps_done and the loop's own running values (energy check, a [test]'s peak)
//   /model      the model's state (Model::save_state), /model/law its contact law's
//   /actuators/<index>, /sensors/<index>   each one's state (an attribute names it)
//
// Every part writes its own state (state_group.hpp): numbers binary, exact.
// The file is written whole or not at all (a temporary sibling renamed into
// place), so a run killed while writing keeps the previous checkpoint. A
// restart refuses, with one line naming what differs, a checkpoint of another
// scene file, packing file, experiment file or results-changing option.
//
// Snapshots (--snapshots) of a restarted run begin at the restart step: the
// interrupted run's were discarded with its other outputs.
//
// On several MPI ranks (docs/mpi.md) rank 0 writes the file one process would
// write at that step: the contact law's per-slot arrays are gathered in the
// whole layout's slot order (SphereSystem::write_slots), so the file does not
// say how many ranks wrote it, and any rank count restarts it (every rank reads
// it whole and keeps its slots: SphereSystem::held_slots). On a signal the ranks
// agree after each step (dem/command/run_command.cpp), so that every rank writes
// the checkpoint and stops after the same step.
//
// A run with stronger bonds may start from an intact checkpoint of a run with
// weaker ones (mw-dem run --intact-checkpoint, --restart-stronger; issue 19):
// while every bond holds, the strengths T and C enter the law (Eqs. 4-6,
// cohesive_frictional_contact.hpp) only through the tests that break a bond,
// -F_n > T R^2 and |F_s| > C R^2 + F_n tan(mu), and an intact bond never slips
// (slip needs |F_s| above the same bound; the moment law's bounds 0.25 T R^3 and
// 0.5 C R^3 break it too, cohesive_moment_contact.hpp; the linearised network and
// the chain never break). So if no bond broke under T0, C0 up to
// step k, none breaks under T1 >= T0, C1 >= C0 either, and the two runs are the
// same bits up to step k: a calibration's failure trials, which differ in T and
// C alone, share that elastic prefix. The checkpoint records the strengths it
// ran with (attributes tensile_strength_Pa, cohesion_Pa; infinite: never break),
// and such a restart is refused unless every other identity entry is equal, both
// strengths are at least the checkpoint's and no bond of it is broken
// (Simulation::restore_stronger). One running value depends on T and C: the
// largest bond force / strength (peak_force_ratio); the restarted run carries the
// checkpoint's, an upper bound of its own over those steps (its strengths are
// larger), so that one number is a bound, not the same bits.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "mesowave/dem/engine/state_group.hpp"
#include "mesowave/dem/scene/scene.hpp"

namespace mesowave::dem {

struct SceneOverrides;  // scene_overrides.hpp

/// What makes two runs the same run: the inputs' contents and the options that change results.
struct CheckpointIdentity {
  std::string scene_sha256, packing_sha256, experiment_sha256;  ///< experiment: "" without one
  /// Option (as on mw-dem's command line: "--dt-ns") -> value; 0 or false: the scene's own.
  nlohmann::ordered_json options = nlohmann::ordered_json::object();
  /// The bond strengths the run has (after every override); infinite: bonds that never break.
  /// Written as attributes; a plain restart checks them through `options`, a stronger one reads them.
  double tensile_strength_Pa = 0, cohesion_Pa = 0;
};

/// The options of the identity that set the bond strengths: the ones a restart
/// with stronger bonds (read_checkpoint_file's `stronger_bonds`) lets differ.
inline constexpr const char* kStrengthOptions[] = {"--T-MPa", "--C-MPa"};

/// The identity of a run of `scene` (read from `scene_file`, `overrides` applied) with --model `model`.
CheckpointIdentity run_identity(const std::filesystem::path& scene_file, const Scene& scene,
                                const SceneOverrides& overrides, const std::string& model);

/// When and where a run writes checkpoints (SimulationOptions::checkpoint).
struct CheckpointOptions {
  std::filesystem::path file;     ///< empty: none
  std::int64_t every_steps = 0;   ///< after every N steps (0: only when `requested` says so)
  /// Polled after each step: true once a checkpoint should be written now (a
  /// SIGTERM arrived, before the run's progress report stops it). One is written per request.
  std::function<bool()> requested;
  CheckpointIdentity identity;
  std::function<void(std::int64_t steps_done)> on_written;  ///< after each checkpoint (optional)
};

/// Writes a checkpoint file: the identity, then `body` fills the root group.
void write_checkpoint_file(const std::filesystem::path& file, const CheckpointIdentity& identity,
                           const std::function<void(StateGroup& root)>& body);
/// Reads one: InputError if it is not a checkpoint or not of the run `identity`
/// describes (naming the first difference), else `body` reads the root group.
/// `stronger_bonds`: the identity's strength options may differ, if the
/// checkpoint's T and C (its attributes) are at most `identity`'s; the caller
/// checks that no bond of it is broken (Simulation::restore_stronger).
void read_checkpoint_file(const std::filesystem::path& file, const CheckpointIdentity& identity,
                          const std::function<void(const StateGroup& root)>& body, bool stronger_bonds = false);

}  // namespace mesowave::dem
