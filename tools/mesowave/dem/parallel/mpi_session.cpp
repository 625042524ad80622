#include "mesowave/dem/parallel/mpi_session.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "mesowave/core/error.hpp"

#ifdef MESOWAVE_HAVE_MPI
#include <mpi.h>  // the C API (OMPI_SKIP_MPICXX: no C++ bindings to link)

#include "mesowave/core/leak_check.hpp"
#endif

namespace mesowave::dem {
namespace {

// The world size a launcher announces (1 when none started this process).
int launched_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "MPI_LOCALNRANKS"})
    if (const char* v = std::getenv(name)) return std::max(1, std::atoi(v));
  return std::getenv("PMIX_RANK") ? 2 : 1;  // a PMIx launch without a size: initialise and ask MPI
}

#ifdef MESOWAVE_HAVE_MPI
// The collective operations over MPI_COMM_WORLD. MPI is called only from the
// thread that initialised it, outside the step's OpenMP region (MPI_THREAD_FUNNELED).
class MpiDomain final : public Domain {
public:
  MpiDomain(int rank, int size) : rank_(rank), size_(size) {}
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void share(double* data, const std::vector<int>& counts, const std::vector<int>& displs) override {
    MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, data, counts.data(), displs.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  }
  void gather_all(const double* send, int count, double* recv, const std::vector<int>& counts,
                  const std::vector<int>& displs) override {
    MPI_Allgatherv(send, count, MPI_DOUBLE, recv, counts.data(), displs.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  }
  void gather(const double* send, int count, double* recv, const std::vector<int>& counts,
              const std::vector<int>& displs) override {
    MPI_Gatherv(send, count, MPI_DOUBLE, recv, counts.data(), displs.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  }
  void exchange(const std::vector<Message>& sends, const std::vector<Message>& receives) override {
    requests_.resize(sends.size() + receives.size());
    std::size_t k = 0;
    for (const Message& m : receives) MPI_Irecv(m.data, m.count, MPI_DOUBLE, m.rank, kGhostTag, MPI_COMM_WORLD, &requests_[k++]);
    for (const Message& m : sends) MPI_Isend(m.data, m.count, MPI_DOUBLE, m.rank, kGhostTag, MPI_COMM_WORLD, &requests_[k++]);
    MPI_Waitall(int(k), requests_.data(), MPI_STATUSES_IGNORE);
  }
  double max(double value) override {
    double out = 0;
    MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return out;
  }
  std::uint64_t sum(std::uint64_t count) override {
    unsigned long long in = count, out = 0;
    MPI_Allreduce(&in, &out, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
    return out;
  }
  void sum_each(std::vector<std::uint64_t>& counts) override {
    static_assert(sizeof(std::uint64_t) == sizeof(unsigned long long));
    MPI_Allreduce(MPI_IN_PLACE, counts.data(), int(counts.size()), MPI_UNSIGNED_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  }

private:
  static constexpr int kGhostTag = 18;
  int rank_, size_;
  std::vector<MPI_Request> requests_;
};
#endif

}  // namespace

void start_mpi_for_library() {
#ifdef MESOWAVE_HAVE_MPI
  static const bool started = [] {
    [[maybe_unused]] const OutsideLeakCheck outside;
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised) {
      int provided = 0;
      MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
      std::atexit([] {
        [[maybe_unused]] const OutsideLeakCheck outside;
        int finalised = 0;
        MPI_Finalized(&finalised);
        if (!finalised) MPI_Finalize();
      });
    }
    return true;
  }();
  (void)started;
#else
  throw InputError("this build has no MPI, which the solver asked for needs (install libopenmpi-dev and configure again)");
#endif
}

MpiSession::MpiSession(int& argc, char**& argv) {
  if (launched_size() <= 1) return;
#ifdef MESOWAVE_HAVE_MPI
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  if (size_ > 1) domain_ = std::make_unique<MpiDomain>(rank_, size_);
#else
  (void)argc, (void)argv;
  throw InputError("started by an MPI launcher for several ranks, but this build has no MPI (install "
                   "libopenmpi-dev and configure again)");
#endif
}

void MpiSession::report_error(const std::string& line, int status) {
  // One write of the whole line: unbuffered std::cerr writes each << apart, and the launcher
  // forwards each write as it comes, so MPI_Abort's banner could land inside the line.
  const std::string text = "error: " + line + "\n";
#ifdef MESOWAVE_HAVE_MPI
  if (size_ > 1) {
    if (rank_ != 0 && !waited_) std::this_thread::sleep_for(std::chrono::seconds(3));
    std::fwrite(text.data(), 1, text.size(), stderr);
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, status);
  }
#endif
  (void)status;
  std::fwrite(text.data(), 1, text.size(), stderr);
}

bool MpiSession::outlive_root_report() {
  if (size_ > 1 && rank_ != 0 && !waited_) std::this_thread::sleep_for(std::chrono::seconds(3));
  waited_ = true;
  return true;
}

MpiSession::~MpiSession() {
#ifdef MESOWAVE_HAVE_MPI
  if (initialised_) MPI_Finalize();
#endif
}

}  // namespace mesowave::dem
