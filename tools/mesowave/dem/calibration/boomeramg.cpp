#include "mesowave/dem/calibration/boomeramg.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesowave/core/error.hpp"

#ifdef MESOWAVE_HAVE_HYPRE
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>  // the C API (OMPI_SKIP_MPICXX)

#include "mesowave/core/leak_check.hpp"
#include "mesowave/dem/parallel/mpi_session.hpp"
#endif

namespace mesowave::dem {

#ifdef MESOWAVE_HAVE_HYPRE
namespace {

// hypre's calls return an error code; one that fails is a bug here or an allocation failure.
void check(HYPRE_Int code, const char* call) {
  if (code != 0) {
    HYPRE_ClearAllErrors();
    throw std::runtime_error(std::string("hypre: ") + call + " failed (error code " + std::to_string(code) + ")");
  }
}
#define MW_HYPRE(call) check(call, #call)

// hypre for the whole process, started on first use after MPI (start_mpi_for_library: a launcher's
// as it is, a plain run's started there) and finalised at exit before MPI (atexit runs in reverse
// order of registration).
void start_hypre() {
  static const bool started = [] {
    start_mpi_for_library();
    [[maybe_unused]] const OutsideLeakCheck outside;
    MW_HYPRE(HYPRE_Init());
    std::atexit([] {
      [[maybe_unused]] const OutsideLeakCheck outside;
      HYPRE_Finalize();
    });
    return true;
  }();
  (void)started;
}

// An IJ vector of n values on MPI_COMM_SELF.
struct Vector {
  HYPRE_IJVector ij = nullptr;
  HYPRE_ParVector par = nullptr;
  explicit Vector(HYPRE_Int n) {
    MW_HYPRE(HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, n - 1, &ij));
    MW_HYPRE(HYPRE_IJVectorSetObjectType(ij, HYPRE_PARCSR));
    MW_HYPRE(HYPRE_IJVectorInitialize(ij));
    MW_HYPRE(HYPRE_IJVectorAssemble(ij));
    void* object = nullptr;
    MW_HYPRE(HYPRE_IJVectorGetObject(ij, &object));
    par = static_cast<HYPRE_ParVector>(object);
  }
  ~Vector() { HYPRE_IJVectorDestroy(ij); }
  Vector(const Vector&) = delete;
  Vector& operator=(const Vector&) = delete;
};

}  // namespace

struct BoomerAmg::Hypre {
  HYPRE_IJMatrix ij = nullptr;
  HYPRE_ParCSRMatrix par = nullptr;
  HYPRE_Solver amg = nullptr;
  std::vector<HYPRE_Int> indices;  // 0 .. n-1, for the vectors' Set/GetValues
  std::unique_ptr<Vector> b, x;
  ~Hypre() {
    if (amg) HYPRE_BoomerAMGDestroy(amg);
    if (ij) HYPRE_IJMatrixDestroy(ij);
  }
};
#else
struct BoomerAmg::Hypre {};
#endif

BoomerAmg::BoomerAmg() = default;
BoomerAmg::~BoomerAmg() = default;

#ifdef MESOWAVE_HAVE_HYPRE

bool BoomerAmg::available() { return true; }

