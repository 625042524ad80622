#!/usr/bin/env bash
# Cost against size (issue 17, item 5; docs/benchmarks.md "Cost against size"): for cubes of the
# concrete paper's spheres (p = 7 %, d = 1.6-2.0 mm) from about 10k to 1.1M spheres,
#  - the packing: mw-pack box --cube-side-mm SIDE (wall, peak RSS), or an existing packing's
#    numbers when one is given (SIDE:FILE; its wall time from its summary, its memory not known);
#  - the wave step: short mw-dem runs of the 50 mm cube's wave scene on that packing (sensors and
#    actuator at the same fractions), linearised network and full law, one thread each (the
#    machine is shared: the load average is printed before every run);
# one row per run as CSV, then the exponent b of wall per step ~ spheres^b fitted on the rows
# (least squares in log-log), per model; bench/cost_vs_size_plot.gp draws the CSV.
#
#   bench/cost_vs_size.sh OUT_DIR SIDE[:PACKING] ...    e.g. bench/cost_vs_size.sh /tmp/cvs 32 50:results/concrete-cube/packing.h5 75 150:big.h5
# STEPS (default 200) steps a run, THREADS (default 1), BIN (default build/bin).
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
echo "side_mm,spheres,bonds,pack_wall_s,pack_peak_rss_MiB,model,threads,steps,setup_s,run_wall_s,ms_per_step,ns_per_bond_step,peak_rss_MiB,bytes_per_sphere,load" > "$csv"
for spec in "$@"; do
  side=${spec%%:*}; packing=${spec#*:}
  if [ "$packing" = "$spec" ]; then
    packing=$out/packing-${side}mm.h5
    echo "# $(date -u +%T) load $(load): mw-pack box --cube-side-mm $side" >&2
    /usr/bin/time -f '%e %M' -o "$out/pack-$side.time" "$BIN/mw-pack" box --threads "$THREADS" --cube-side-mm "$side" \
      --porosity-pct 7 --d-min-mm 1.6 --d-max-mm 2 --density-kg-m3 2129.56 --detection-factor 1.1 --quiet \
      --packing "$packing" --out "$out/pack-$side.json" > /dev/null
    read -r pack_wall pack_rss < "$out/pack-$side.time"; pack_rss=$((pack_rss / 1024))
  else
    summary=${packing%.h5}.json
    pack_wall=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1])).get('wall_time_s', ''))" "$summary" 2>/dev/null || true)
    pack_rss=
  fi
  # STEPS steps of the scene's 50 ns.
  duration_ms=$(awk -v n="$STEPS" 'BEGIN { printf "%.6g", n * 50e-9 * 1e3 }')
  for model in linear full; do
    l=$(load)
    echo "# $(date -u +%T) load $l: mw-dem run --packing $packing --model $model ($STEPS steps)" >&2
    /usr/bin/time -f '%e %M' -o "$out/run.time" "$BIN/mw-dem" run "$SCENE" --packing "$packing" --model "$model" \
      --threads "$THREADS" --frequency-kHz 100 --duration-ms "$duration_ms" --quiet --signals "$out/run.h5" \
      --summary "$out/run-$side-$model.json" > /dev/null
    read -r _ rss < "$out/run.time"
    python3 - "$out/run-$side-$model.json" "$side" "$pack_wall" "$pack_rss" "$rss" "$l" >> "$csv" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
side, pack_wall, pack_rss, rss, load = sys.argv[2:]
rss_mib = int(rss) / 1024
ms = 1e3 * (s["wall_s"] - s["setup_s"]) / s["steps"]
print(f"{side},{s['spheres']},{s['bonds']},{pack_wall},{pack_rss},{s['model']},{s['threads']},{s['steps']},"
      f"{s['setup_s']:.3f},{s['wall_s']:.3f},{ms:.4g},{1e6 * ms / s['bonds']:.4g},{rss_mib:.0f},"
      f"{rss_mib * 1048576 / s['spheres']:.0f},{load}")
PY
  done
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
        print(f"exponent of ms/step against spheres, {model}: {fit([float(x['spheres']) for x in r], [float(x['ms_per_step']) for x in r]):.3f}")
        print(f"exponent of peak RSS against spheres, {model}: {fit([float(x['spheres']) for x in r], [float(x['peak_rss_MiB']) for x in r]):.3f}")
p = [x for x in rows if x["model"] == "linear" and x["pack_wall_s"]]
if len(p) >= 2:
    print(f"exponent of packing wall against spheres: {fit([float(x['spheres']) for x in p], [float(x['pack_wall_s']) for x in p]):.3f}")
PY
