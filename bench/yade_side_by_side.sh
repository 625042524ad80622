#!/usr/bin/env bash
# The DEM step against Yade, side by side (issue 17 item 3; docs/benchmarks.md, "The step near the
# memory limit", fifth part): in each round, Yade 2023.02a's wave script on the cube, then bench_dem's
# step benchmarks on the same packing, at 1 and then 2 threads, so that both codes see the machine in
# the same state (its speed drifts by up to 2x within minutes). Prints every run's time per step and,
# per model and thread count, the median over the rounds of Yade's s/step divided by mesowave's
# (bench/paired_ratios.py).
# Needs `scripts/install-deps bench` (Yade) and the packing exported for Yade.
#
#   mw-pack box --cube-side-mm 50 ... --packing cube.h5 --export-yade cube.txt
#   mw-dem info pipeline/concrete-cube/scenes/cube-wave.toml --packing cube.h5 > cube-info.json
#   bench/yade_side_by_side.sh cube.h5 cube.txt cube-info.json [rounds] [yade steps]
set -euo pipefail
PACKING=$1
SPHERES_TXT=$2
INFO=$3
ROUNDS=${4:-3}
STEPS=${5:-300}
BIN=${BIN:-build/bin}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "# $(date -u +%FT%TZ) $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $ROUNDS rounds, Yade $STEPS steps"
for round in $(seq 1 "$ROUNDS"); do
  for threads in 1 2; do
    echo "# round $round, $threads thread(s), load $(cut -d' ' -f1 /proc/loadavg)"
    yade -n -j"$threads" -x bench/yade/wave.py "$SPHERES_TXT" "$INFO" "$tmp/yade.json" "$STEPS" "$threads" > /dev/null 2>&1
    yade_s=$(python3 -c "import json,sys; print('%.6f' % json.load(open(sys.argv[1]))['s_per_step'])" "$tmp/yade.json")
    echo "yade, round $round, $threads thread(s): $yade_s s/step"
    # Rows for the summary, "THREADS-thread-MODEL ROUND CODE s/step": Yade's once for each model.
    MESOWAVE_BENCH_PACKING=$PACKING "$BIN/bench_dem" --benchmark_filter="Step/$threads/" --benchmark_format=json 2>/dev/null |
      python3 -c "
import json, sys
for b in json.load(sys.stdin)['benchmarks']:
    scale = {'ms': 1e-3, 'us': 1e-6, 'ns': 1e-9}[b['time_unit']]
    group = sys.argv[2] + '-thread-' + ('full' if 'FullLaw' in b['name'] else 'linear')
    print(group, sys.argv[1], 'mesowave', '%.6f' % (b['real_time'] * scale))
    print(group, sys.argv[1], 'yade', sys.argv[3])" "$round" "$threads" "$yade_s" | tee -a "$tmp/rows" | grep mesowave
  done
done
# Per model and thread count: the medians (s/step) and the median of the rounds' Yade / mesowave.
python3 "$(dirname "$0")/paired_ratios.py" "$tmp/rows" yade mesowave --unit s/step
