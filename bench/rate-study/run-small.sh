#!/bin/bash
# The loading-rate study of the compression test's peak (issue 19 item 2; docs/calibration.md,
# "The loading rate of the failure trials"): cubes of SIDE mm packed as the pipeline packs its
# 50 mm cube (mw-pack box, p = 7 %, d = 1.6-2.0 mm) with each of SEEDS, each loaded by the shipped
# scene at each of RATES [mm/s], one thread, one run at a time. Every run is recorded in db/.
# Material: the calibrated parameters of the 2026-12-01 make reproduce (docs/calibration.md).
#   SIDE=30 SEEDS="1 2" RATES="5 2.5 10" bench/rate-study/run-small.sh && bench/rate-study/table.py
set -u
cd "$(dirname "$0")/../.."
export MESOWAVE_DB=${MESOWAVE_DB:-$PWD/db/provenance.sqlite}
B=${B:-build/bin}; SIDE=${SIDE:-30}; D=results/rate-study/${SIDE}mm; mkdir -p $D
MAT="--E-dem-GPa 26.92 --nu-dem 0.2960 --T-MPa 33.77 --C-MPa 33.77"
for seed in ${SEEDS:-1 2 3 4}; do
  P=$D/packing-s$seed.h5
  [ -f $P ] || $B/mw-pack box --cube-side-mm $SIDE --porosity-pct 7 --d-min-mm 1.6 --d-max-mm 2 \
      --density-kg-m3 2129.56 --seed $seed --threads 1 --quiet --packing $P --out $D/packing-s$seed.json > /dev/null
  for v in ${RATES:-25 10 5 2.5}; do
    S=$D/s$seed-v$v
    [ -f $S.json ] && continue
    t0=$(date +%s.%N)
    $B/mw-dem run pipeline/concrete-cube/scenes/cube-compression.toml --packing $P $MAT --velocity-mm-s $v \
      --threads 1 --quiet --signals $S.h5 --curves $S.csv --summary $S.json > $S.log 2>&1
    rc=$?; t1=$(date +%s.%N)
    echo "side $SIDE seed $seed v $v rc $rc wall $(echo "$t1 - $t0" | bc) load $(cut -d' ' -f1 /proc/loadavg)" >> $D/runs.log
  done
done
