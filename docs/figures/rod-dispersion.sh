#!/usr/bin/env bash
# Regenerates docs/figures/rod-dispersion-{full,zoom}.png: Pochhammer-Chree L(0,1)/L(0,2)
# for the rod paper's steel (Section 4.1) and the exact lattice dispersion of the four DEM
# chains of rod Table 1 (particle density rho_p, K_n column read as the contact modulus E_dem).
#   docs/figures/rod-dispersion.sh [build/bin]
set -euo pipefail
bin=${1:-build/bin}
out=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
chain() {  # label rho_p E_dem[GPa] d/R
  "$bin/mw-dispersion" lattice --sphere-radius-mm 5.1 --particle-density-kg-m3 "$2" --E-dem-GPa "$3" \
    --spacing-R "$4" --label "$1" --f-max-kHz 500 --csv "$tmp/$1.csv" > /dev/null
}
chain 0.95R 5577.17 230 0.95
chain 0.95R-EDEM 5577.17 686 0.95   # E_dem that reproduces Table 1's E_DEM = 207.30 GPa (E_dem = pi E_DEM / 0.95)
chain 1.03R 6044.37 660 1.03
chain 1.05R 6173.66 640 1.05
chain 1.15R 6751.31 600 1.15
overlays=(--overlay "DEM chain 0.95R (Table 1 K_n = 2.3e11)=$tmp/0.95R.csv"
          --overlay "DEM chain 0.95R (K_n = 6.86e11 from E_{DEM})=$tmp/0.95R-EDEM.csv"
          --overlay "DEM chain 1.03R=$tmp/1.03R.csv" --overlay "DEM chain 1.05R=$tmp/1.05R.csv"
          --overlay "DEM chain 1.15R=$tmp/1.15R.csv")
steel=(--E-GPa 208.72 --nu 0.3 --density-kg-m3 7850.66 --radius-mm 5.1 --f-max-kHz 500 --df-kHz 1 --modes 2)
"$bin/mw-dispersion" theory "${steel[@]}" "${overlays[@]}" --plot-key inside,bottom,left \
  --plot "$out/rod-dispersion-full.png" > /dev/null
"$bin/mw-dispersion" theory "${steel[@]}" "${overlays[@]}" --plot-key inside,bottom,right \
  --plot-f-range-kHz 40,160 --plot-c-range-m-s 2500,5500 --plot "$out/rod-dispersion-zoom.png" > /dev/null
