#!/usr/bin/env bash
# What the EFG costs against the Q4 FEM (issue 15, Must show 4; the shock paper's Fig. 6 question):
# the same elastic problem - Timoshenko & Goodier's cantilever, L = 48, D = 12, t = 1, E = 3e7,
# nu = 0.3, P = 1000 (Belytschko, Lu & Gu 1994), mw-efg cantilever's defaults - solved by
# `mw-efg cantilever --method efg|fem` at several node spacings, each run REPS times (one thread).
#
#   bench/efg/cantilever.sh OUTDIR ["efg spacings"] ["fem spacings"] [reps]
#
# Writes OUTDIR/runs.csv (every run: method, spacing, nodes, Gauss points, errors, the tool's own
# time of the solution - not of the error measurement -, the process's wall time and peak RSS) and
# prints the medians per method and spacing and the EFG/FEM ratios (bench/efg/ratios.py): at equal node count (the same
# spacing) and at equal displacement error (the FEM's wall time and memory interpolated, log-log,
# to the EFG's error).
set -euo pipefail
out=${1:?output directory}
efg_spacings=${2:-"4 2 1 0.5 0.25"}
fem_spacings=${3:-"4 2 1 0.5 0.25 0.125 0.0625"}
reps=${4:-5}
bin=${BIN:-build/bin}
mkdir -p "$out"
echo "method,spacing_m,nodes,gauss_points,displacement_error_L2,energy_error,solution_s,process_s,peak_rss_MiB" > "$out/runs.csv"
echo "# $(uname -m) $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%FT%TZ)"
for method in efg fem; do
  spacings=$efg_spacings; [ "$method" = fem ] && spacings=$fem_spacings
  for s in $spacings; do
    for ((k = 0; k < reps; k++)); do
      t0=$(date +%s.%N)
      /usr/bin/time -f "%M" -o "$out/rss" "$bin/mw-efg" cantilever --threads 1 --method "$method" --spacing-m "$s" \
        --out "$out/r.json" > /dev/null
      t1=$(date +%s.%N)
      jq -r --arg m "$method" --arg s "$s" --arg p "$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')" --arg rss "$(cat "$out/rss")" \
        '.runs[0] | [$m, $s, .nodes, .gauss_points, .displacement_error_L2, .energy_error, .wall_s, ($p | tonumber),
         (($rss | tonumber) / 1024)] | @csv' "$out/r.json" | tr -d '"' >> "$out/runs.csv"
    done
  done
done
rm -f "$out/r.json" "$out/rss"
/usr/bin/python3 "$(dirname "$0")/ratios.py" "$out/runs.csv"
