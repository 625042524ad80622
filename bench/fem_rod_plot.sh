#!/usr/bin/env bash
# Speed against error plot from bench/fem_rod.sh's table: wall time of one 1.5 ms run
# (15000 / steps_per_s... as measured: steps scaled to the paper's 1.5 ms) against the RSS of
# the group velocity to Pochhammer-Chree over 50-150 kHz.
#   bench/fem_rod_plot.sh fem_rod.csv OUT.png
set -euo pipefail
csv=${1:?table from bench/fem_rod.sh}
png=${2:?output png}
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
# wall for 1.5 ms = (1.5 ms / dt) / steps_per_s
awk -F, 'NR > 1 { printf "%s %s %.6g %.6g\n", $1, $2, 1.5e-3 / ($4 * 1e-6) / $7, $11 }' "$csv" > "$tmp"
gnuplot <<GP
set terminal pngcairo size 900,600 font 'Sans,11'
set output '$png'
set logscale xy
set grid
set xlabel 'wall time of a 1.5 ms run, one thread [s]'
set ylabel 'RSS of the group velocity, 50-150 kHz [m^2/s^2]'
set title 'mw-fem, steel rod (1 m), 11 bursts 50-150 kHz: speed against error'
set key top right box opaque
set offsets graph 0.08, graph 0.15, graph 0.1, graph 0.1
plot '< grep ^axisymmetric $tmp' u 3:4 w lp pt 7 ps 1.5 lw 2 t 'axisymmetric rings', \
     '' u 3:4:(sprintf("%s mm", stringcolumn(2))) w labels offset 0,1.2 notitle, \
     '< grep ^3d $tmp' u 3:4 w lp pt 5 ps 1.5 lw 2 t '3D hexahedra', \
     '' u 3:4:(sprintf("%s mm", stringcolumn(2))) w labels offset 0,-1.2 notitle, \
     6056 w l dt 2 lc rgb '#888888' t 'rod paper, Abaqus C3D8R 1 mm (Table 2)'
GP
