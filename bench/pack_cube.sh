#!/usr/bin/env bash
# Packing benchmark: mw-pack on the concrete paper's 50 mm cube (p = 7 %,
# d uniform 1.6-2.0 mm), several seeds at 1 and 2 OpenMP threads. Prints one
# markdown row per run and the medians; results go to docs/benchmarks.md
# ("Packing"). Yade 2023.02a took about 10 minutes for this cube.
#
#   bench/pack_cube.sh [BIN_DIR] [SEEDS]      e.g. bench/pack_cube.sh build/bin "1 2 3"
set -euo pipefail
bin=${1:-build/bin}
seeds=${2:-"1 2 3"}
threads_list=${THREADS:-"1 2"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| threads | seed | spheres | iterations | wall s | CPU s | peak RSS MB | bonds (C_f 1.1) | coordination | overlap mean/max | load |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
declare -A walls
for threads in $threads_list; do
  for seed in $seeds; do
    /usr/bin/time -f "%e %U %S %M" -o "$work/time" \
      "$bin/mw-pack" box --threads "$threads" --cube-side-mm 50 --porosity-pct 7 --d-min-mm 1.6 --d-max-mm 2 \
      --seed "$seed" --quiet --packing "$work/cube.h5" > "$work/summary.json"
    read -r wall user sys rss < "$work/time"
    python3 - "$work/summary.json" "$threads" "$seed" "$wall" "$user" "$sys" "$rss" "$(cut -d' ' -f1 /proc/loadavg)" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
threads, seed, wall, user, sysc, rss, load = sys.argv[2:]
print(f"| {threads} | {seed} | {s['spheres']} | {s['relaxation_iterations']} | {float(wall):.1f} | "
      f"{float(user) + float(sysc):.1f} | {int(rss) / 1024:.0f} | {s['bonds']} | {s['coordination']:.3f} | "
      f"{s['overlap_mean_ratio']:.3f}/{s['overlap_max_ratio']:.3f} | {load} |")
PY
    walls[$threads]+="$wall "
  done
done
echo
for threads in $threads_list; do
  median=$(printf '%s\n' ${walls[$threads]} | sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}')
  echo "median wall time, $threads thread(s): $median s"
done
