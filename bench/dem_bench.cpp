// DEM step benchmarks (docs/benchmarks.md, "DEM engine"): time per step of
// the full law and the linearised network at 1 and 2 threads on the 50 mm
// cube. The packing is MESOWAVE_BENCH_PACKING (an mw-pack file) if set, else
// a stand-in of the same size: a jittered FCC block of 37,044 spheres with
// diameters 1.6-2.0 mm and ~220,000 bonds.
//
//   build/bin/bench_dem --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <memory>

#include "dem_step_model.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/dem/contact/cohesive_frictional_contact.hpp"
#include "mesowave/dem/contact/linear_bonded_network.hpp"
#include "mesowave/dem/packing/packing_file.hpp"
#include "mesowave/dem/engine/simulation.hpp"

using namespace mesowave::dem;

namespace {

Packing stand_in_cube() {
  Packing p;
  std::uint64_t state = 12345;
  auto uniform = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / double(1ULL << 53);
  };
  const int cells = 21;
  const double a = 2.55e-3;  // nearest neighbours a/sqrt(2) = 1.80 mm apart: the mean diameter
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int k = 0; k < cells; ++k)
        for (const auto& b : basis) {
          std::array<double, 3> c = {(i + b[0] + 0.5) * a, (j + b[1] + 0.5) * a, (k + b[2] + 0.5) * a};
          for (double& x : c) x += 0.03 * a * (2 * uniform() - 1);
          p.centres_m.push_back(c);
          p.radii_m.push_back(0.8e-3 + 0.2e-3 * uniform());
          p.ids.push_back(std::int64_t(p.ids.size()));
        }
  // Shuffle, as a generator would leave them: the engine's Morton renumbering must recover locality.
  for (std::size_t i = p.radii_m.size() - 1; i > 0; --i) {
    const std::size_t j = std::size_t(uniform() * double(i + 1));
    std::swap(p.centres_m[i], p.centres_m[j]);
    std::swap(p.radii_m[i], p.radii_m[j]);
  }
  p.container.shape = "box";
  p.container.upper_m = {cells * a + 0.5 * a, cells * a + 0.5 * a, cells * a + 0.5 * a};
  p.particle_density_kg_m3 = 2290;
  return p;
}

const Packing& cube() {
  static const Packing p = [] {
    const char* file = std::getenv("MESOWAVE_BENCH_PACKING");
    return file ? read_packing_file(file) : stand_in_cube();
  }();
  return p;
}

template <class Law>
void step_benchmark(benchmark::State& state) {
  mesowave::use_threads(int(state.range(0)));
  const auto model = mesowave::bench::step_model<Law>(cube());
  for (auto _ : state) model->step(5e-8, false);
  state.counters["spheres"] = double(model->sphere_count());
  state.counters["bonds"] = double(model->bond_count());
  state.counters["ns_per_bond_step"] =
      benchmark::Counter(double(model->bond_count()) * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.SetItemsProcessed(state.iterations());
}

void BM_FullLawStep(benchmark::State& state) { step_benchmark<CohesiveFrictionalContact>(state); }
void BM_LinearNetworkStep(benchmark::State& state) { step_benchmark<LinearBondedNetwork>(state); }

void BM_BondDetection(benchmark::State& state) {
  const auto m = mesowave::bench::concrete(cube());
  const SphereSet s = make_sphere_set(cube(), m.density_kg_m3);
  for (auto _ : state) benchmark::DoNotOptimize(make_bond_network(s, m.bond_factor));
}

}  // namespace

BENCHMARK(BM_FullLawStep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_LinearNetworkStep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_BondDetection)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
