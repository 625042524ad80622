#!/usr/bin/env bash
# Regenerates docs/figures/shpb-echo.png from the real split-Hopkinson-bar record in
# ../shared/realdata/shpb-steel-bar: the incident-bar gauge record, and the leading edge of
# the reflected pulse beside the Pochhammer-Chree echo (the first pulse carried 2 x 1018 mm
# along the 20 mm bar and reflected), for the nominal bar (E = 210 GPa) and for the bar
# velocity fitted to the echo's edges.   docs/figures/shpb-echo.sh [build/bin]
set -euo pipefail
bin=${1:-build/bin}
out=$(cd "$(dirname "$0")" && pwd)
data=${SHPB_DATA:-$out/../../../shared/realdata/shpb-steel-bar}/epoxy_sample01_raw_strain.csv
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo_for() {  # E_GPa file
  "$bin/mw-dispersion" bar-echo --record "$data" --column incident_bar_signal --path-mm 2036 --E-GPa "$1" --nu 0.3 \
    --density-kg-m3 7800 --radius-mm 10 --signals "$2" --out "$2.json" > /dev/null
}
echo_for 210 "$tmp/nominal.csv"
c0=$(jq .fitted_c0_m_s "$tmp/nominal.csv.json")
E_fit=$(jq -n "7800 * $c0 * $c0 / 1e9")
echo_for "$E_fit" "$tmp/fitted.csv"
gnuplot <<GP
set terminal pngcairo size 1100,800 font 'Sans,11'
set output '$out/shpb-echo.png'
set datafile separator ','
set multiplot layout 2,1
set title 'Incident-bar gauge, 20 mm steel bar (real record): pulse, then its echo from the specimen end'
set xlabel 't [us]'; set ylabel 'strain (as recorded)'; set grid; set key top left box opaque
plot '$tmp/nominal.csv' every ::4 u (\$1*1e6):2 w l lc rgb '#6a3d9a' t 'measured'
set title sprintf('Leading edge of the echo: Pochhammer-Chree (nu = 0.3) with c0 = 5189 m/s (nominal) and %.0f m/s (fitted)', $c0)
set xrange [370:440]
plot '$tmp/nominal.csv' every ::4 u (\$1*1e6):2 w l lw 1.5 lc rgb '#6a3d9a' t 'measured', \
     '' every ::4 u (\$1*1e6):3 w l lw 2 dt 2 lc rgb '#1f77b4' t 'theory, nominal E = 210 GPa', \
     '$tmp/fitted.csv' every ::4 u (\$1*1e6):3 w l lw 2 lc rgb '#d62728' t sprintf('theory, c0 = %.0f m/s (E = %.1f GPa)', $c0, $E_fit)
unset multiplot
GP
