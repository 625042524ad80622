#pragma once
// The ranks of a distributed DEM run as the engine sees them (docs/mpi.md): who
// this process is and the few collective operations the step needs. The engine
// holds a Domain only when there is more than one rank; it never includes MPI,
// so a build without MPI and a plain run (np = 1) carry no MPI code at all.
// The one implementation, over MPI_COMM_WORLD, is mpi_session.hpp.
//
// Every operation is collective: all ranks call it, in the same order, with
// their own part. Sums are never taken by the communication layer (an MPI
// reduction adds in an order of its own choosing): data is gathered and the
// caller adds it in the serial order, so the bits match the single-process run.
// The only reductions are max and the integer sum, which are exact in any order.
// exchange() is the point-to-point part: each rank sends its neighbours the motion of
// the spheres they hold as ghosts (stage 2, docs/mpi.md), nothing to anyone else.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mesowave::dem {

class Domain {
public:
  /// One point-to-point message of `count` doubles to or from `rank`.
  struct Message {
    int rank;
    double* data;
    int count;
  };
  virtual ~Domain() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// In place: rank r's part data[displs[r] .. displs[r] + counts[r]) (doubles) is copied to
  /// every rank; the parts must not overlap.
  virtual void share(double* data, const std::vector<int>& counts, const std::vector<int>& displs) = 0;
  /// recv gets every rank's `send` (counts[r] doubles each), in rank order at displs[r].
  virtual void gather_all(const double* send, int count, double* recv, const std::vector<int>& counts,
                          const std::vector<int>& displs) = 0;
  /// Rank 0's recv gets every rank's `send` (counts[r] doubles each, in rank order at displs[r]);
  /// the other ranks' recv is not touched (what only rank 0 writes: a checkpoint).
  virtual void gather(const double* send, int count, double* recv, const std::vector<int>& counts,
                      const std::vector<int>& displs) = 0;
  /// Every send goes to its rank, every receive is filled from its rank; both sides know
  /// the counts (the ghost lists are built on both from the same layout). Not collective:
  /// only the ranks named take part. Returns when all have completed.
  virtual void exchange(const std::vector<Message>& sends, const std::vector<Message>& receives) = 0;
  /// The largest of every rank's value (exact in any order).
  virtual double max(double value) = 0;
  /// The sum of every rank's count (integers: exact in any order).
  virtual std::uint64_t sum(std::uint64_t count) = 0;
  /// In place, each count the sum of every rank's at its place (integers: exact in any order).
  virtual void sum_each(std::vector<std::uint64_t>& counts) = 0;
};

/// A hash of a pair of spheres (first, second), for the ranks' check that they agree on the pairs
/// across them before an exchange: each adds the hashes of the pairs it sends and subtracts those
/// it expects, and the integer sum over the ranks (mod 2^64) is 0 unless they disagree, in which
/// case every rank stops with one line rather than in a message of the wrong size.
inline std::uint64_t pair_hash(std::uint32_t first, std::uint32_t second) {
  return ((std::uint64_t(first) << 32) | second) * 0x9E3779B97F4A7C15ull;
}

/// Every rank's `value` (a count: exact below 2^53), in rank order, on every rank.
inline std::vector<double> gathered_each(Domain& domain, double value) {
  const auto ranks = static_cast<std::size_t>(domain.size());
  std::vector<int> ones(ranks, 1), at(ranks);
  for (std::size_t r = 0; r < ranks; ++r) at[r] = int(r);
  std::vector<double> all(ranks);
  domain.gather_all(&value, 1, all.data(), ones, at);
  return all;
}

/// Every rank's list `mine` (of any length), one after the other in rank order, on every rank.
inline std::vector<double> gathered_lists(Domain& domain, const std::vector<double>& mine) {
  const std::vector<double> lengths = gathered_each(domain, double(mine.size()));
  std::vector<int> counts(lengths.size()), displs(lengths.size());
  std::size_t total = 0;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    counts[r] = int(lengths[r]), displs[r] = int(total);
    total += std::size_t(lengths[r]);
  }
  std::vector<double> all(total);
  domain.gather_all(mine.data(), int(mine.size()), all.data(), counts, displs);
  return all;
}

/// What every rank sends this one, one after the other in rank order, into `in`: out[t] goes to
/// rank t (this rank's own, out[rank], stays; `out` is read, not changed). The lengths travel
/// first, one double each way.
inline void exchange_lists(Domain& domain, std::vector<std::vector<double>>& out, std::vector<double>& in) {
  const auto ranks = static_cast<std::size_t>(domain.size()), me = static_cast<std::size_t>(domain.rank());
  std::vector<double> lengths_out(ranks), lengths_in(ranks);
  std::vector<Domain::Message> sends, receives;
  for (std::size_t r = 0; r < ranks; ++r) {
    if (r == me) continue;
    lengths_out[r] = double(out[r].size());
    sends.push_back({int(r), &lengths_out[r], 1});
    receives.push_back({int(r), &lengths_in[r], 1});
  }
  domain.exchange(sends, receives);
  std::vector<std::size_t> at(ranks + 1, 0);  // where rank r's list starts in `in`
  for (std::size_t r = 0; r < ranks; ++r) at[r + 1] = at[r] + (r == me ? out[r].size() : std::size_t(lengths_in[r]));
  in.resize(at[ranks]);
  std::copy(out[me].begin(), out[me].end(), in.begin() + std::ptrdiff_t(at[me]));
  sends.clear(), receives.clear();
  for (std::size_t r = 0; r < ranks; ++r) {
    if (r == me) continue;
    if (!out[r].empty()) sends.push_back({int(r), out[r].data(), int(out[r].size())});
    if (at[r + 1] > at[r]) receives.push_back({int(r), in.data() + at[r], int(at[r + 1] - at[r])});
  }
  domain.exchange(sends, receives);
}

/// exchange_lists into a new list; `out` is spent.
inline std::vector<double> exchanged_lists(Domain& domain, std::vector<std::vector<double>> out) {
  std::vector<double> in;
  exchange_lists(domain, out, in);
  return in;
}

/// A floating-point sum in the serial order of parts held rank after rank (rank r's part comes
/// after rank r - 1's, as the spheres' ranges do): rank 0 starts from 0, each rank continues the
/// previous rank's partial sum (`continue_sum(partial)` adds its own terms in order) and passes
/// it on; every rank gets the last one's. The bits of one process adding every term in order,
/// at the price of the ranks adding one after the other (setup only: the critical step's Lanczos).
template <class Continue>
double chained_sum(Domain& domain, const Continue& continue_sum) {
  const int me = domain.rank(), ranks = domain.size();
  double sum = 0;
  if (me > 0) domain.exchange({}, {{me - 1, &sum, 1}});
  sum = continue_sum(sum);
  if (me + 1 < ranks) domain.exchange({{me + 1, &sum, 1}}, {});
  std::vector<int> counts(static_cast<std::size_t>(ranks), 0), displs(static_cast<std::size_t>(ranks), 0);
  counts.back() = 1;
  domain.share(&sum, counts, displs);
  return sum;
}

}  // namespace mesowave::dem
