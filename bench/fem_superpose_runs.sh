#!/usr/bin/env bash
# One FEM run per mesh, every frequency (docs/benchmarks.md, "One run, every frequency", the FEM):
# mw-fem box --frequencies-kHz (fem/superposition.hpp) against one direct --frequency-kHz run per
# frequency, on the concrete cube of the pipeline (experiment.toml, the moduli of upv.json).
#  - whole records at 1 mm: the superposed run (--check-kHz: the direct runs inside it, their
#    PCC and max |diff| / peak in the JSON's superposition.checks), then each direct run alone;
#  - early references (55 us): each frequency on its own mesh h = 156.25 mm / f (waves.mk before
#    one run per mesh) against all of them from one run on the highest frequency's mesh, compared
#    by mw-pcc over the first 50 us (what Table 3's early column does with the DEM).
# /usr/bin/time gives each run's wall and CPU seconds (CPU: the robust figure on a loaded machine).
#
#   bench/fem_superpose_runs.sh [build-dir] [out-dir] [side-mm] [frequencies]
#     (upv.json: make results/concrete-cube/upv.json; the quick tree: side 20, frequencies 100,300,500)
set -euo pipefail
B=${1:-build}/bin
O=${2:-results/bench/fem-superpose}
SIDE=${3:-20}
FREQS=${4:-100,300,500}
mkdir -p "$O"
note() { echo "# $(date -u +%FT%TZ) load $(cut -d' ' -f1-3 /proc/loadavg): $*"; }
timed() { /usr/bin/time -f "%e s wall, %U s user, %S s sys, %M KiB peak" "$@"; }
FEM=("$B/mw-fem" --from results/concrete-cube/upv.json box --experiment lab-data/concrete-cube/experiment.toml
     --size-mm "$SIDE" --quiet)
last=$(tr ',' '\n' <<< "$FREQS" | sort -g | tail -1)
h_last=$(awk -v f="$last" 'BEGIN { printf "%.6g", 156.25 / f }')

note "whole record, 1 mm, 0.3 ms: superposed $FREQS, each checked by a direct run"
timed "${FEM[@]}" --mesh-mm 1 --duration-ms 0.3 --frequencies-kHz "$FREQS" --check-kHz "$FREQS" \
  --signals-pattern "$O/whole-sup-{f}kHz.h5" --out "$O/whole-sup-checked.json" > /dev/null
note "whole record, 1 mm, 0.3 ms: superposed $FREQS alone"
timed "${FEM[@]}" --mesh-mm 1 --duration-ms 0.3 --frequencies-kHz "$FREQS" \
  --signals-pattern "$O/whole-sup-{f}kHz.h5" --out "$O/whole-sup.json" > /dev/null
for f in ${FREQS//,/ }; do
  note "whole record, 1 mm, 0.3 ms: direct $f kHz"
  timed "${FEM[@]}" --mesh-mm 1 --duration-ms 0.3 --frequency-kHz "$f" --signals "$O/whole-dir-${f}kHz.h5" \
    --out "$O/whole-dir-${f}kHz.json" > /dev/null
done
note "early, 55 us: superposed $FREQS on the $last kHz mesh, h = $h_last mm"
timed "${FEM[@]}" --mesh-mm "$h_last" --duration-ms 0.055 --frequencies-kHz "$FREQS" \
  --signals-pattern "$O/early-sup-{f}kHz.h5" --out "$O/early-sup.json" > /dev/null
for f in ${FREQS//,/ }; do
  h=$(awk -v f="$f" 'BEGIN { printf "%.6g", 156.25 / f }')
  note "early, 55 us: direct $f kHz on its own mesh, h = $h mm"
  timed "${FEM[@]}" --mesh-mm "$h" --duration-ms 0.055 --frequency-kHz "$f" --signals "$O/early-dir-${f}kHz.h5" \
    --out "$O/early-dir-${f}kHz.json" > /dev/null
  "$B/mw-pcc" --a "$O/early-dir-${f}kHz.h5" --b "$O/early-sup-${f}kHz.h5" --sensors B,C,D,E,F,G --pad double --window-end-us 50 \
    --csv "$O/early-pcc-${f}kHz.csv" > /dev/null
  echo "early $f kHz, own mesh against the shared mesh, first 50 us (mean over B-G: signal, envelope):" \
    "$(grep '^mean' "$O/early-pcc-${f}kHz.csv")"
done
note done
