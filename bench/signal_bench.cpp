// Signal toolkit benchmarks (issue #3): envelopes and spectra of a 30,000- and
// a 4,194,304-sample record, prime lengths beside the nearest power of two, and
// the concrete paper's Table-3 analysis: 6 sensors x 9 frequencies x 30,000
// samples, two signal sets - envelopes, PCC of signals and of envelopes, spectra.
//
//   build/bin/bench_signal --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// scipy's figures for the same work: bench/signal_scipy.py. Results: docs/benchmarks.md.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <numbers>

#include "mesowave/signal/correlation.hpp"
#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/fft.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "mesowave/signal/noise.hpp"
#include "mesowave/signal/spectrum.hpp"

using namespace mesowave::signal;

namespace {

// A burst train in noise: the kind of record the tools see.
std::vector<double> record(std::size_t n, std::uint64_t seed) {
  const auto noise = gaussian_noise(n, 0.05, seed);
  const HannBurst burst(100e3 + 50e3 * double(seed % 9), 5, 1.0, 0.0);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = burst(double(i % 2000) * 1e-7) + noise[i];
  return x;
}

void BM_Envelope(benchmark::State& state) {
  const auto x = record(std::size_t(state.range(0)), 1);
  for (auto _ : state) benchmark::DoNotOptimize(envelope(x));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_Spectrum(benchmark::State& state) {
  const auto x = record(std::size_t(state.range(0)), 2);
  for (auto _ : state) benchmark::DoNotOptimize(amplitude_spectrum(x, 1e-7));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_RealFft(benchmark::State& state) {
  const auto x = record(std::size_t(state.range(0)), 3);
  for (auto _ : state) benchmark::DoNotOptimize(rfft(x));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The complex transforms Bluestein's convolution runs on, at the lengths >= 1.5 x 29,999 it
// could choose (fft.cpp picks its length by these timings' pattern: few factors of 5 and 7).
void BM_ComplexFft(benchmark::State& state) {
  const auto x = record(std::size_t(state.range(0)), 4);
  std::vector<Complex> z(x.begin(), x.end());
  for (auto _ : state) benchmark::DoNotOptimize(fft(z));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// Table 3: for each of 9 frequencies, 6 sensors in two sets; envelopes, PCC
// of signals and envelopes, and spectra of both records per sensor, in one
// correlate_sensors call (sensors in parallel over `threads`).
void BM_Table3Analysis(benchmark::State& state) {
  omp_set_num_threads(int(state.range(0)));
  const std::size_t n = 30000;
  std::vector<std::vector<Signal>> a(9), b(9);
  for (std::size_t f = 0; f < 9; ++f)
    for (std::size_t s = 0; s < 6; ++s) {
      const std::string name(1, char('B' + s));
      a[f].push_back(Signal{name, "acceleration", "m/s^2", "z", 0.0, 1e-7, record(n, 100 * f + s), std::nullopt});
      b[f].push_back(Signal{name, "acceleration", "m/s^2", "z", 0.0, 1e-7, record(n, 1000 + 100 * f + s), std::nullopt});
    }
  CorrelationOptions options;
  options.spectra = SpectrumOptions{};  // spectra of both records of every sensor, as scipy's run computes
  for (auto _ : state) {
    double sum = 0;
    for (std::size_t f = 0; f < 9; ++f) {
      const auto table = correlate_sensors(a[f], b[f], options);
      sum += table.mean_pcc_signal + table.mean_pcc_envelope + table.sensors[0].spectrum_b.amplitude[100];
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["pairs"] = 54;
}

}  // namespace

BENCHMARK(BM_Envelope)->Arg(30000)->Arg(29999)->Arg(32768)->Arg(4194304)->Arg(4194301)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Spectrum)->Arg(30000)->Arg(29999)->Arg(32768)->Arg(4194304)->Arg(4194301)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RealFft)->Arg(30000)->Arg(29999)->Arg(32768)->Arg(4194304)->Arg(4194301)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ComplexFft)->Arg(45000)->Arg(45360)->Arg(46080)->Arg(48000)->Arg(49152)->Arg(50000)->Arg(65536)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Table3Analysis)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
