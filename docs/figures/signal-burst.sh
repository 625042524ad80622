#!/usr/bin/env bash
# Makes docs/figures/signal-burst.png from mw-signal's own outputs: a 5-cycle
# 100 kHz Hann burst, its Hilbert envelope and its amplitude spectrum.
#   docs/figures/signal-burst.sh [build/bin]
set -euo pipefail
bin=${1:-build/bin}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$bin/mw-signal" burst --cycles 5 --frequency-kHz 100 --sampling-MHz 10 --delay-us 10 --duration-us 100 \
  --out "$work/burst.csv" >/dev/null
"$bin/mw-signal" envelope "$work/burst.csv" --pad double --out "$work/envelope.csv" >/dev/null
"$bin/mw-signal" spectrum "$work/burst.csv" --pad 65536 --max-frequency-kHz 300 --out "$work/spectrum.csv" >/dev/null
paste -d, "$work/burst.csv" <(cut -d, -f2 "$work/envelope.csv") | grep -v '^#' > "$work/time.csv"

gnuplot <<GNUPLOT
set terminal pngcairo size 1000,420 font "sans,10"
set output "$here/signal-burst.png"
set datafile separator ","
set multiplot layout 1,2 title "5-cycle Hann burst, f_c = 100 kHz, sampled at 10 MHz (mw-signal burst / envelope / spectrum)"
set xlabel "t [us]"
set ylabel "force [N]"
set xrange [0:80]
set yrange [-1.15:1.15]
set grid
set key top right
plot "$work/time.csv" using (\$1*1e6):2 skip 1 with lines lw 1.5 lc rgb "#1f77b4" title "burst", \
     "" using (\$1*1e6):3 skip 1 with lines lw 2 lc rgb "#d62728" title "envelope |x + i H{x}|" noenhanced, \
     "" using (\$1*1e6):(-\$3) skip 1 with lines lw 1 dt 2 lc rgb "#d62728" notitle
set xlabel "f [kHz]"
set ylabel "amplitude 2|X_k|/n [N]"
set xrange [0:300]
set autoscale y
set yrange [0:0.3]
set arrow from 60, graph 0 to 60, graph 1 nohead dt 3 lc rgb "gray40"
set arrow from 140, graph 0 to 140, graph 1 nohead dt 3 lc rgb "gray40"
set label "main lobe f_c(1 -/+ 2/n)" at 145, graph 0.6 tc rgb "gray30"
set key top right
plot "$work/spectrum.csv" using 1:2 skip 1 with lines lw 2 lc rgb "#2ca02c" title "spectrum (zero padded to 65536)"
unset multiplot
GNUPLOT
echo "wrote $here/signal-burst.png"
