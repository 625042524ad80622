#!/usr/bin/env bash
# Speed against error of the continuum reference for the steel rod (rod paper
# Section 4.3.1): mw-fem at several meshes, bursts at 50-150 kHz in 10 kHz steps,
# group velocity by the rod paper's peak-to-peak (echo) method at the far-end
# sensor, RSS against Pochhammer-Chree over the sweep's band (rod Table 2). The rod, its
# steel, the burst and the record are lab-data/steel-rod/experiment.toml's (--experiment); the
# load is the paper's concentrated force (--patch-radius-mm 0), as in pipeline/steel-rod/study.mk.
#
#   THREADS=1 bench/fem_rod.sh OUTDIR "axisymmetric:2 axisymmetric:1 axisymmetric:0.5 3d:2 3d:1" [duration_ms] [freqs]
# (duration_ms: default the experiment's record)
#
# Writes OUTDIR/<model>-<mesh>/ (signals, reports) and appends one row per model
# and mesh to OUTDIR/fem_rod.csv: model, mesh_mm, elements, dt_us, steps,
# wall_s (median over the frequencies), steps_per_s, element_updates_per_s,
# peak_rss_MiB, threads, rss_m2_s2, rms_m_s. THREADS (default 1) is mw-fem's --threads:
# the thread policy (core/threads.hpp) takes no OMP_NUM_THREADS.
set -euo pipefail
out=${1:?output directory}
cases=${2:-"axisymmetric:2 axisymmetric:1 axisymmetric:0.5 3d:2 3d:1"}
duration=${3:-}
freqs=${4:-"50 60 70 80 90 100 110 120 130 140 150"}
bin=${BIN:-build/bin}
threads=${THREADS:-1}
rod=(--experiment lab-data/steel-rod/experiment.toml)
band="${freqs%% *},${freqs##* }"
mkdir -p "$out"
[ -f "$out/fem_rod.csv" ] || echo "model,mesh_mm,elements,dt_us,steps,wall_s,steps_per_s,element_updates_per_s,peak_rss_MiB,threads,rss_m2_s2,rms_m_s" > "$out/fem_rod.csv"
for c in $cases; do
  model=${c%%:*}; mesh=${c##*:}
  dir="$out/$model-$mesh"; mkdir -p "$dir"
  runs=()
  for f in $freqs; do
    "$bin/mw-fem" rod "${rod[@]}" --patch-radius-mm 0 --model "$model" --mesh-mm "$mesh" --frequency-kHz "$f" \
      --alpha-damping 2000 ${duration:+--duration-ms "$duration"} --sample-dt-us 0.2 --threads "$threads" --signals "$dir/s$f.h5" \
      --out "$dir/r$f.json" > /dev/null 2>&1
    runs+=(--run "$dir/s$f.h5")
  done
  "$bin/mw-dispersion" measure "${runs[@]}" --method echo "${rod[@]}" --band-kHz "$band" \
    --csv "$dir/measure.csv" --out "$dir/measure.json" > /dev/null
  wall=$(jq -s 'map(.wall_s) | sort | .[length/2|floor]' "$dir"/r*.json)
  first=$(ls "$dir"/r*.json | head -1)
  jq -r --arg m "$model" --arg h "$mesh" --argjson w "$wall" --slurpfile ms "$dir/measure.json" \
    '[$m, $h, .elements, .dt_us, .steps, $w, (.steps / $w), (.steps * .elements / $w), .peak_rss_MiB, .threads,
      $ms[0].rss_m2_s2, $ms[0].rms_m_s] | @csv' "$first" | tr -d '"' >> "$out/fem_rod.csv"
  tail -1 "$out/fem_rod.csv"
done
