set terminal pngcairo size 1100,1300 font "DejaVu Sans,10"
set output "docs/figures/cube-wave-100kHz-sensors.png"
set datafile separator ","
set multiplot layout 6,1 title "mw-dem: 50 mm cube (37,580 spheres, 217,138 bonds), 100 kHz 5-cycle burst at A (centre of x = 0), acceleration normal to the face\n(linearised network; dt = 50 ns, 30,000 steps)" font ",11"
set lmargin 12
set xrange [0:1.5]
set format y "%g"
set grid
names = "B C D E F G"
do for [k=1:6] {
  set ylabel word(names,k)." [m/s^2]"
  if (k == 6) { set xlabel "t [ms]" } else { unset xlabel }
  plot "results/concrete-cube/dem-100kHz.csv" every ::1 using ($1*1e3):(column(k+1)) with lines lw 1 lc rgb "#1f4e9c" notitle
}
unset multiplot
