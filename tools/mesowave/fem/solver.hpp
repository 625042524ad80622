#pragma once
// Explicit linear-elastic dynamics on a FemModel: the continuum reference of the
// rod study (the rod paper's Abaqus/Explicit role) and of the concrete cube.
//   M a = F(t) - K u - alpha M v         lumped M, Rayleigh damping alpha M (beta = 0)
// Central differences with half-step velocities (damping term centred):
//   v^{n+1/2} = ((1 - alpha dt/2) v^{n-1/2} + dt M^-1 (F^n - K u^n)) / (1 + alpha dt/2)
//   u^{n+1}   = u^n + dt v^{n+1/2}
// stable for dt <= 2 / omega_max whatever alpha >= 0; the model's element bound
// gives omega_max, and a step above it is refused. K u is assembled element by
// element from the precomputed element matrices, colour by colour, in parallel
// (OpenMP) with the same bits for any thread count.
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "mesowave/experiment/motion_quantity.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "mesowave/signal/signal.hpp"
#include "mesowave/fem/model.hpp"

namespace mesowave::fem {

/// What a probe records: the lab's quantity (experiment/motion_quantity.hpp: its one parser,
/// names and units), the same the DEM's motion sensors record.
using experiment::MotionQuantity;

/// A force F(t) = burst(t) spread over dofs with weights summing to 1 (total force = burst).
struct BurstLoad {
  std::vector<std::pair<std::size_t, double>> dof_weights;  ///< (dof index = node * dim + component, weight)
  signal::HannBurst burst;
};

/// A recorded dof: the signal `name`.
struct Probe {
  std::string name;
  std::size_t dof = 0;
  MotionQuantity quantity = MotionQuantity::acceleration;
  std::string component;  ///< x | y | z | r, or -x | -y | -z (the outward normal of a lower face)
  double sign = 1.0;      ///< the recorded value is sign * the dof's (-1: along -axis)
};

/// Optional space-time record (for a 2D FFT): one quantity at many dofs.
struct SpaceTimeRequest {
  std::vector<std::size_t> dofs;
  std::vector<double> coordinate_m;  ///< position of each along the line
  MotionQuantity quantity = MotionQuantity::velocity;
};

struct ExplicitOptions {
  double dt_s = 0;
  std::int64_t steps = 0;            ///< number of steps; samples at n dt, n = 0, stride, 2 stride, ... <= steps
  std::int64_t sample_stride = 1;
  double alpha_damping_per_s = 0;    ///< Rayleigh mass-proportional coefficient alpha [1/s]
  /// Called with the step count now and then (from one thread); what it throws stops the
  /// run and is rethrown once the threads have left the loop (an interrupted run's stop).
  std::function<void(std::int64_t)> progress;
  bool allow_unstable = false;       ///< tests only: run above the stable step to watch it diverge
  /// Superposition (fem/superposition.hpp): the load's weights carry 1 N on step 0 alone
  /// (F^0 = 1, F^n = 0 after), the load's burst unused - the impulse response of every probe.
  bool unit_impulse = false;
  /// Threads used: at most one per this many elements (and at most OpenMP's maximum;
  /// core/threads.hpp), so that small meshes do not pay for barriers they cannot amortise.
  std::size_t min_elements_per_thread = 4000;
};

struct ExplicitResult {
  std::vector<signal::Signal> signals;  ///< one per probe, t0 = 0, dt = stride dt
  std::vector<double> spacetime;        ///< samples x dofs (row-major), if requested
  std::int64_t steps = 0;
  double wall_s = 0;
  double max_kinetic_energy_J = 0;
  double final_kinetic_energy_J = 0;
  int threads = 1;
};

/// Largest frequency of the assembled mesh (power iteration on M^-1 K; free dofs).
/// Below the element bound behind FemModel::stable_dt(); for reporting.
double global_max_omega(const FemModel& model, int iterations = 300);

/// InputError if dt exceeds the stable step (unless allow_unstable), if a dof is
/// out of range or the stride is not positive; std::runtime_error if the
/// solution stops being finite.
ExplicitResult run_explicit(const FemModel& model, const BurstLoad& load, const std::vector<Probe>& probes,
                            const ExplicitOptions& options, const SpaceTimeRequest* spacetime = nullptr);

}  // namespace mesowave::fem
