#!/bin/bash
# The size transfer of the calibrated micro-parameters (issue 18 item 1; docs/calibration.md,
# "Transfer across size"): cubes of each of SIDES mm packed as step 5 packs the 50 mm one (mw-pack box
# with the --from files of step-5-packing.mk and cube-150.mk, --cube-side-mm S), then E_glob and
# nu_glob of each by the calibration's elastic trial as a static solve (mw-dem run --static on the
# linearised network with unbreakable bonds, loaded to 1/3 of the target strength, the secant between
# 10 % and 1/3 of it: calibration_report.cpp, compression_trial_options) with the material of
# results/concrete-cube/calibration.json. The scene's wall and extensometers are placed by fractions
# of the packing's extent, so the shipped compression scene fits every size. One thread, one run at a time.
# The solve's preconditioner PC: amg (hypre's BoomerAMG, 3.6-3.8x Jacobi's speed at 75 mm; the same
# E_glob and nu_glob to 1e-9: docs/calibration.md) unless given; the runs of 2026-12-04 used jacobi.
#   SIDES="75 100" bench/size-transfer/run.sh     (50: the pipeline's own packing; PC=jacobi for those runs' solver)
set -u
cd "$(dirname "$0")/../.."
export MESOWAVE_DB=${MESOWAVE_DB:-$PWD/db/provenance.sqlite}
B=${B:-build/bin}; R=results/size-transfer; mkdir -p $R
PC=${PC:-amg}
L=lab-data/concrete-cube; CAL=results/concrete-cube/calibration.json
LEVELS=$(python3 -c "import json; s = json.load(open('$CAL'))['sigma_max_target_MPa']; print(repr(0.1 * s) + ',' + repr(s / 3), repr(1.02 * (s / 3)))")
for side in ${SIDES:-75 100}; do
  if [ $side = 50 ]; then P=results/concrete-cube/packing.h5; else
    P=$R/packing-$side.h5
    if [ ! -f $P ]; then
      uptime > $R/pack-$side.uptime
      /usr/bin/time -v $B/mw-pack box --from $L/porosity.toml --from $L/dem-packing.toml --from results/concrete-cube/density.json \
        --cube-side-mm $side --threads 1 --quiet --packing $P --out $R/packing-$side.json > /dev/null 2> $R/pack-$side.time
      uptime >> $R/pack-$side.uptime
    fi
  fi
  S=$R/static-$side
  [ -f $S.json ] && continue
  uptime > $S.uptime
  /usr/bin/time -v $B/mw-dem --from $CAL run pipeline/concrete-cube/scenes/cube-compression.toml --packing $P \
    --unbreakable-bonds --model linear --modulus-levels-MPa ${LEVELS% *} --stop-at-MPa ${LEVELS#* } --static --static-preconditioner $PC \
    --threads 1 --quiet --signals $S.h5 --curves $S.csv --summary $S.json > $S.log 2> $S.time
  uptime >> $S.uptime
done