void BoomerAmg::setup(Eigen::Index n, const StorageIndex* outer, const StorageIndex* counts, const StorageIndex* inner,
                      const double* values) {
  start_hypre();
  h_.reset();  // a new matrix: the old hierarchy goes first (memory)
  h_ = std::make_unique<Hypre>();
  n_ = n;
  const auto N = HYPRE_Int(n);
  Hypre& h = *h_;

  // The matrix, every row at once from Eigen's rows.
  const auto size = static_cast<std::size_t>(n);
  std::vector<HYPRE_Int> row_counts(size), rows(size), columns;
  h.indices.resize(size);
  std::size_t nonzeros = 0;
  for (std::size_t r = 0; r < size; ++r) {
    row_counts[r] = HYPRE_Int(counts ? counts[r] : outer[r + 1] - outer[r]);
    rows[r] = h.indices[r] = HYPRE_Int(r);
    nonzeros += std::size_t(row_counts[r]);
  }
  columns.reserve(nonzeros);
  std::vector<double> entries;
  entries.reserve(nonzeros);
  for (std::size_t r = 0; r < size; ++r)
    for (StorageIndex k = outer[r]; k < outer[r] + StorageIndex(row_counts[r]); ++k) {
      columns.push_back(HYPRE_Int(inner[k]));
      entries.push_back(values[k]);
    }
  MW_HYPRE(HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, N - 1, 0, N - 1, &h.ij));
  MW_HYPRE(HYPRE_IJMatrixSetObjectType(h.ij, HYPRE_PARCSR));
  MW_HYPRE(HYPRE_IJMatrixSetRowSizes(h.ij, row_counts.data()));
  MW_HYPRE(HYPRE_IJMatrixInitialize(h.ij));
  MW_HYPRE(HYPRE_IJMatrixSetValues(h.ij, N, row_counts.data(), rows.data(), columns.data(), entries.data()));
  MW_HYPRE(HYPRE_IJMatrixAssemble(h.ij));
  void* object = nullptr;
  MW_HYPRE(HYPRE_IJMatrixGetObject(h.ij, &object));
  h.par = static_cast<HYPRE_ParCSRMatrix>(object);
  columns = {};
  entries = {};
  h.b = std::make_unique<Vector>(N);
  h.x = std::make_unique<Vector>(N);

  const BoomerAmgSettings& s = settings_;
  MW_HYPRE(HYPRE_BoomerAMGCreate(&h.amg));
  MW_HYPRE(HYPRE_BoomerAMGSetPrintLevel(h.amg, 0));
  MW_HYPRE(HYPRE_BoomerAMGSetMaxIter(h.amg, 1));  // one V-cycle per application
  MW_HYPRE(HYPRE_BoomerAMGSetTol(h.amg, 0.0));
  MW_HYPRE(HYPRE_BoomerAMGSetStrongThreshold(h.amg, s.strong_threshold));
  MW_HYPRE(HYPRE_BoomerAMGSetCoarsenType(h.amg, s.coarsen_type));
  MW_HYPRE(HYPRE_BoomerAMGSetInterpType(h.amg, s.interp_type));
  MW_HYPRE(HYPRE_BoomerAMGSetPMaxElmts(h.amg, s.p_max_elements));
  MW_HYPRE(HYPRE_BoomerAMGSetRelaxType(h.amg, s.relax_type));
  if (s.num_functions > 1) {
    if (n % s.num_functions != 0)
      throw std::logic_error("BoomerAmg: " + std::to_string(n) + " DOFs are not " + std::to_string(s.num_functions) +
                             " a node");
    MW_HYPRE(HYPRE_BoomerAMGSetNumFunctions(h.amg, s.num_functions));
    MW_HYPRE(HYPRE_BoomerAMGSetNodal(h.amg, s.nodal));
  }
  MW_HYPRE(HYPRE_BoomerAMGSetup(h.amg, h.par, h.b->par, h.x->par));
}

Eigen::VectorXd BoomerAmg::solve(const Eigen::VectorXd& b) const {
  Hypre& h = *h_;
  const auto N = HYPRE_Int(n_);
  MW_HYPRE(HYPRE_IJVectorSetValues(h.b->ij, N, h.indices.data(), b.data()));
  MW_HYPRE(HYPRE_ParVectorSetConstantValues(h.x->par, 0.0));
  MW_HYPRE(HYPRE_BoomerAMGSolve(h.amg, h.par, h.b->par, h.x->par));
  Eigen::VectorXd x(n_);
  MW_HYPRE(HYPRE_IJVectorGetValues(h.x->ij, N, h.indices.data(), x.data()));
  return x;
}

#else

bool BoomerAmg::available() { return false; }

void BoomerAmg::setup(Eigen::Index, const StorageIndex*, const StorageIndex*, const StorageIndex*, const double*) {
  throw InputError("the static solve's amg preconditioner needs hypre, which this build lacks (install libhypre-dev "
                   "and configure again)");
}

Eigen::VectorXd BoomerAmg::solve(const Eigen::VectorXd& b) const { return b; }

#endif

}  // namespace mesowave::dem
