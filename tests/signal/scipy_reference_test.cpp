// Against scipy itself: scipy.signal.hilbert and numpy.fft.rfft on records of
// even, odd, prime and awkward lengths (tests/data/signal/scipy_reference.csv,
// made by make_scipy_reference.py beside it with Debian's scipy 1.10.1).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "mesowave/io/csv.hpp"
#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/fft.hpp"

using namespace mesowave;
using namespace mesowave::signal;

TEST(ScipyReference, HilbertEnvelopeAndRfftMatchScipy) {
  const auto table = io::read_csv(std::string(MESOWAVE_SOURCE_DIR) + "/tests/data/signal/scipy_reference.csv");
  struct Record {
    std::vector<double> x, h, e, X;
  };
  std::map<std::size_t, Record> records;
  const auto cn = table.column("n"), cx = table.column("x"), ch = table.column("hilbert_imag"),
             ce = table.column("envelope"), cX = table.column("rfft_abs");
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    auto& rec = records[std::size_t(table.number(r, cn))];
    rec.x.push_back(table.number(r, cx));
    rec.h.push_back(table.number(r, ch));
    rec.e.push_back(table.number(r, ce));
    if (!table.text(r, cX).empty()) rec.X.push_back(table.number(r, cX));
  }
  ASSERT_EQ(records.size(), 14u);
  for (const auto& [n, rec] : records) {
    ASSERT_EQ(rec.x.size(), n);
    const auto h = hilbert_transform(rec.x);
    const auto e = envelope(rec.x);
    const auto X = rfft(rec.x);
    ASSERT_EQ(X.size(), rec.X.size()) << n;
    // Both sides round at ~eps log n times the record's scale (|x| < 1.6, |X| < 1.6 n).
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_NEAR(h[i], rec.h[i], 1e-13) << "n " << n << " i " << i;
      EXPECT_NEAR(e[i], rec.e[i], 1e-13) << "n " << n << " i " << i;
    }
    for (std::size_t k = 0; k < X.size(); ++k) EXPECT_NEAR(std::abs(X[k]), rec.X[k], 1e-13 * double(n)) << n;
  }
}
