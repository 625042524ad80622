#!/usr/bin/env python3
# mw-dem's virtual compression test against Yade's (bench/yade/compression.py)
# on the same spheres: E_glob and nu_glob (secant and least-squares) side by
# side, and the largest differences of the curves sample by sample (both codes
# sample at the same instants: t = k x sample interval).
#
#   bench/yade/compare_compression.py yade.json ours-full.json ours-full.csv [ours-linear.json ours-linear.csv ...]
#
# ours-*.json: `mw-dem run --summary`; ours-*.csv: `mw-dem run --curves`.
# Exit status 1 if a model misses the target: E_glob within 2 % and
# nu_glob within 0.005 of Yade's.
import csv
import json
import sys

E_TOLERANCE, NU_TOLERANCE = 0.02, 0.005

yade_file, pairs = sys.argv[1], sys.argv[2:]
if not pairs or len(pairs) % 2:
    raise SystemExit("usage: compare_compression.py yade.json ours.json ours.csv [ours.json ours.csv ...]")
yade = json.load(open(yade_file))
yc = yade["curves"]
y_t, y_sig = yc["t_s"], [s / 1e6 for s in yc["stress_Pa"]]
y_eps, y_lat = yc["axial_strain"], yc["lateral_strain"]


def largest_difference(ours, theirs):
    n = min(len(ours), len(theirs))
    scale = max(abs(x) for x in theirs[:n])
    return max(abs(ours[i] - theirs[i]) for i in range(n)) / scale


rows = [("Yade 2023.02a", yade["E_secant_GPa"], yade["nu_secant"], yade["E_fit_GPa"], yade["nu_fit"],
         yade["steps"], yade["wall_s"], yade["threads"], None)]
ok = True
for summary_file, curves_file in zip(pairs[0::2], pairs[1::2]):
    s = json.load(open(summary_file))
    t = s["test"]
    data = list(csv.DictReader(open(curves_file)))
    o_t = [float(r["t_s"]) for r in data]
    n = min(len(o_t), len(y_t))
    clock = max(abs(o_t[i] - y_t[i]) for i in range(n))
    if clock > 1e-12:
        raise SystemExit("error: %s samples at other instants than Yade (off by %g s)" % (curves_file, clock))
    diffs = (largest_difference([float(r["stress_MPa"]) for r in data], y_sig),
             largest_difference([float(r["axial_strain"]) for r in data], y_eps),
             largest_difference([float(r["lateral_strain"]) for r in data], y_lat))
    rows.append(("mesowave " + s["model"], t["E_glob_GPa"], t["nu_glob"], t["E_fit_GPa"], t["nu_fit"], s["steps"],
                 s["wall_s"], s["threads"], diffs))
    dE = t["E_glob_GPa"] / yade["E_secant_GPa"] - 1
    dnu = t["nu_glob"] - yade["nu_secant"]
    ok = ok and abs(dE) <= E_TOLERANCE and abs(dnu) <= NU_TOLERANCE

print("levels %g-%g MPa, %d samples (Yade), area %.3f mm2" % (*yade["modulus_levels_MPa"], len(y_t), yade["area_mm2"]))
print("%-16s %10s %9s %10s %9s %8s %8s %6s %9s %9s  %s" % (
    "code", "E_glob GPa", "nu_glob", "E_fit GPa", "nu_fit", "dE", "dnu", "steps", "wall s", "threads",
    "max|diff|/max: stress, axial, lateral"))
for name, E, nu, E_fit, nu_fit, steps, wall, threads, diffs in rows:
    dE = "%+.2e" % (E / rows[0][1] - 1) if diffs else ""
    dnu = "%+.1e" % (nu - rows[0][2]) if diffs else ""
    curve = "%.2e, %.2e, %.2e" % diffs if diffs else ""
    print("%-16s %10.4f %9.5f %10.4f %9.5f %8s %8s %6d %9.1f %9d  %s" % (
        name, E, nu, E_fit, nu_fit, dE, dnu, steps, wall, threads, curve))
print("target: E_glob within %g %% and nu_glob within %g of Yade's: %s" % (
    E_TOLERANCE * 100, NU_TOLERANCE, "met" if ok else "MISSED"))
sys.exit(0 if ok else 1)
