// The machine's memory bandwidth, to set the DEM step's bytes against (docs/benchmarks.md,
// "DEM engine: the step near the memory limit"): McCalpin's STREAM triad a = b + s c on arrays of
// doubles, at 1 and 2 OpenMP threads, for three working sets - one that fits in L2 (3 x 512 KiB),
// one the size of the DEM cube's working set that fits in this VM's 32 MiB L3 (3 x 6 MiB), and one
// far beyond any cache (3 x 128 MiB: main memory). Bytes counted as STREAM counts them, 24 per
// element (two reads, one write; the write-allocate read is not counted).
//
//   build/bin/bench_stream --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cstddef>
#include <vector>

namespace {

void BM_StreamTriad(benchmark::State& state) {
  const std::size_t n = std::size_t(state.range(0)) / sizeof(double);
  const int threads = int(state.range(1));
  std::vector<double> a(n), b(n, 1.0), c(n, 2.0);
  const double s = 3.0;
  double* pa = a.data();
  const double* pb = b.data();
  const double* pc = c.data();
  // Each thread touches its own part first (first-touch placement) and keeps it in every repetition.
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t i = 0; i < n; ++i) pa[i] = 0.0;
  for (auto _ : state) {
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t i = 0; i < n; ++i) pa[i] = pb[i] + s * pc[i];
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(a.data());
  state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(3 * n * sizeof(double)));
}

}  // namespace

BENCHMARK(BM_StreamTriad)
    ->ArgNames({"bytes_per_array", "threads"})
    ->ArgsProduct({{512 << 10, 6 << 20, 128 << 20}, {1, 2}})
    ->UseRealTime()
    ->MinTime(1.0);

BENCHMARK_MAIN();
