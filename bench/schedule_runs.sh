#!/usr/bin/env bash
# The schedule on 2 cores (docs/benchmarks.md, "The schedule on 2 cores"): a part of the pipeline
# made from nothing in a fresh copy of this tree (scripts/copy-tree), once per schedule, the
# schedules alternated ROUNDS times so that the machine's drift falls on all of them alike:
#   j2-1t      make -j2, MESOWAVE_THREADS=1 (one thread per run)
#   j1-2t      make -j1, MESOWAVE_THREADS=2 (one run at a time on two threads)
#   j2-policy  make -j2, each run's threads from the thread policy (what make reproduce does)
#   j1-policy  make -j1, the same policy
# PART: quick (make pipeline QUICK=1: the whole quick tree, the build left out) or rod-shock (the
# full tree's steel-rod and shock-concrete studies: make steel-rod-summary steel-rod-calibration
# shock-concrete-summary).
# Per make: its wall time, the load average before it, the recorded runs' count and summed wall
# time (the provenance database), and the threads and reason of every DEM and FEM record.
#
#   bench/schedule_runs.sh [BUILD_DIR] [PART] [ROUNDS] [SCHEDULE...]
#   bench/schedule_runs.sh build quick 2 j2-1t j1-2t j2-policy
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath "${1:-$src/build}")
part=${2:-quick}
rounds=${3:-1}
shift $(($# < 3 ? $# : 3))
schedules=("$@")
[ ${#schedules[@]} -gt 0 ] || schedules=(j2-1t j1-2t j2-policy)
case $part in
  quick) goals=(pipeline QUICK=1) out=results-quick ;;
  rod-shock) goals=(steel-rod-summary steel-rod-calibration shock-concrete-summary QUICK=0) out=results ;;
  *) echo "schedule_runs: PART ($part) must be quick or rod-shock" >&2; exit 1 ;;
esac
work=$(realpath "$(mktemp -d)")
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
echo "# $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), tools from $build/bin"
for round in $(seq "$rounds"); do
  for s in "${schedules[@]}"; do
    case $s in
      j2-1t) jobs=-j2 env=(MESOWAVE_THREADS=1) ;;
      j1-2t) jobs=-j1 env=(MESOWAVE_THREADS=2) ;;
      j2-policy) jobs=-j2 env=() ;;
      j1-policy) jobs=-j1 env=() ;;
      *) echo "schedule_runs: schedule $s is not one of j2-1t j1-2t j2-policy j1-policy" >&2; exit 1 ;;
    esac
    tree=$work/$s-$round
    "$src/scripts/copy-tree" "$tree"
    db=$tree/db/provenance-bench.sqlite
    load=$(cut -d' ' -f1-3 /proc/loadavg)
    t0=$(date +%s.%N)
    (cd "$tree" && env "${env[@]}" make --no-print-directory "$jobs" BUILD="$build" MESOWAVE_DB="$db" \
      "${goals[@]}") > "$tree.log" 2>&1 || { echo "$s: make failed:"; tail -20 "$tree.log"; exit 1; }
    t1=$(date +%s.%N)
    runs=$(sqlite3 -batch -noheader "$db" "select count(*) || ' runs, ' || printf('%.1f', sum(wall_s)) || ' s of run wall' from runs")
    echo "round $round $s ($part): $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }') s wall," \
      "$runs, load before $load, $(date -u +%H:%M:%S) UTC"
    # Every DEM and FEM record's thread choice (the summaries' threads and threads_reason).
    for j in "$tree/$out"/*/dem-*.json "$tree/$out"/*/fem-*.json "$tree/$out"/*/speed-[a-z]*[0-9]t.json; do
      [ -f "$j" ] || continue
      jq -r --arg f "${j#"$tree/"}" '"  \($f): threads \(.threads) (\(.threads_reason // "-"))"' "$j" 2> /dev/null || true
    done > "$tree.threads"
    awk '{ print $3 }' "$tree.threads" | sort | uniq -c | awk -v s="$s" '{ printf "  %s: %d records on %s thread(s)\n", s, $1, $2 }'
    [ -z "${VERBOSE:-}" ] || cat "$tree.threads"
    [ -n "${KEEP:-}" ] || rm -rf "$tree"
  done
done
