// The Koermeling-Reinhardt notched beam (efg/three_point_bending.hpp) on grids finer than the
// tests can afford: per law and node spacing one complete run, its peak load, deflection at the
// peak, work of fracture, dissipated energy, elastic stiffness and cost as counters.
//
//   build/bin/bench_efg_beam --benchmark_filter='/10/'   (spacing in units of 0.5 mm)
//
// Results: docs/efg.md.
#include <benchmark/benchmark.h>

#include "mesowave/efg/three_point_bending.hpp"

using namespace mesowave::efg;

namespace {

/// `ligament`: the whole ligament a cohesive interface from the start, run until the beam has separated (the
/// complete curve and its work of fracture); otherwise St. Venant growth to 1.5 mm.
void run(benchmark::State& state, const char* law, bool ligament) {
  ThreePointBendingOptions o;
  o.law = law;
  o.spacing_m = 0.5e-3 * static_cast<double>(state.range(0));
  o.max_deflection_m = 1.5e-3;
  o.steps = 75;
  if (ligament) {
    o.ligament_interface = true;
    o.max_deflection_m = 12e-3;
    o.steps = 60;
    o.step_ratio = 1.07;
    o.stop_load_fraction = 1e-4;
  }
  ThreePointBendingResult r;
  for (auto _ : state) r = run_three_point_bending(o);
  state.counters["nodes"] = static_cast<double>(r.nodes);
  state.counters["gauss_points"] = static_cast<double>(r.gauss_points);
  state.counters["peak_N"] = r.peak_load_N;
  state.counters["deflection_at_peak_mm"] = r.deflection_at_peak_m * 1e3;
  state.counters["work_Nmm"] = r.work_of_fracture_J * 1e3;
  state.counters["dissipated_Nmm"] = r.dissipated_J * 1e3;
  state.counters["stored_Nmm"] = r.stored_J * 1e3;
  state.counters["final_load_N"] = r.final_load_N;
  state.counters["final_deflection_mm"] = r.final_deflection_m * 1e3;
  state.counters["k_elastic_N_per_mm"] = r.elastic_stiffness_N_per_m * 1e-3;
  state.counters["newton_iterations"] = r.newton_iterations;
  state.counters["crack_tip_mm"] = r.crack_path.back().y() * 1e3;
  state.counters["completed"] = r.completed ? 1 : 0;
  state.counters["wall_s"] = r.wall_s;
}

}  // namespace

BENCHMARK_CAPTURE(run, exponential, "exponential", false)->Arg(20)->Arg(10)->Arg(5)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(run, bilinear, "bilinear", false)->Arg(20)->Arg(10)->Arg(5)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(run, exponential_ligament, "exponential", true)->Arg(20)->Arg(10)->Arg(5)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(run, bilinear_ligament, "bilinear", true)->Arg(20)->Arg(10)->Arg(5)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_MAIN();
