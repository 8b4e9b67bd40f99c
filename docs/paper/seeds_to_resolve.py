#!/usr/bin/env python3
"""For each check a paper report left "not resolved", the seeds that would resolve it if the
mean and the seed-to-seed spread stayed as measured: the least n with
t_0.975(n - 1) * sd / sqrt(n) < |mean - threshold|, the rule findings.csv's seeds_to_resolve
column applies (engine/studies/src/paper/ensemble_stats.cpp, seedsToExclude). Reads a
findings.csv whose intervals are Student-t intervals, recovering sd from their width.

    python3 docs/paper/seeds_to_resolve.py docs/paper/ensemble-full/findings.csv
"""
import csv
import math
import sys

T975 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160, 2.145, 2.131,
        2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042]


def t975(dof):
    if dof <= 30:
        return T975[dof - 1]
    z = 1.959964
    return z + (z ** 3 + z) / (4 * dof) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * dof * dof)


def seeds_to_exclude(mean, sd, threshold):
    gap = abs(mean - threshold)
    for n in range(2, 100001):
        if t975(n - 1) * sd / math.sqrt(n) < gap:
            return n
    return None


def number(text, empty):
    return float(text) if text else empty


def main(path):
    rows = [r for r in csv.DictReader(open(path)) if r["check_verdict"].startswith("not resolved")]
    print("| # | check | mean (threshold) | seeds that measured it | seeds that would resolve it | runs, at the share that measures it |")
    print("|---|---|---:|---:|---:|---:|")
    for r in rows:
        n, runs = int(r["seeds"]), int(r["check_verdict"].split(" at ")[1].split()[0])
        low, high, mean = float(r["ci_low"]), float(r["ci_high"]), float(r["value"])
        holds_from, holds_to = number(r["holds_from"], -math.inf), number(r["holds_to"], math.inf)
        sd = (high - low) / 2 * math.sqrt(n) / t975(n - 1)
        threshold = holds_from if low < holds_from <= high else holds_to
        need = seeds_to_exclude(mean, sd, threshold)
        total = math.ceil(need * runs / n) if need else None
        shown = f"{threshold:.3g}" if abs(threshold) > 1e-300 else "0"
        subject = r['subject'].replace('|', '\\|')
        print(f"| {r['number']} | {subject} | {mean:.3g} ({shown}) | {n} of {runs} | {need or 'over 100,000'} | "
              f"{total if total else '—'} |")


if __name__ == "__main__":
    main(sys.argv[1])
