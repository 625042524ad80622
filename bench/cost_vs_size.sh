#!/usr/bin/env bash
# Cost against size (issue 17, item 5; docs/benchmarks.md "Cost against size"): for cubes of the
# concrete paper's spheres (p = 7 %, d = 1.6-2.0 mm) from about 10k to 1.1M spheres,
#  - the packing: mw-pack box --cube-side-mm SIDE (wall, CPU, peak RSS), or an existing packing's
#    wall time from its summary when one is given (SIDE:FILE);
#  - the wave step: bench_dem's step benchmarks on that packing (MESOWAVE_BENCH_PACKING), the
#    linearised network and the full law, THREADS threads (default 1): wall and CPU per step (the machine is shared:
#    CPU time is the steadier figure, on one thread: Google Benchmark counts the main thread only;
#    the load average is printed before every run), and the
#    benchmark process's peak RSS (the larger of the two models, built one after the other);
# one row per size and model as CSV, then the exponent b of cost ~ spheres^b fitted on the rows
# (least squares in log-log); bench/cost_vs_size.gp draws the CSV. Then the step again with every
# size side by side in one process (bench_dem_sizes: the sizes stepped in turns, so that the
# machine's drift between the rows above does not enter the exponent), for both models, with its
# CSV beside (steps-side-by-side-MODEL.csv): the exponent to quote.
#
#   bench/cost_vs_size.sh OUT_DIR SIDE[:PACKING] ...    e.g. bench/cost_vs_size.sh /tmp/cvs 32 50:results/concrete-cube/packing.h5 75 150:big.h5
# BIN (default build/bin).
set -euo pipefail
out=${1:?OUT_DIR}; shift
BIN=${BIN:-build/bin}
STEPS=${STEPS:-200}
THREADS=${THREADS:-1}
SCENE=pipeline/concrete-cube/scenes/cube-wave.toml
mkdir -p "$out"
csv=$out/cost-vs-size.csv
load() { cut -d' ' -f1 /proc/loadavg; }
echo "# machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $(date -u +%FT%TZ)" >&2
echo "side_mm,spheres,bonds,pack_wall_s,pack_cpu_s,pack_peak_rss_MiB,model,wall_ms_per_step,cpu_ms_per_step,cpu_ns_per_bond_step,bench_peak_rss_MiB,bytes_per_sphere,load" > "$csv"
packings=()
for spec in "$@"; do
  side=${spec%%:*}; packing=${spec#*:}
  pack_cpu=; pack_rss=
  if [ "$packing" = "$spec" ]; then
    packing=$out/packing-${side}mm.h5
    echo "# $(date -u +%T) load $(load): mw-pack box --cube-side-mm $side" >&2
    /usr/bin/time -f '%e %U %S %M' -o "$out/pack-$side.time" "$BIN/mw-pack" box --threads 1 --cube-side-mm "$side" \
      --porosity-pct 7 --d-min-mm 1.6 --d-max-mm 2 --density-kg-m3 2129.56 --detection-factor 1.1 --quiet \
      --packing "$packing" --out "${packing%.h5}.json" > /dev/null
    read -r pack_wall u sy pack_rss < "$out/pack-$side.time"
    pack_cpu=$(awk -v u="$u" -v s="$sy" 'BEGIN { print u + s }'); pack_rss=$((pack_rss / 1024))
  fi
  packings+=("$packing")
  pack_wall=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1])).get('wall_time_s', ''))" "${packing%.h5}.json" 2>/dev/null || true)
  l=$(load)
  echo "# $(date -u +%T) load $l: bench_dem on $packing ($THREADS thread(s))" >&2
  MESOWAVE_BENCH_PACKING=$packing /usr/bin/time -f '%M' -o "$out/bench.time" "$BIN/bench_dem" \
    --benchmark_filter="BM_(FullLaw|LinearNetwork)Step/$THREADS/" --benchmark_format=json > "$out/bench-$side.json"
  python3 - "$out/bench-$side.json" "$side" "$pack_wall" "$pack_cpu" "$pack_rss" "$(cat "$out/bench.time")" "$l" >> "$csv" <<'PY'
import json, sys
b = json.load(open(sys.argv[1]))["benchmarks"]
side, pack_wall, pack_cpu, pack_rss, rss, load = sys.argv[2:]
rss_mib = int(rss) / 1024
for r in b:
    model = "full" if "FullLaw" in r["name"] else "linear"
    scale = {"ms": 1.0, "us": 1e-3, "ns": 1e-6}[r["time_unit"]]
    wall, cpu = r["real_time"] * scale, r["cpu_time"] * scale
    print(f"{side},{int(r['spheres'])},{int(r['bonds'])},{pack_wall},{pack_cpu},{pack_rss},{model},{wall:.4g},{cpu:.4g},"
          f"{1e6 * cpu / r['bonds']:.4g},{rss_mib:.0f},{rss_mib * 1048576 / r['spheres']:.0f},{load}")
PY
done
cat "$csv"
python3 - "$csv" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
def fit(xs, ys):
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)
for model in ("linear", "full"):
    r = [x for x in rows if x["model"] == model]
    if len(r) >= 2:
        n = [float(x["spheres"]) for x in r]
        print(f"{model}: exponent of CPU per step against spheres {fit(n, [float(x['cpu_ms_per_step']) for x in r]):.3f}, "
              f"of wall per step {fit(n, [float(x['wall_ms_per_step']) for x in r]):.3f}")
r = [x for x in rows if x["model"] == "linear"]
if len(r) >= 2:
    n = [float(x["spheres"]) for x in r]
    print(f"exponent of the benchmark's peak RSS against spheres: {fit(n, [float(x['bench_peak_rss_MiB']) for x in r]):.3f}")
    p = [(a, float(x["pack_wall_s"])) for a, x in zip(n, r) if x["pack_wall_s"]]
    if len(p) >= 2: print(f"exponent of the packing's wall against spheres: {fit([a for a, _ in p], [b for _, b in p]):.3f}")
    p = [(a, float(x["pack_cpu_s"])) for a, x in zip(n, r) if x["pack_cpu_s"]]
    if len(p) >= 2: print(f"exponent of the packing's CPU against spheres: {fit([a for a, _ in p], [b for _, b in p]):.3f}")
PY
if [ "${#packings[@]}" -ge 2 ]; then
  for model in linear full; do
    echo "# $(date -u +%T) load $(load): bench_dem_sizes --model $model ($THREADS thread(s)), the sizes side by side" >&2
    "$BIN/bench_dem_sizes" --model "$model" --threads "$THREADS" --csv "$out/steps-side-by-side-$model.csv" "${packings[@]}" 2>/dev/null
  done
fi
