#!/usr/bin/env python3
"""Prints, for each preset of a `grainlab tradeoff --seeds N` tradeoff.csv, the per-setting
table of docs/speed-accuracy.md: how many quantities are biased, undecided or show no bias,
the shearing's CPU seconds per run, three biases with their 95 % intervals, and how far σ11
was from its target.

    python3 docs/speed-accuracy/ensemble_table.py DIR/tradeoff.csv
"""
import csv
import sys
from collections import OrderedDict


def g(text, digits=2):
    return f"{float(text):.{digits}g}"


def bias(row):
    if row is None or row["bias"] == "":
        return "—"
    return f"{g(row['bias'])} ({g(row['bias_ci_low'])} to {g(row['bias_ci_high'])})"


def main(path):
    rows = list(csv.DictReader(open(path)))
    presets = OrderedDict()
    for r in rows:
        presets.setdefault(r["preset"], OrderedDict()).setdefault((r["axis"], r["value"]), []).append(r)
    for preset, settings in presets.items():
        seeds = max(int(r["seeds"]) for s in settings.values() for r in s if r["seeds"])
        print(f"### {preset}: {seeds} seeds\n")
        print("| axis | value | paired | shearing CPU s/run | biased | undecided | no bias found | "
              "peak φ_mob bias (°) | void ratio at 20% bias | ω at 5% bias (°) | σ11 off target |")
        print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
        for (axis, value), group in settings.items():
            by = {r["quantity"]: r for r in group}
            off = f"{100 * float(group[0]['lateral_stress_off']):.2g}%" if group[0]["lateral_stress_off"] else "—"
            if axis == "reference":
                sd = lambda q: f"sd {g(by[q]['sd'])}" if q in by and by[q]["sd"] else "—"
                print(f"| reference | {value} | — | {g(group[0]['cpu_s'], 3)} | | | | {sd('peak_phi_mob_deg')} | "
                      f"{sd('void_ratio_20')} | {sd('omega_5_deg')} | {off} |")
                continue
            verdicts = [r["verdict"] for r in group]
            biased = sum(v.startswith("biased") for v in verdicts)
            clean = sum(v.startswith("no bias") for v in verdicts)
            undecided = len(verdicts) - biased - clean
            paired = "yes" if group[0]["paired"] == "1" else "no"
            print(f"| {axis} | {value} | {paired} | {g(group[0]['cpu_s'], 3)} | {biased} | {undecided} | {clean} | "
                  f"{bias(by.get('peak_phi_mob_deg'))} | {bias(by.get('void_ratio_20'))} | {bias(by.get('omega_5_deg'))} | {off} |")
        print()


if __name__ == "__main__":
    main(sys.argv[1])
