#!/usr/bin/env bash
# Two builds' DEM step timed against each other on a shared machine (docs/benchmarks.md, "The step
# near the memory limit"): bench_dem of build A and of build B alternated in one script, benchmark
# by benchmark, so that both see the same load; the 1-minute load average is
# printed before each run.
# The order alternates from round to round (A B, then B A), so that a drift of the machine within a
# pair favours neither; at the end, per benchmark and build the medians over the rounds, and per
# benchmark the median of the rounds' ratios B/A with its quartiles: the figure to quote. (The
# host's memory speed can drift by 2x within minutes: rounds far apart in time compare badly, and
# a few rounds can show a steady gain that is not there - docs/benchmarks.md, "The step near the
# memory limit", fifth part. For a switch the step reads at run time, A against B in one process
# is better still.)
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
# Alternated per benchmark (A and B on one benchmark, then the next), so that a pair sees the same load.
names=$("$A" --benchmark_list_tests=true --benchmark_filter="$FILTER" 2>/dev/null)
for round in $(seq 1 "$ROUNDS"); do
  for name in $names; do
    order="A B"
    [ $((round % 2)) = 0 ] && order="B A"
    for side in $order; do
      bin=$A
      [ "$side" = B ] && bin=$B
      echo "# round $round $side load $(cut -d' ' -f1 /proc/loadavg)"
      line=$("$bin" --benchmark_filter="^$name\$" --benchmark_min_time="$MIN_TIME" 2>/dev/null | grep '^BM_')
      echo "$side $round $line"
      # For the summary: "NAME-wall ROUND SIDE ms" and "NAME-cpu ROUND SIDE ms".
      echo "$line" | awk -v r="$round" -v s="$side" \
        '{ n = $1; sub("/min_time.*", "", n); print n "-wall", r, s, $2; print n "-cpu", r, s, $4 }' >> "$out"
    done
  done
done
# Per benchmark: the medians of the wall and CPU ms per build, and the median of the ratios B/A.
python3 "$(dirname "$0")/paired_ratios.py" "$out" B A --unit ms
