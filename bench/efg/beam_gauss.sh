#!/usr/bin/env bash
# The peak load of the Koermeling-Reinhardt beam against the Gauss points per cell (issue 15, Must show 4;
# the shock paper's Fig. 4 says the EFG result depends on that number): `mw-efg bending --from the lab-data
# file --ligament-interface` for each grid, each n x n rule and both laws, up to the peak and past it in
# equal steps (the peak is the largest curve point: resolution one step), one thread.
#
#   bench/efg/beam_gauss.sh OUTDIR ["spacings mm"] ["gauss"] [max deflection mm] [steps]
#
# Writes OUTDIR/peaks.csv: spacing_mm, gauss, law, nodes, gauss_points, peak_load_N, deflection_at_peak_mm,
# elastic_stiffness_N_per_mm, newton_iterations, wall_s (the tool's own), process_s, peak_rss_MiB.
set -euo pipefail
out=${1:?output directory}
spacings=${2:-"10 5"}
rules=${3:-"2 3 4"}
max=${4:-0.25}
steps=${5:-50}
bin=${BIN:-build/bin}
lab=lab-data/shock-concrete/three-point-bending.toml
mkdir -p "$out"
echo "# $(uname -m) $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%FT%TZ)"
echo "spacing_mm,gauss,law,nodes,gauss_points,peak_load_N,deflection_at_peak_mm,elastic_stiffness_N_per_mm,newton_iterations,wall_s,process_s,peak_rss_MiB" > "$out/peaks.csv"
for h in $spacings; do
  for g in $rules; do
    for law in exponential bilinear; do
      t0=$(date +%s.%N)
      /usr/bin/time -f "%M" -o "$out/rss" "$bin/mw-efg" bending --from "$lab" --law "$law" --spacing-mm "$h" \
        --gauss "$g" --ligament-interface --max-deflection-mm "$max" --steps "$steps" --fem-refinement 0 \
        --threads 1 --out "$out/r.json" > /dev/null
      t1=$(date +%s.%N)
      python3 - "$out/r.json" "$h" "$g" "$law" "$(echo "$t1 - $t0" | bc)" "$(cat "$out/rss")" >> "$out/peaks.csv" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); c = j["cost"]
print(",".join(str(x) for x in [sys.argv[2], sys.argv[3], sys.argv[4], c["nodes"], c["gauss_points"],
      round(j["peak_load_N"], 1), j["deflection_at_peak_mm"], round(j["elastic_stiffness"]["efg_N_per_mm"], 1),
      c["newton_iterations"], round(c["wall_s"], 2), sys.argv[5], int(sys.argv[6]) // 1024]))
PY
      tail -1 "$out/peaks.csv"
    done
  done
done
rm -f "$out/r.json" "$out/rss"
