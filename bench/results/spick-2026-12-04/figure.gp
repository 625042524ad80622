# docs/figures/upv-pickers-dem-s.png: the DEM's S records (1/3 scale) against Stokes' point force (stokes.py),
# with the continuum's S time, mw-upv's AIC-after-P pick and its matched-filter (xcorr) pick
set terminal pngcairo size 1200,800 font 'Sans,11'
set output 'docs/figures/upv-pickers-dem-s.png'
set multiplot layout 2,1
set grid
set xrange [10:34]
set yrange [-0.6:0.6]
set xlabel 'time after the load starts [{/Symbol m}s] (50 mm path)'
set ylabel 'normalised velocity'
set key top left font 'Sans,9'
do for [c in "static dynamic"] {
  if (c eq "static") { ts = 21.23; aic = 24.475; xc = 21.654; tp = 13.50 } else { ts = 18.37; aic = 21.775; xc = 18.500; tp = 11.67 }
  unset arrow
  set arrow from ts, -0.6 to ts, 0.6 nohead lw 2.5 lc rgb 'black'
  set arrow from aic, -0.6 to aic, 0.6 nohead dt 2 lw 2 lc rgb '#d62728'
  set arrow from xc, -0.6 to xc, 0.6 nohead dt 2 lw 2 lc rgb '#1f77b4'
  set arrow from tp, -0.6 to tp, 0.6 nohead dt 3 lw 1 lc rgb '#555555'
  set title sprintf("calibration '%s': continuum t_p %.2f, t_s %.2f {/Symbol m}s (black); AIC after P %.3f (red); matched filter %.3f (blue)", c, tp, ts, aic, xc) font 'Sans,10'
  plot 'spick-runs/stokes-'.c.'.dat' u 1:5 w l lw 2 lc rgb '#333333' t 'DEM record (R, y velocity)', \
       '' u 1:4 w l lw 1.2 lc rgb '#2ca02c' t 'point force, Stokes (near + far field)', \
       '' u 1:2 w l lw 1.2 dt 4 lc rgb '#9467bd' t 'its near field alone (the slow rise)'
}
unset multiplot
