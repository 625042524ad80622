#!/usr/bin/python3
"""Medians per method and spacing of bench/efg/cantilever.sh's runs.csv, and the EFG/FEM ratios:
at equal node count (the same spacing) and at equal displacement error (the FEM's wall time and
peak RSS interpolated log-log in its error to each EFG error; '-' outside the FEM's range).
usage: bench/efg/ratios.py runs.csv"""
import csv
import math
import statistics
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
groups = {}
for r in rows:
    groups.setdefault((r["method"], float(r["spacing_m"])), []).append(r)
med = {}
for key, rs in groups.items():
    m = {k: statistics.median(float(r[k]) for r in rs)
         for k in ("nodes", "gauss_points", "displacement_error_L2", "energy_error", "solution_s", "process_s", "peak_rss_MiB")}
    m["reps"] = len(rs)
    med[key] = m

print("| method | spacing | nodes | Gauss points | displacement error | energy error | solution wall [s] | process wall [s] | peak RSS [MiB] |")
print("|---|---|---|---|---|---|---|---|---|")
for (method, s), m in sorted(med.items(), key=lambda kv: (kv[0][0], -kv[0][1])):
    print(f"| {method.upper()} | {s:g} | {m['nodes']:.0f} | {m['gauss_points']:.0f} | {m['displacement_error_L2']:.3e} | "
          f"{m['energy_error']:.3e} | {m['solution_s']:.4f} | {m['process_s']:.3f} | {m['peak_rss_MiB']:.1f} |")

fem = sorted(((m["displacement_error_L2"], m) for (meth, s), m in med.items() if meth == "fem"), key=lambda t: t[0])


def fem_at(error, key):
    """The FEM's `key` at displacement error `error`, log-log between the two FEM runs around it."""
    for (e0, m0), (e1, m1) in zip(fem, fem[1:]):
        if e0 <= error <= e1:
            f = (math.log(error) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(m0[key]) + f * (math.log(m1[key]) - math.log(m0[key])))
    return None


print()
print("| spacing | EFG/FEM wall, equal nodes | EFG/FEM RSS, equal nodes | FEM error / EFG error, equal nodes | "
      "EFG/FEM wall, equal error | EFG/FEM RSS, equal error | FEM nodes for the EFG's error |")
print("|---|---|---|---|---|---|---|")
for (method, s), m in sorted(med.items(), key=lambda kv: -kv[0][1]):
    if method != "efg":
        continue
    f = med.get(("fem", s))
    e = m["displacement_error_L2"]
    w, rss, n = fem_at(e, "solution_s"), fem_at(e, "peak_rss_MiB"), fem_at(e, "nodes")
    def fmt(x):
        return "-" if x is None else f"{x:.3g}"
    print(f"| {s:g} | {fmt(m['solution_s'] / f['solution_s'] if f else None)} | {fmt(m['peak_rss_MiB'] / f['peak_rss_MiB'] if f else None)} | "
          f"{fmt(f['displacement_error_L2'] / e if f else None)} | {fmt(m['solution_s'] / w if w else None)} | "
          f"{fmt(m['peak_rss_MiB'] / rss if rss else None)} | {fmt(n)} |")
