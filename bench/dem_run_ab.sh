#!/usr/bin/env bash
# Whole cube-wave runs of two mw-dem builds alternated (docs/benchmarks.md, "The step near the
# memory limit"), the order alternating from round to round (A B, then B A: a drift of the machine
# within a round favours neither), with the 1-minute load average before each; prints each run's
# wall (the step loop's, from the run record), setup and process time, and whether its signals
# are byte-identical to the first run's; at the end the medians and the median of the rounds'
# ratios B/A (bench/paired_ratios.py).
#
#   bench/dem_run_ab.sh OLD/bin/mw-dem NEW/bin/mw-dem packing.h5 [rounds] [model] [threads]
set -euo pipefail
A=$1
B=$2
PACKING=$3
ROUNDS=${4:-2}
MODEL=${5:-linear}
THREADS=${6:-2}
SCENE=pipeline/concrete-cube/scenes/cube-wave.toml
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
: > "$tmp/rows"
echo "# $(date -u +%FT%TZ) A=$A B=$B $SCENE --model $MODEL --threads $THREADS --frequency-kHz 100 (30,000 steps)"
for round in $(seq 1 "$ROUNDS"); do
  order="A B"
  [ $((round % 2)) = 0 ] && order="B A"
  for side in $order; do
    bin=$A
    [ "$side" = B ] && bin=$B
    load=$(cut -d' ' -f1 /proc/loadavg)
    start=$(date +%s.%N)
    "$bin" run $SCENE --packing "$PACKING" --model "$MODEL" --threads "$THREADS" --frequency-kHz 100 \
      --signals "$tmp/$side-$round.h5" --quiet > "$tmp/$side-$round.json"
    end=$(date +%s.%N)
    same=identical
    [ -e "$tmp/first.h5" ] || cp "$tmp/$side-$round.h5" "$tmp/first.h5"
    cmp -s "$tmp/first.h5" "$tmp/$side-$round.h5" || same=DIFFERENT
    # The run's line, and its rows for the summary ("loop-wall|process ROUND SIDE s").
    python3 -c "
import json, sys
d, process = json.load(open(sys.argv[1])), $end - $start
print('$side round $round load $load: steps', d['steps'], 'threads', d['threads'],
      'loop wall %.2f s, setup %.2f s, process %.2f s, signals $same' % (d['wall_s'], d['setup_s'], process))
with open(sys.argv[2], 'a') as rows:
    print('loop-wall $round $side', d['wall_s'], file=rows)
    print('process $round $side', process, file=rows)" "$tmp/$side-$round.json" "$tmp/rows"
  done
done
python3 "$(dirname "$0")/paired_ratios.py" "$tmp/rows" B A --unit s
