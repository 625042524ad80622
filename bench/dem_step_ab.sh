#!/usr/bin/env bash
# Two builds' DEM step timed against each other on a shared machine (docs/benchmarks.md, "The step
# near the memory limit"): bench_dem of build A and of build B alternated A, B, A, B, ... in one
# script, benchmark by benchmark, so that both see the same load; the 1-minute load average is
# printed before each run.
# Medians over the rounds (the `median` lines at the end), per benchmark and build.
#
#   MESOWAVE_BENCH_PACKING=cube.h5 bench/dem_step_ab.sh OLD/bin/bench_dem NEW/bin/bench_dem [rounds] [filter] [min_time]
set -euo pipefail
A=$1
B=$2
ROUNDS=${3:-5}
FILTER=${4:-Step/}
MIN_TIME=${5:-1}
: "${MESOWAVE_BENCH_PACKING:?set MESOWAVE_BENCH_PACKING to a packing file}"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
echo "# $(date -u +%FT%TZ) A=$A B=$B rounds=$ROUNDS filter=$FILTER min_time=$MIN_TIME"
# Alternated per benchmark (A, B on one benchmark, then the next), so that a pair sees the same load.
names=$("$A" --benchmark_list_tests=true --benchmark_filter="$FILTER" 2>/dev/null)
for round in $(seq 1 "$ROUNDS"); do
  for name in $names; do
    for side in A B; do
      bin=$A
      [ "$side" = B ] && bin=$B
      echo "# round $round $side load $(cut -d' ' -f1 /proc/loadavg)"
      "$bin" --benchmark_filter="^$name\$" --benchmark_min_time="$MIN_TIME" 2>/dev/null | grep '^BM_' |
        sed "s/^/$side /" | tee -a "$out"
    done
  done
done
# Median of the wall and CPU ms per benchmark and side.
awk '{name = $1 " " $2; sub(/\/min_time.*/, "", name); wall[name] = wall[name] " " $3; cpu[name] = cpu[name] " " $5}
  function median(list,   v, n, i, j, t) {
    n = split(list, v, " ")
    for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j) if (v[j] + 0 < v[i] + 0) { t = v[i]; v[i] = v[j]; v[j] = t }
    return n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2
  }
  END { for (k in wall) printf "median %-32s wall %8.3f ms  cpu %8.3f ms\n", k, median(wall[k]), median(cpu[k]) }' "$out" | sort -k3,3 -k2,2
