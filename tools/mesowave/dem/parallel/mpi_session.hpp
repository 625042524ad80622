#pragma once
// MPI for a tool's main (docs/mpi.md): `mpirun -np N mw-dem run ...` runs N ranks
// of one simulation. MPI is initialised only when the process was started by an
// MPI launcher (OpenMPI's mpirun sets OMPI_COMM_WORLD_SIZE; PMIx and PMI launchers
// PMIX_RANK / PMI_SIZE); a plain run never touches MPI and is the single-process
// engine, unchanged. Under a launcher with one rank the run is the plain one too.
//
// The session finalises MPI when it goes out of scope. A build without MPI
// (MESOWAVE_HAVE_MPI unset: libopenmpi-dev missing at configure time) refuses a
// launch with more than one rank in one line rather than running N copies.
#include <memory>
#include <string>

#include "mesowave/dem/parallel/domain.hpp"

namespace mesowave::dem {

/// MPI for a library that needs it (hypre's BoomerAMG, dem/calibration/boomeramg.hpp) in a
/// process no launcher started: initialised on the first call (a singleton: about 1 s of
/// OpenMPI's start-up) and finalised at exit; under a launcher MpiSession's MPI is used as it is.
/// The one place besides MpiSession where MPI starts. InputError in a build without MPI.
void start_mpi_for_library();

class MpiSession {
public:
  /// InputError if started with several ranks by a build without MPI.
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  /// Rank 0 writes the outputs and records the run; the others only compute.
  bool is_root() const { return rank_ == 0; }
  /// A run's one-line error: on one rank (or no launcher) printed as "error: LINE". On several
  /// ranks it ends them all (MPI_Abort with `status`: a failure on some ranks must not leave the
  /// others waiting in an exchange), printed once: rank 0 prints at once; another rank first
  /// waits a moment, so that a failure every rank meets (a bad input) is printed by rank 0,
  /// whose abort ends the others before they print, and one of its own is still printed.
  void report_error(const std::string& line, int status);
  /// Before a rank but 0 records its own failure (app::Tool::set_failure_recording): waits the
  /// moment report_error would, so that a failure rank 0 meets too is recorded and ended by
  /// rank 0 first (its abort ends this rank inside the wait). True if this rank is still running.
  bool outlive_root_report();
  /// The ranks as the engine takes them (SimulationOptions::domain); nullptr for a single rank.
  Domain* domain() { return domain_.get(); }

private:
  int rank_ = 0, size_ = 1;
  bool initialised_ = false;
  bool waited_ = false;  ///< outlive_root_report waited already: report_error does not again
  std::unique_ptr<Domain> domain_;
};

}  // namespace mesowave::dem
