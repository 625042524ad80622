// ordered_dot: the sum in row order, which a process continues from the previous one's partial sum
// (the critical step on several ranks): continued at any split it has the bits of one pass, and
// those are the bits of adding in row order, not of another order.
#include "mesowave/core/ordered_dot.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

TEST(OrderedDot, ContinuedAtAnySplitHasTheBitsOfOnePassInRowOrder) {
  // Terms of very different sizes, so that the order of the additions shows in the bits.
  const std::vector<double> a = {1e16, 1.0, -1e16, 1.0, 3.0, 1e-3, 7.0};
  const std::vector<double> b = {1.0, 1.0, 1.0, 1.0, 0.5, 1.0, 1e-9};
  double serial = 0;
  for (std::size_t i = 0; i < a.size(); ++i) serial += a[i] * b[i];
  const double one_pass = mesowave::ordered_dot(a.data(), b.data(), a.size());
  EXPECT_EQ(one_pass, serial);
  EXPECT_EQ(one_pass, 2.5 + 1e-3 + 7e-9);  // 1e16 + 1 rounds to 1e16: the first 1.0 is lost, the second kept
  for (std::size_t k = 0; k <= a.size(); ++k) {
    const double first = mesowave::ordered_dot(a.data(), b.data(), k);
    EXPECT_EQ(mesowave::ordered_dot(a.data() + k, b.data() + k, a.size() - k, first), one_pass) << k;
  }
  // Backwards the cancellation goes otherwise: the bits depend on the order.
  double backwards = 0;
  for (std::size_t i = a.size(); i-- > 0;) backwards += a[i] * b[i];
  EXPECT_NE(backwards, one_pass);
}

}  // namespace
