#!/usr/bin/env bash
# Mesh convergence of the concrete cube's continuum reference (mw-fem box, the wave test of
# pipeline/concrete-cube/study.mk: E_d, nu_d and rho from mw-upv, transducers and burst from
# lab-data/concrete-cube/experiment.toml, 1.5 ms, 0.1 us samples). For one burst frequency,
# runs every mesh and correlates each with the finest (the last one listed) and with a DEM
# record if given - over the whole record and over its first 50 us (the direct waves and their
# first reflections: the PCC window of the pipeline's early comparison).
#   bench/fem_cube_mesh.sh BIN OUT F_KHZ "MESHES_MM (coarse to fine)" [DEM_SIGNALS.h5] [DURATION_MS]
# Writes OUT/fem-F-H[-D].{h5,json} (kept: a rerun reuses them) and prints CSV:
#   f_kHz,duration_ms,mesh_mm,elements,dt_us,wall_s,threads,load,pcc_fine,env_fine,pcc_fine_50us,env_fine_50us,
#   pcc_dem,env_dem,pcc_dem_50us,env_dem_50us
set -euo pipefail
bin=$1 out=$2 f=$3 meshes=$4 dem=${5:-} duration=${6:-1.5}
suffix=$([ "$duration" = 1.5 ] || echo "-${duration}ms")
here=$(cd "$(dirname "$0")/.." && pwd)
lab=$here/lab-data/concrete-cube
mkdir -p "$out"
[ -f "$out/upv.json" ] || {
  "$bin/mw-specimen" --from "$lab/specimen.toml" --out "$out/density.json" > /dev/null
  "$bin/mw-upv" --from "$out/density.json" --from "$lab/upv.toml" --out "$out/upv.json" > /dev/null
}
for h in $meshes; do
  run=$out/fem-${f}kHz-${h}mm$suffix
  [ -f "$run.json" ] && continue
  load=$(cut -d' ' -f1 /proc/loadavg)
  "$bin/mw-fem" --from "$out/upv.json" box --experiment "$lab/experiment.toml" --mesh-mm "$h" --frequency-kHz "$f" \
    --duration-ms "$duration" --quiet --signals "$run.h5" --out "$run.json" > /dev/null
  jq --arg l "$load" '. + {load: ($l | tonumber)}' "$run.json" > "$run.tmp" && mv "$run.tmp" "$run.json"
done
fine=$out/fem-${f}kHz-$(echo "$meshes" | awk '{ print $NF }')mm$suffix.h5
pcc() {  # a b [window-end-us] -> "signal envelope" means over B-G (not the FEM's excitation record)
  "$bin/mw-pcc" --a "$1" --b "$2" --sensors B,C,D,E,F,G --resample linear ${3:+--window-end-us $3} \
    --out "$out/pcc.tmp.json" > /dev/null
  jq -r '"\(.mean_pcc_signal) \(.mean_pcc_envelope)"' "$out/pcc.tmp.json"
}
echo "f_kHz,duration_ms,mesh_mm,elements,dt_us,wall_s,threads,load,pcc_fine,env_fine,pcc_fine_50us,env_fine_50us,pcc_dem,env_dem,pcc_dem_50us,env_dem_50us"
for h in $meshes; do
  run=$out/fem-${f}kHz-${h}mm$suffix
  read -r pf ef < <(pcc "$fine" "$run.h5")
  read -r pf50 ef50 < <(pcc "$fine" "$run.h5" 50)
  pd=- ed=- pd50=- ed50=-
  if [ -n "$dem" ]; then
    read -r pd ed < <(pcc "$run.h5" "$dem")
    read -r pd50 ed50 < <(pcc "$run.h5" "$dem" 50)
  fi
  jq -r --arg f "$f" --arg d "$duration" --arg h "$h" --arg v "$pf,$ef,$pf50,$ef50,$pd,$ed,$pd50,$ed50" \
    '"\($f),\($d),\($h),\(.elements),\(.dt_us),\(.wall_s),\(.threads),\(.load),\($v)"' "$run.json"
done
rm -f "$out/pcc.tmp.json"
