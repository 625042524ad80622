#!/usr/bin/env bash
# Where the DEM step's time goes, without the set-up (docs/benchmarks.md, "The step near the memory
# limit", sixth part): bench_dem_sizes --profile-s builds the model and then steps it alone; perf
# attaches once it steps and samples the rest (software clock: this VM gives perf no hardware
# counters). Prints the step's ms and the functions' shares; the samples stay in OUT.data for
# `perf annotate`. (A bench_dem run under perf also samples the set-up, which at 1 M spheres takes
# longer than the steps it times.)
#
#   bench/step_profile.sh packing.h5 [linear|full] [threads] [seconds] [OUT]
set -euo pipefail
PACKING=$1
MODEL=${2:-linear}
THREADS=${3:-1}
SECONDS_STEPPED=${4:-20}
OUT=${5:-step-profile}
BIN=${BIN:-build/bin}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
"$BIN/bench_dem_sizes" --model "$MODEL" --threads "$THREADS" --profile-s "$SECONDS_STEPPED" "$PACKING" > "$log" 2>/dev/null &
until grep -q '^# process' "$log"; do
  kill -0 $! 2> /dev/null || { echo "error: bench_dem_sizes ended before it stepped" >&2; exit 1; }
  sleep 0.2
done
pid=$(sed -n 's/^# process \([0-9]*\):.*/\1/p' "$log")
echo "# $(date -u +%FT%TZ) $PACKING, $MODEL, $THREADS thread(s), load $(cut -d' ' -f1 /proc/loadavg)"
# The first second is left out (caches and pages settle), the last one too (the process may end).
sleep 1
perf record -e cpu-clock -p "$pid" -o "$OUT.data" -- sleep $((SECONDS_STEPPED > 3 ? SECONDS_STEPPED - 2 : 1)) > /dev/null 2>&1
wait
tail -n 1 "$log"
perf report -i "$OUT.data" --no-children --sort symbol 2> /dev/null | grep -v '^#' | grep -v '^$' | head -8 | cut -c1-100
