#!/bin/bash
# The calibrated 50 mm cube at the paper's 2.5 mm/s (issue 19 item 2; docs/calibration.md, "The
# loading rate of the failure trials"): the pipeline's packing and calibration.json, the shipped
# compression scene at --velocity-mm-s 2.5, one thread.
#   STAGE=a  the calibrated T = C; keeps the last intact state (--intact-checkpoint)
#   STAGE=b  T = C rescaled by sigma_max / peak(a), as mw-calibrate's first failure step does
#            (calibration.cpp, next_failure: T <- T sigma_max / peak), started from a's intact state
#   STAGE=c  the secant through a and b (next_failure's second step), from b's intact state when
#            T_c >= T_b, else from a's when T_c >= T_a
# Every run is recorded in db/provenance.sqlite; R=results/rate-study/50mm.
set -u
cd "$(dirname "$0")/../.."
export MESOWAVE_DB=${MESOWAVE_DB:-$PWD/db/provenance.sqlite}
B=${B:-build/bin}; R=results/rate-study/50mm; mkdir -p $R
CAL=results/concrete-cube/calibration.json
SIGMA=$(python3 -c "import json; print(repr(json.load(open('$CAL'))['sigma_max_target_MPa']))")
field() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(repr(eval(sys.argv[2], {}, d)))" "$@"; }
T_A=$(field $CAL "T_MPa")
case ${STAGE:?STAGE=a, b or c} in
  a) T=$T_A; EXTRA="" ;;
  b) T=$(python3 -c "print(repr($T_A * $SIGMA / $(field $R/a.json "test['peak_stress_MPa']")))")
     EXTRA="--restart-stronger $R/a.intact.h5" ;;
  c) T=$(python3 -c "
ta, sa, tb, sb, s = $T_A, $(field $R/a.json "test['peak_stress_MPa']"), $(field $R/b.json "material['T_Pa'] / 1e6"), $(field $R/b.json "test['peak_stress_MPa']"), $SIGMA
print(repr(tb + (s - sb) * (tb - ta) / (sb - sa)))")
     EXTRA=$(python3 -c "print('--restart-stronger $R/b.intact.h5' if $T >= $(field $R/b.json "material['T_Pa'] / 1e6") else '--restart-stronger $R/a.intact.h5' if $T >= $T_A else '')") ;;
esac
S=$R/$STAGE
echo "stage $STAGE T = C = $T MPa (target $SIGMA MPa) $EXTRA" | tee $S.params
uptime > $S.uptime
/usr/bin/time -v $B/mw-dem --from $CAL run pipeline/concrete-cube/scenes/cube-compression.toml \
  --packing results/concrete-cube/packing.h5 --velocity-mm-s 2.5 --T-MPa $T --C-MPa $T --threads 1 --quiet \
  --intact-checkpoint $S.intact.h5 $EXTRA --signals $S.h5 --curves $S.csv --summary $S.json > $S.log 2> $S.time
echo "rc $?" >> $S.params; uptime >> $S.uptime
