#!/usr/bin/env python3
"""Two codes or builds timed in rounds on a drifting machine, summarised pair by pair.

On the development VM the same step took 12.5 to 24.5 ms within ten minutes (docs/benchmarks.md,
"The step near the memory limit", fifth part), so only timings taken side by side compare: the
figure to quote is the median over the rounds of each round's ratio, not a ratio of medians.
Used by bench/dem_step_ab.sh, bench/dem_run_ab.sh and bench/yade_side_by_side.sh.

Input (FILE, or standard input): one timing a line, "GROUP ROUND SIDE SECONDS_OR_MS"
(whitespace-separated, GROUP without spaces). Output, per group: each side's median, then the
median of the rounds' ratios NUMERATOR / DENOMINATOR with its quartiles (of the n sorted ratios
the one at rank f (n - 1) rounded to the nearest, ties away from the median: of an even count the
upper middle one is the median, of three rounds the quartiles are the extremes).

    paired_ratios.py FILE NUMERATOR DENOMINATOR [--unit ms]
"""
import argparse
import collections
import math
import statistics
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file", help="the timings, GROUP ROUND SIDE VALUE a line ('-': standard input)")
    parser.add_argument("numerator", help="the side above the ratio's line, e.g. B")
    parser.add_argument("denominator", help="the side below it, e.g. A")
    parser.add_argument("--unit", default="", help="printed after each median (the values' unit)")
    args = parser.parse_args()
    values = collections.defaultdict(list)  # (group, side) -> timings
    rounds = collections.defaultdict(dict)  # (group, round) -> {side: timing}
    with (sys.stdin if args.file == "-" else open(args.file)) as rows:
        for number, line in enumerate(rows, 1):
            fields = line.split()
            if len(fields) != 4:
                sys.exit(f"paired_ratios.py: line {number} has {len(fields)} fields, not GROUP ROUND SIDE VALUE: {line.strip()}")
            group, rnd, side, value = fields
            values[(group, side)].append(float(value))
            rounds[(group, rnd)][side] = float(value)
    for group in sorted({g for g, _ in values}):
        for side in (args.denominator, args.numerator):
            if (group, side) in values:
                print(f"median {side} {group:<40} {statistics.median(values[(group, side)]):10.4g} {args.unit}")
        r = sorted(v[args.numerator] / v[args.denominator] for (g, _), v in rounds.items()
                   if g == group and args.numerator in v and args.denominator in v)
        if not r:
            continue
        # The nearest rank, ties away from the median: of three rounds the quartiles are the extremes.
        q = lambda f: r[math.ceil(f * (len(r) - 1) - 0.5) if f < 0.5 else math.floor(f * (len(r) - 1) + 0.5)]
        print(f"ratio {args.numerator}/{args.denominator} {group:<40} median {q(0.5):.3f} "
              f"(quartiles {q(0.25):.3f}-{q(0.75):.3f}) over {len(r)} rounds")


if __name__ == "__main__":
    main()
