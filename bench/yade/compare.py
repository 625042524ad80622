#!/usr/bin/env python3
# PCC and relative difference of mw-dem's sensor signals (CSV from
# `mw-dem run --signals-csv`) against Yade's (OUT.json from wave.py).
#   bench/yade/compare.py ours.csv yade.json
import csv
import json
import math
import sys

ours_file, yade_file = sys.argv[1], sys.argv[2]
rows = list(csv.reader(open(ours_file)))
header, data = rows[0], rows[1:]
yade = json.load(open(yade_file))["samples"]


def pearson(a, b):
    n = min(len(a), len(b))
    ma, mb = sum(a[:n]) / n, sum(b[:n]) / n
    sab = sum((a[i] - ma) * (b[i] - mb) for i in range(n))
    saa = sum((a[i] - ma) ** 2 for i in range(n))
    sbb = sum((b[i] - mb) ** 2 for i in range(n))
    return sab / math.sqrt(saa * sbb)


print("sensor  samples  PCC            max|diff|/max|yade|")
worst = 1.0
for k, name in enumerate(header):
    if name.endswith("t_s"):
        continue
    label = name.split(" [")[0]
    ours = [float(r[k]) for r in data]
    theirs = yade[label]
    n = min(len(ours), len(theirs))
    pcc = pearson(ours[:n], theirs[:n])
    peak = max(abs(x) for x in theirs[:n])
    diff = max(abs(ours[i] - theirs[i]) for i in range(n)) / peak
    worst = min(worst, pcc)
    print("%-7s %7d  %.10f  %.3g" % (label, n, pcc, diff))
print("lowest PCC %.10f" % worst)
