// core/lanczos.hpp: the top eigenvalue against the closed form of the 1-D Laplacian, and the
// row-split iteration (what the DEM's ranks run, docs/mpi.md) against the one-process one, bit for
// bit, with threads standing in for the ranks.
#include "mesowave/core/lanczos.hpp"

#include <gtest/gtest.h>

#include <barrier>
#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

using namespace mesowave;

namespace {

constexpr std::size_t kSize = 120;

// y = A x for A = tridiag(-1, 2, -1), rows [first, first + count) from the whole x.
void laplacian_rows(const double* whole_x, double* y, std::size_t first, std::size_t count) {
  for (std::size_t r = 0; r < count; ++r) {
    const std::size_t i = first + r;
    y[r] = 2.0 * whole_x[i] - (i > 0 ? whole_x[i - 1] : 0.0) - (i + 1 < kSize ? whole_x[i + 1] : 0.0);
  }
}

// lambda_max(tridiag(-1, 2, -1)) = 2 + 2 cos(pi / (n + 1)). Ritz values approach it from below; the
// residual bound then lies above it.
TEST(Lanczos, LaplacianTopEigenvalueIsTheClosedForm) {
  const double exact = 2.0 + 2.0 * std::cos(std::numbers::pi / double(kSize + 1));
  const auto r = largest_eigenvalue(kSize, [](const double* x, double* y) { laplacian_rows(x, y, 0, kSize); }, 150, 1e-10);
  EXPECT_NEAR(r.ritz, exact, 1e-13 * exact);  // 1.2e-15 measured: the Krylov space is the whole space
  EXPECT_LE(r.ritz, exact * (1 + 1e-14));
  EXPECT_GE(r.ritz + r.residual, exact * (1 - 1e-14));
}

// Three "ranks" (threads) hold rows [0, 30), [30, 80), [80, 120). apply gathers x through a shared
// vector; dot continues the partial sum rank after rank in row order, as the DEM's chained_sum does.
TEST(Lanczos, RowsSplitOverThreeRanksGiveTheBitsOfOneProcess) {
  const auto whole = largest_eigenvalue(kSize, [](const double* x, double* y) { laplacian_rows(x, y, 0, kSize); });
  const std::size_t bounds[] = {0, 30, 80, kSize};
  constexpr int kRanks = 3;
  std::vector<double> shared_x(kSize), partial(kRanks + 1);
  std::barrier sync(kRanks);
  LanczosResult results[kRanks];
  std::vector<std::thread> ranks;
  for (int rank = 0; rank < kRanks; ++rank)
    ranks.emplace_back([&, rank] {
      const std::size_t first = bounds[rank], count = bounds[rank + 1] - first;
      const auto apply = [&](const double* x, double* y) {
        std::copy(x, x + count, shared_x.begin() + std::ptrdiff_t(first));
        sync.arrive_and_wait();
        laplacian_rows(shared_x.data(), y, first, count);
        sync.arrive_and_wait();  // nobody writes x again before every rank has read it
      };
      const auto dot = [&](const double* a, const double* b) {
        for (int turn = 0; turn < kRanks; ++turn) {  // rank `turn` continues the sum of the ranks before
          if (turn == rank) {
            double sum = turn == 0 ? 0.0 : partial[std::size_t(turn)];
            for (std::size_t i = 0; i < count; ++i) sum += a[i] * b[i];
            partial[std::size_t(turn + 1)] = sum;
          }
          sync.arrive_and_wait();
        }
        const double sum = partial[kRanks];
        sync.arrive_and_wait();  // read by all before the next dot writes it
        return sum;
      };
      results[rank] = largest_eigenvalue(LanczosRows{kSize, first, count}, apply, dot);
    });
  for (auto& t : ranks) t.join();
  for (const auto& r : results) {
    EXPECT_EQ(r.ritz, whole.ritz);
    EXPECT_EQ(r.residual, whole.residual);
    EXPECT_EQ(r.iterations, whole.iterations);
  }
  EXPECT_GT(whole.iterations, 10);
}

}  // namespace
