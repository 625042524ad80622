#!/usr/bin/env bash
# What the explicit EFG costs (issue 16, Must show 4): `mw-efg wave` on the 1 m roller strip (40 mm
# wide, plane strain concrete, a 40/40 us triangular pulse, sensors at 0.2 and 0.8 m) at several node
# spacings and thread counts, each run REPS times. Prints per run the nodes, Gauss points, steps, the
# tool's own wall time of the stepping and of the set-up (MLS, mass, Lanczos stable step), the wall
# per step, the peak speed error against c_p and the energy drift; the histories of the thread counts
# are compared with cmp (the same bits).
#
#   bench/efg/wave.sh OUTDIR ["spacings in mm"] ["thread counts"] [reps]
set -euo pipefail
out=${1:?output directory}
spacings=${2:-"10 5 2.5"}
threads=${3:-"1 2"}
reps=${4:-3}
bin=${BIN:-build/bin}
mkdir -p "$out"
echo "# $(uname -m) $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%FT%TZ)"
echo "spacing_mm,threads,nodes,gauss_points,steps,setup_s,wall_s,wall_per_step_ms,peak_speed_error,energy_drift"
for s in $spacings; do
  for t in $threads; do
    for ((k = 0; k < reps; k++)); do
      "$bin/mw-efg" wave --length-mm 1000 --rise-us 40 --fall-us 40 --sensor-mm 200 --sensor-mm 800 --spacing-mm "$s" \
        --threads "$t" --history "$out/h-$s-$t.csv" --out "$out/w.json" > /dev/null
      jq -r --arg s "$s" --arg t "$t" '[$s, $t, .nodes, .gauss_points, .steps, .setup_s, .wall_s, .wall_per_step_us / 1000,
        .peak_speed_error, .energy_drift] | @csv' "$out/w.json" | tr -d '"'
    done
  done
  first=$(echo $threads | cut -d' ' -f1)
  for t in $threads; do cmp -s "$out/h-$s-$first.csv" "$out/h-$s-$t.csv" || echo "# spacing $s: threads $t differ from $first"; done
done
rm -f "$out/w.json"
