#pragma once
// The dot product in row order: the one order that the Lanczos iteration's vectors are summed in,
// in one process and, continued rank after rank, on several (dem/parallel/domain.hpp's
// chained_sum), so that the critical step has the same bits on any rank count.
#include <cstddef>

namespace mesowave {

/// sum + sum_i a_i b_i over i < n, added in row order.
inline double ordered_dot(const double* a, const double* b, std::size_t n, double sum = 0) {
  for (std::size_t i = 0; i < n; ++i) sum += a[i] * b[i];
  return sum;
}

}  // namespace mesowave
