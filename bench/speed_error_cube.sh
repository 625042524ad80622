#!/usr/bin/env bash
# Speed against error at full scale (issue 17, item 6; docs/benchmarks.md "The DEM cube: speed
# against error"): the concrete paper's 50 mm cube wave test (pipeline/concrete-cube/scenes/
# cube-wave.toml, one burst frequency) with every cost knob a user has:
#  - the particle size: d_max 2.0, 1.5, 1.0 mm (d_min = 0.8 d_max, as the paper's 1.6-2.0 mm;
#    porosity 7 %, C_f 1.1); the calibrated micro-parameters are taken unchanged (the bonds' E_dem
#    is a modulus: the packing's E_glob does not depend on the sphere size at a fixed packing
#    structure, docs/calibration.md "Transfer across size");
#  - the time step as a fraction of the run's own stable limit (dt_limit_s of its summary):
#    DT_FRACTIONS, by default 0.1 0.2 0.4 0.8;
#  - the full contact law or the linearised network;
#  - threads (1 and 2 for the paper's size at the scene's step).
# Every run is compared with the most exact one - the smallest spheres, the full law, the smallest
# step - by mw-pcc: the mean PCC over sensors B-G, the mean arrival shift (first crossing of 2 % of
# each record's peak) and the mean peak-amplitude error, on the reference's samples (linear
# resampling). One row a run in OUT/speed-error.csv with the Pareto front of wall time against
# PCC (mw-table gather --pareto), and OUT/speed-error.png. Single precision is not a knob: mw-dem
# computes in double only.
#
#   bench/speed_error_cube.sh OUT_DIR CALIBRATION.json [PACKING_2MM.h5]
#   D_MAX_MM="2.0 1.5 1.0" DT_FRACTIONS="0.1 0.2 0.4 0.8" FREQUENCY_KHZ=250 DURATION_MS=0.3 BIN=build/bin
# One quiet core: 29 min with DURATION_MS=0.1 (2026-12-05, docs/benchmarks.md), so about 1.5 h for
# the defaults (the 1.0 mm cube: 300,816 spheres, 59 ms a full-law step), plus 7 min of packing.
set -euo pipefail
out=${1:?OUT_DIR}; material=${2:?CALIBRATION.json}; given_packing=${3:-}
BIN=${BIN:-build/bin}
D_MAX_MM=${D_MAX_MM:-2.0 1.5 1.0}
DT_FRACTIONS=${DT_FRACTIONS:-0.1 0.2 0.4 0.8}
FREQUENCY_KHZ=${FREQUENCY_KHZ:-250}
DURATION_MS=${DURATION_MS:-0.3}
SCENE=pipeline/concrete-cube/scenes/cube-wave.toml
mkdir -p "$out"
export MESOWAVE_DB=${MESOWAVE_DB:-$out/provenance.sqlite}
load() { cut -d' ' -f1 /proc/loadavg; }
log() { echo "# $(date -u +%T) load $(load): $*" >&2; }
json() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))$2)" "$1"; }
echo "# machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $(date -u +%FT%TZ)" >&2

run_dem() {  # name packing model dt_ns threads
  local name=$1 packing=$2 model=$3 dt_ns=$4 threads=$5
  log "mw-dem $name (dt $dt_ns ns, $model, $threads threads)"
  "$BIN/mw-dem" --from "$material" run "$SCENE" --packing "$packing" --frequency-kHz "$FREQUENCY_KHZ" \
    --duration-ms "$DURATION_MS" --model "$model" --dt-ns "$dt_ns" --threads "$threads" --quiet \
    --signals "$out/$name.h5" --summary "$out/$name.json" > /dev/null
}

runs=()
finest=
for d in $D_MAX_MM; do
  packing=$out/packing-d${d}mm.h5
  if [ "$d" = "2.0" ] && [ -n "$given_packing" ]; then
    packing=$given_packing
  elif [ ! -e "$packing" ]; then
    d_min=$(python3 -c "print(0.8 * $d)")
    log "mw-pack box --d-max-mm $d --d-min-mm $d_min"
    "$BIN/mw-pack" box --threads 1 --cube-side-mm 50 --porosity-pct 7 --d-min-mm "$d_min" --d-max-mm "$d" \
      --density-kg-m3 2129.56 --detection-factor 1.1 --quiet --packing "$packing" --out "${packing%.h5}.json" > /dev/null
  fi
  # The stable limit of this packing: a run of one step (the setup computes it).
  "$BIN/mw-dem" --from "$material" run "$SCENE" --packing "$packing" --frequency-kHz "$FREQUENCY_KHZ" \
    --duration-ms 0.00001 --model linear --threads 1 --quiet --signals "$out/limit-d$d.h5" --summary "$out/limit-d$d.json" > /dev/null
  limit_s=$(json "$out/limit-d$d.json" "['dt_limit_s']")
  for f in $DT_FRACTIONS; do
    dt_ns=$(python3 -c "print(f'{$f * $limit_s * 1e9:.4g}')")
    for model in linear full; do
      name=d${d}-${model}-dt${f}-1t
      run_dem "$name" "$packing" "$model" "$dt_ns" 1
      runs+=("$name")
    done
  done
  finest=$d
done
# Threads: the same bits (tested), so only the cost; one pair at the paper's size and the smallest fraction.
first_d=${D_MAX_MM%% *}; first_f=${DT_FRACTIONS%% *}
first_packing=$out/packing-d${first_d}mm.h5
[ "$first_d" = "2.0" ] && [ -n "$given_packing" ] && first_packing=$given_packing
dt_ns=$(python3 -c "print(f'{$first_f * $(json "$out/limit-d$first_d.json" "['dt_limit_s']") * 1e9:.4g}')")
run_dem "d${first_d}-full-dt${first_f}-2t" "$first_packing" full "$dt_ns" 2
runs+=("d${first_d}-full-dt${first_f}-2t")

reference=d${finest}-full-dt${first_f}-1t
rows=()
for r in "${runs[@]}"; do
  "$BIN/mw-pcc" --a "$out/$reference.h5" --b "$out/$r.h5" --resample linear --pad double --arrival-relative 0.02 \
    --out "$out/pcc-$r.json" > /dev/null
  rows+=(--row "$r=$out/pcc-$r.json,$out/$r.json")
done
"$BIN/mw-table" gather --key-name run "${rows[@]}" --column spheres --column model --column dt_s \
  --column dt_limit_s --column threads --column steps --column wall_s --column pcc=mean_pcc_signal \
  --column pcc_envelope=mean_pcc_envelope --column arrival_error_us=mean_abs_arrival_shift_us \
  --column peak_amplitude_error=mean_abs_peak_error --pareto min:wall_s,max:pcc --csv "$out/speed-error.csv"
"$BIN/mw-table" plot "$out/speed-error.csv" --x wall_s --y pcc --label-column run --log-x --log-y --one-minus \
  --x-label "wall time of the run [s]" --y-label "1 - mean PCC over B-G against $reference" \
  --title "Concrete cube, $FREQUENCY_KHZ kHz: speed against error (sphere size, time step, model, threads)" \
  --out "$out/speed-error.png" > /dev/null
echo "reference: $reference; table $out/speed-error.csv, figure $out/speed-error.png" >&2
