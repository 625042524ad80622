# cand.py: the candidate S pickers tried on the DEM records before choosing (pure Python, no numpy):
# AIC in mw-upv's S window (1.3 t_p .. the largest |x|) on the record filtered (zero phase, FFT) by a
# high-pass, a band-pass f/2..2f with raised-cosine flanks (f/4, 4f), a d/dt pre-emphasis; and the lag of the
# global maximum of the correlation with F' (no window: the C++ xcorr picker is windowed and refined).
# Run from the repository root after dem-runs.sh: python3 bench/results/spick-2026-12-04/cand.py
import csv, math, cmath, sys
def load(f, col=1):
    r = list(csv.reader(open(f)))[1:]
    return [float(x[0]) for x in r], [float(x[col]) for x in r]
def dft(x):  # real -> complex, naive
    n = len(x); return [sum(x[k]*cmath.exp(-2j*math.pi*m*k/n) for k in range(n)) for m in range(n//2+1)]
def idft(X, n):
    out = []
    for k in range(n):
        s = X[0].real
        for m in range(1, len(X)):
            w = 1 if (n % 2 == 1 or m != n//2) else 0.5
            s += 2*w*(X[m]*cmath.exp(2j*math.pi*m*k/n)).real
        out.append(s/n)
    return out
def aic(x, a, b):
    seg = x[a:b]; n = len(seg); best = None
    for k in range(2, n-2):
        l = seg[:k]; r = seg[k:]
        def var(v):
            m = sum(v)/len(v); return max(sum((q-m)**2 for q in v)/len(v), 1e-300)
        A = k*math.log(var(l)) + (n-k-1)*math.log(var(r))
        if best is None or A < best[0]: best = (A, a+k)
    return best[1]
f0 = 120e3
def F(t): return math.sin(2*math.pi*f0*t)*0.5*(1-math.cos(math.pi*f0*t)) if 0 <= t <= 2/f0 else 0.0
def dF(t, h=1e-9): return (F(t+h)-F(t-h))/(2*h)
for c, tp, ts in [('static', 13.547877, 21.23), ('dynamic', 11.762485, 18.37)]:
    t, x = load('spick-runs/s-%s.csv' % c)
    dt = t[1]-t[0]; n = len(x)
    # matched filter: template F'(t) sampled on dt, correlate
    tpl = [dF(k*dt) for k in range(int(2/f0/dt)+1)]
    best = max(range(n-len(tpl)), key=lambda L: sum(x[L+k]*tpl[k] for k in range(len(tpl))))
    # t[best] is the sample time at which template's t=0 aligns; template starts at burst time 0
    print(c, 'xcorr F\' lag onset %.3f us (continuum %.2f)' % ((t[best]-t[0]+t[0]-0*dt)*1e6 - 0.0, ts))
    # spectra: pad to 2n, band filters
    m = 2*n; X = dft(x + [0.0]*n); df = 1/(m*dt)
    i0 = int(math.ceil((1.3*tp*1e-6 - t[0])/dt))
    for name, g in [('none', lambda f: 1.0),
                    ('hp f0/2 cos', lambda f: 0 if f < f0/4 else (1 if f > f0/2 else 0.5*(1-math.cos(math.pi*(f-f0/4)/(f0/4))))),
                    ('bp f0/2..2f0', lambda f: 0 if f < f0/4 or f > 4*f0 else (1 if f0/2 <= f <= 2*f0 else (0.5*(1-math.cos(math.pi*(f-f0/4)/(f0/4))) if f < f0/2 else 0.5*(1+math.cos(math.pi*(f-2*f0)/(2*f0)))))),
                    ('f-weight (d/dt)', lambda f: f/f0)]:
        Y = [X[k]*g(k*df) for k in range(len(X))]
        y = idft(Y, m)[:n]
        # envelope peak search as mw-upv: window 1.3tp..3.5tp; use |y| max as crude envelope peak
        i1 = min(n, int((3.5*tp*1e-6 - t[0])/dt))
        ipk = max(range(i0, i1), key=lambda i: abs(y[i]))
        k = aic(y, i0, ipk)
        print('  %-16s AIC %.3f us (window %.2f..%.2f)' % (name, t[k]*1e6, t[i0]*1e6, t[ipk]*1e6))
