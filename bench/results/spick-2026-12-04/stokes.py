# stokes.py: Stokes point-force record (Aki & Richards Eq. 4.23) beside the DEM S record; writes spick-runs/stokes-<c>.dat
# (t_us, near field, far field, both, DEM), each normalised. python3 bench/results/spick-2026-12-04/stokes.py static 13.50 21.23
# Stokes' point-force solution (Aki & Richards Eq. 4.23) on the force's axis, transverse component:
# u_y = -1/(4 pi rho r^3) int_{r/a}^{r/b} tau F(t - tau) dtau + 1/(4 pi rho b^2 r) F(t - r/b)
# velocity by finite difference; compared with the DEM's S record.
import csv, math, sys
c = sys.argv[1]; tp = float(sys.argv[2]); ts = float(sys.argv[3])
f0 = 120e3; T = 2 / f0
def F(t):
    return math.sin(2*math.pi*f0*t) * 0.5*(1-math.cos(math.pi*f0*t)) if 0 <= t <= T else 0.0
r = 0.05; a = r/(tp*1e-6); b = r/(ts*1e-6)
def u(t, part):
    # near field integral by midpoint rule
    n = 400; lo = r/a; hi = r/b; h = (hi-lo)/n
    nf = -sum((lo+(k+.5)*h)*F(t-(lo+(k+.5)*h)) for k in range(n))*h / r**3
    ff = F(t - r/b) / (b*b*r)
    return {'nf': nf, 'ff': ff, 'all': nf+ff}[part]
rows = list(csv.reader(open('spick-runs/s-%s.csv' % c)))[1:]
t = [float(x[0]) for x in rows]; R = [float(x[1]) for x in rows]
dt = 1e-8
def v(tt, part): return (u(tt+dt, part)-u(tt-dt, part))/(2*dt)
vals = [(tt, v(tt,'nf'), v(tt,'ff'), v(tt,'all')) for tt in t]
pk = max(abs(x[3]) for x in vals if x[0] < 40e-6); pr = max(abs(x) for x in R)
out = open('spick-runs/stokes-%s.dat' % c, 'w')
for (tt, nf, ff, al), rr in zip(vals, R):
    out.write('%g %g %g %g %g\n' % (tt*1e6, nf/pk, ff/pk, al/pk, rr/pr))
