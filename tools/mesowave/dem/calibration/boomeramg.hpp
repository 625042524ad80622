#pragma once
// hypre's BoomerAMG (algebraic multigrid; hypre 2.26, Debian's libhypre-dev) as
// the preconditioner of Eigen's BiCGSTAB, for the static elastic test's system
// (static_elastic.hpp): one V-cycle per application, from a zero guess, so the
// preconditioner is one fixed linear operator, as BiCGSTAB assumes.
//
// The system is the bonded network's stiffness with 6 DOFs per sphere, numbered
// sphere by sphere (d_x, d_y, d_z, theta_x, theta_y, theta_z) and scaled to a
// unit diagonal by the caller (translations in m and rotations in rad: unscaled,
// the strength of connection would compare newtons with newton-metres).
// BoomerAMG runs it as a system of 6 functions (HYPRE_BoomerAMGSetNumFunctions):
// it coarsens spheres, not single DOFs (nodal coarsening on the row-sum norm of
// the 6 x 6 blocks, HYPRE_BoomerAMGSetNodal), and interpolates each function from
// the same function. The settings are the fastest of those measured on the 50 mm
// cube (docs/calibration.md, "Elastic trials as a static solve", with what else
// was tried: HMIS coarsening, block interpolation, the rigid rotations as
// interpolation vectors, Schwarz and ILU smoothers, GMRES): PMIS coarsening and
// extended+i interpolation (operator complexity 1.3), one forward Gauss-Seidel
// sweep down and up.
//
// hypre is an MPI library; it runs here on MPI_COMM_SELF, one process. A plain
// run of a tool never initialises MPI (dem/parallel/mpi_session.hpp), so the
// first BoomerAmg does (MPI_Init_thread as a singleton: about 1 s of OpenMPI's
// start-up) and finalises it at exit; under a launcher it uses that MPI as it
// is. Debian's hypre is built without OpenMP: the V-cycle runs on one thread
// (BiCGSTAB's products on the OpenMP threads), and with one process and no
// random coarsening it gives the same bits run to run.
//
// Built without hypre (MESOWAVE_HAVE_HYPRE unset: libhypre-dev missing at
// configure time), compute() throws InputError naming the package.
#include <Eigen/SparseCore>
#include <memory>

namespace mesowave::dem {

/// hypre's codes (HYPRE_parcsr_ls.h).
struct BoomerAmgSettings {
  double strong_threshold = 0.5;  ///< strength of connection (hypre's default 0.25 suits 2-D scalar problems)
  int num_functions = 6;          ///< DOFs per sphere
  int nodal = 4;                  ///< nodal coarsening on the blocks' row-sum norm
  int coarsen_type = 8;           ///< PMIS
  int interp_type = 6;            ///< extended+i
  int p_max_elements = 4;         ///< interpolation's entries per row
  int relax_type = 3;             ///< hybrid Gauss-Seidel, forward (one process: Gauss-Seidel)
};

/// An Eigen preconditioner (what IterativeSolverBase calls: compute, solve, info).
class BoomerAmg {
public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  using StorageIndex = Matrix::StorageIndex;

  BoomerAmg();
  ~BoomerAmg();
  BoomerAmg(const BoomerAmg&) = delete;
  BoomerAmg& operator=(const BoomerAmg&) = delete;

  /// Whether this build has hypre (else compute throws).
  static bool available();
  void set_settings(const BoomerAmgSettings& settings) { settings_ = settings; }

  template <typename MatrixType>
  BoomerAmg& analyzePattern(const MatrixType&) { return *this; }
  /// Builds the hierarchy of a row-major matrix (a SparseMatrix or the Ref BiCGSTAB passes).
  template <typename MatrixType>
  BoomerAmg& factorize(const MatrixType& a) {
    setup(a.rows(), a.outerIndexPtr(), a.innerNonZeroPtr(), a.innerIndexPtr(), a.valuePtr());
    return *this;
  }
  template <typename MatrixType>
  BoomerAmg& compute(const MatrixType& a) { return factorize(a); }

  /// One V-cycle on b from x = 0.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  Eigen::ComputationInfo info() const { return Eigen::Success; }
  Eigen::Index rows() const { return n_; }
  Eigen::Index cols() const { return n_; }

private:
  // Row r holds inner[outer[r] .. outer[r] + (counts ? counts[r] : outer[r + 1] - outer[r])).
  void setup(Eigen::Index n, const StorageIndex* outer, const StorageIndex* counts, const StorageIndex* inner,
             const double* values);
  struct Hypre;
  std::unique_ptr<Hypre> h_;
  BoomerAmgSettings settings_;
  Eigen::Index n_ = 0;
};

}  // namespace mesowave::dem
