#!/usr/bin/env bash
# DEM engine benchmarks, recorded in docs/benchmarks.md ("DEM engine"):
#  1. steps/s of the full law and the linearised network at 1 and 2 threads
#     (bin/bench_dem on the mw-pack cube, medians of repetitions);
#  2. wall time, steps/s and peak memory of whole 30,000-step cube runs at
#     100 kHz (mw-dem run, linear and full, 2 threads and 1);
#  3. the rod chain (191 spheres, 30,000 steps);
#  4. Yade 2023.02a on the same cube and parameters (bench/yade/wave.py,
#     1,000 steps), back to back.
# The machine is shared: each measurement records the 1-minute load average
# before it, and the script first waits (up to WAIT_MIN minutes) for the load
# to drop below LOAD_MAX.
#
#   bench/dem_runs.sh [build-dir] > results/bench/dem-runs.txt
set -euo pipefail
BUILD=${1:-build}
BIN=$BUILD/bin
REPS=${REPS:-5}
YADE_STEPS=${YADE_STEPS:-1000}
LOAD_MAX=${LOAD_MAX:-1.0}
WAIT_MIN=${WAIT_MIN:-30}
CUBE=results/concrete-cube/packing.h5
CUBE_TXT=results/bench/cube.txt
SCENE=pipeline/concrete-cube/scenes/cube-wave.toml
mkdir -p results/bench

load() { cut -d' ' -f1 /proc/loadavg; }
wait_quiet() {
  local waited=0
  while awk -v l="$(load)" -v m="$LOAD_MAX" 'BEGIN{exit !(l > m)}' && [ $waited -lt $((WAIT_MIN * 60)) ]; do
    sleep 20; waited=$((waited + 20))
  done
}
note() { echo "# $(date -u +%FT%TZ) load $(load): $*"; }

{ [ -f "$CUBE" ] && [ -f "$CUBE_TXT" ]; } || $BIN/mw-pack box --cube-side-mm 50 --porosity-pct 7 --d-min-mm 1.6 --d-max-mm 2 \
  --density-kg-m3 2129.56 --packing "$CUBE" --export-yade "$CUBE_TXT" --quiet > /dev/null
echo "# machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"

wait_quiet
note "step benchmarks (bench_dem, $REPS repetitions, medians)"
MESOWAVE_BENCH_PACKING=$CUBE $BIN/bench_dem --benchmark_filter='Step' --benchmark_repetitions=$REPS \
  --benchmark_report_aggregates_only=true --benchmark_min_time=2 2>/dev/null | grep -E 'median|Benchmark'

for model in linear full; do
  for threads in 2 1; do
    wait_quiet
    note "mw-dem run $SCENE --model $model --threads $threads (30,000 steps, 100 kHz)"
    /usr/bin/time -f '# peak RSS %M KiB, elapsed %e s' $BIN/mw-dem run $SCENE --model $model --threads $threads \
      --frequency-kHz 100 --signals /tmp/dem-bench.h5 --quiet 2>&1 | grep -E '"(model|threads|wall_s|steps_per_s|ns_per_contact_step|setup_s)"|peak RSS'
  done
done

wait_quiet
note "rod chain (191 spheres, 30,000 steps)"
$BIN/mw-pack line --experiment lab-data/steel-rod/experiment.toml --spacing-R 1.03 \
  --packing results/bench/rod.h5 --quiet > /dev/null
for i in 1 2 3 4 5; do
  $BIN/mw-dem run pipeline/steel-rod/scenes/rod-wave.toml --packing results/bench/rod.h5 --signals /tmp/rod-bench.h5 \
    --quiet | grep -E '"wall_s"'
done

if command -v yade > /dev/null; then
  $BIN/mw-dem info $SCENE > results/bench/cube-info.json
  [ -f "$CUBE_TXT" ] || { echo "# no $CUBE_TXT: remake the cube with --export-yade"; exit 0; }
  for j in 1 2; do
    wait_quiet
    note "yade -j$j, $YADE_STEPS steps of the same cube"
    yade -n -j$j -x bench/yade/wave.py "$CUBE_TXT" results/bench/cube-info.json results/bench/cube-yade-j$j.json \
      $YADE_STEPS $j 2>&1 | { grep '^yade:' || echo "# yade failed: run the command above by hand to see why"; }
    wait_quiet
    note "mw-dem, same $YADE_STEPS steps, threads $j (linear, then full)"
    for model in linear full; do
      $BIN/mw-dem run $SCENE --model $model --threads $j --duration-ms $(awk -v n=$YADE_STEPS 'BEGIN{print n*5e-5}') \
        --signals /tmp/dem-bench.h5 --quiet | grep -E '"(model|wall_s|steps_per_s)"'
    done
  done
fi
note "done"
