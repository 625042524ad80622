#!/bin/bash
# the four 1/3-scale UPV runs of the brief, one thread, one at a time
cd "$(dirname "$0")/../../.."; mkdir -p spick-runs
S="--E-dem-GPa 26.92 --nu-dem 0.2960 --friction-angle-deg 18 --T-MPa 33.77 --C-MPa 33.77"
D="--E-dem-GPa 36.19219840919328 --nu-dem 0.28993249834973567 --friction-angle-deg 18 --T-MPa 33.93178676344461 --C-MPa 33.93178676344461"
for k in s p; do
 for c in static dynamic; do
  if [ $c = static ]; then M="$S"; else M="$D"; fi
  echo "$(date -u) start $k $c"; uptime
  /usr/bin/time -v build/bin/mw-dem run pipeline/concrete-cube/scenes/upv50-$k.toml --packing results/concrete-cube/packing.h5 $M \
    --signals-csv spick-runs/$k-$c.csv --signals spick-runs/$k-$c.h5 --summary spick-runs/$k-$c.json --threads 1 --quiet > spick-runs/$k-$c.log 2>&1
  echo "$(date -u) end $k $c rc $?"; grep -E "Elapsed|Maximum resident" spick-runs/$k-$c.log
 done
done
