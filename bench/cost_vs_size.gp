# Cost against size (docs/benchmarks.md "Cost against size"): CPU per step of the linearised network
# and the full law, and the packing's wall time, against the sphere count, log-log, with the power laws
# fitted by gnuplot (c N^b) beside them.
#   gnuplot -e "csv='cost-vs-size.csv'; out='cost-vs-size.png'" bench/cost_vs_size.gp
if (!exists("csv")) csv = 'cost-vs-size.csv'
if (!exists("out")) out = 'cost-vs-size.png'
set datafile separator ','
set fit quiet
set fit logfile '/dev/null'  # no fit.log in the caller's folder (the checkout)
set terminal pngcairo size 1000,650 font ',11'
set output out
set logscale xy
set grid
set key top left
set xlabel 'spheres'
set ylabel 'CPU ms per step; packing wall s'
set title 'mesowave on the concrete paper''s spheres (d 1.6-2.0 mm, p = 7 %): cost against size, one thread'
lin(x) = a1 * x**b1; full(x) = a2 * x**b2; pk(x) = a3 * x**b3
a1 = 1e-4; b1 = 1; a2 = 1e-3; b2 = 1; a3 = 1e-3; b3 = 1
fit log(lin(x)) '< grep ,linear, '.csv using 2:(log($9)) via a1, b1
fit log(full(x)) '< grep ,full, '.csv using 2:(log($9)) via a2, b2
fit log(pk(x)) '< grep ,linear, '.csv using 2:(log($4)) via a3, b3
plot '< grep ,linear, '.csv using 2:9 with linespoints pt 7 title 'wave step, linearised network', \
     lin(x) dt 2 lc 1 title sprintf('  fit: N^{%.3f}', b1), \
     '< grep ,full, '.csv using 2:9 with linespoints pt 5 title 'wave step, full law', \
     full(x) dt 2 lc 2 title sprintf('  fit: N^{%.3f}', b2), \
     '< grep ,linear, '.csv using 2:4 with linespoints pt 9 title 'packing (mw-pack, wall s, loaded machine)', \
     pk(x) dt 2 lc 3 title sprintf('  fit: N^{%.3f}', b3)
