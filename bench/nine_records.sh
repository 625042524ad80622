#!/usr/bin/env bash
# Issue 17 item 1's target, "the cube's nine DEM wave records from one run in at most 90 s": the
# pipeline's own command (waves.mk, CC_DEM_WAVES, as `make -n` prints it for the tree, so the two
# cannot drift apart) run alone, at 1 and at 2 threads, alternated,
# on a make reproduce tree's packing and calibration; each run's records compared with the first
# run's (cmp: the same bits whatever the thread count; a record names its packing's path, so the
# tree's own, made with a relative path, differ in that attribute). docs/benchmarks.md, "One run,
# every frequency".
#
#   bench/nine_records.sh RESULTS [OUT] [REPS]   RESULTS: a tree's results/concrete-cube
set -euo pipefail
R=${1:?usage: bench/nine_records.sh RESULTS [OUT] [REPS]}
O=${2:-results/bench/nine-records}
N=${3:-2}
B=${BIN:-build/bin}
mkdir -p "$O"
R=$(realpath "$R")
# The pipeline's command for this tree (RESULTS: the tree's results folder), its outputs to be replaced.
command=$(make --no-print-directory -n -B RESULTS="$(dirname "$R")" BIN="$B" "$R/dem-waves.json" | grep -e '--frequencies-kHz' | grep mw-dem)
[ -n "$command" ] || { echo "nine_records.sh: make -n printed no nine-frequency mw-dem command for $R" >&2; exit 1; }
command=${command%% --signals-pattern *}
freqs=$(sed -n 's/.*--frequencies-kHz \([0-9,]*\).*/\1/p' <<< "$command")
echo "# $command"
for rep in $(seq 1 "$N"); do
  for threads in 1 2; do
    out="$O/t$threads-r$rep"
    mkdir -p "$out"
    load=$(cut -d' ' -f1 /proc/loadavg)
    MESOWAVE_THREADS=$threads /usr/bin/time -f "%e %U %S %M" -o "$out/time.txt" bash -c \
      "$command --signals-pattern '$out/dem-{f}kHz.h5' --summary '$out/dem-waves.json' > /dev/null"
    same=yes
    for f in ${freqs//,/ }; do
      cmp -s "$out/dem-${f}kHz.h5" "$O/t1-r1/dem-${f}kHz.h5" || same=no
    done
    read -r wall user sys rss < "$out/time.txt"
    printf '%s threads=%s rep=%s load_at_start=%s wall_s=%s cpu_s=%.1f peak_MiB=%d records_equal_to_first_run=%s\n' \
      "$(date -u +%FT%TZ)" "$threads" "$rep" "$load" "$wall" "$(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }')" "$((rss / 1024))" "$same"
  done
done
