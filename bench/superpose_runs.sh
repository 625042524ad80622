#!/usr/bin/env bash
# One run, every frequency (docs/benchmarks.md, "One run, every frequency"): the cube-wave scene
# (the paper's Table 2 parameters as the scene file has them, alpha_d 0.01, dt 50 ns) superposed
# from one impulse run against direct runs, with the paper's local damping and with
# damping_law viscous, on the quick tree's 20 mm cube (0.3 and 1.5 ms) and the 50 mm cube.
# The records (--summary) hold every number: superposition.checks (PCC, max |diff| / peak per
# sensor, the direct runs' wall), impulse_wall_s, frequencies[].convolution_s. mw-pcc compares
# the two damping laws' direct signals (the modelling change).
#
#   bench/superpose_runs.sh [build-dir] [out-dir]      (packings: make results-quick/concrete-cube/packing.h5
#                                                        results/concrete-cube/packing.h5)
set -euo pipefail
B=${1:-build}/bin
O=${2:-results/bench/superpose}
S=pipeline/concrete-cube/scenes/cube-wave.toml
mkdir -p "$O"
note() { echo "# $(date -u +%FT%TZ) load $(cut -d' ' -f1-3 /proc/loadavg): $*"; }
quick=results-quick/concrete-cube/packing.h5
full=results/concrete-cube/packing.h5
all=100,150,200,250,300,350,400,450,500
for rec in 0.3 1.5; do
  for law in local viscous; do
    note "20 mm cube, $rec ms, $law: superposed 100,300,500 with direct checks"
    /usr/bin/time -f "%e s wall" "$B/mw-dem" run $S --packing $quick --duration-ms $rec --damping-law $law \
      --frequencies-kHz 100,300,500 --check-kHz 100,300,500 --signals-pattern "$O/q-sup-$law-$rec-{f}kHz.h5" \
      --summary "$O/q-sup-$law-$rec.json" --quiet > /dev/null
    for f in 100 300 500; do
      "$B/mw-dem" run $S --packing $quick --duration-ms $rec --damping-law $law --frequency-kHz $f \
        --signals "$O/q-dir-$law-$rec-${f}kHz.h5" --quiet > /dev/null
    done
  done
  for f in 100 300 500; do
    "$B/mw-pcc" "$O/q-dir-local-$rec-${f}kHz.h5" "$O/q-dir-viscous-$rec-${f}kHz.h5" --out "$O/q-pcc-laws-$rec-${f}kHz.json" > /dev/null
  done
done
note "50 mm cube, local: superposed, all nine checked directly"
/usr/bin/time -f "%e s wall" "$B/mw-dem" run $S --packing $full --frequencies-kHz $all --check-kHz $all \
  --signals-pattern "$O/c-sup-local-{f}kHz.h5" --summary "$O/c-sup-local.json" --quiet > /dev/null
note "50 mm cube, viscous: superposed, 100, 200 and 500 checked directly (200: the bound does not prove the linear model there)"
/usr/bin/time -f "%e s wall" "$B/mw-dem" run $S --packing $full --damping-law viscous --frequencies-kHz $all \
  --check-kHz 100,200,500 --signals-pattern "$O/c-sup-viscous-{f}kHz.h5" --summary "$O/c-sup-viscous.json" --quiet > /dev/null
for f in 100 300 500; do
  note "50 mm cube, local, direct $f kHz"
  "$B/mw-dem" run $S --packing $full --frequency-kHz $f --signals "$O/c-dir-local-${f}kHz.h5" --quiet > /dev/null
  "$B/mw-pcc" "$O/c-dir-local-${f}kHz.h5" "$O/c-sup-viscous-${f}kHz.h5" --out "$O/c-pcc-laws-${f}kHz.json" > /dev/null
done
note done
