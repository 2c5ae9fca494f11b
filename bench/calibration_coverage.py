#!/usr/bin/env python3
"""Summarises calibration_coverage_bench's CSV (issue 36): per constant, over
its fits, how often the 95 % interval contains the truth (coverage; and
the interval before the refit check, A-CAL-12), how
often it is flagged identified, how often an identified one misses the
truth, and the error of the identified ones; per load and noise, then
over all. Markdown tables for docs/calibration.md.

    bench/calibration_coverage.py coverage.csv
"""
import csv
import statistics
import sys
from collections import defaultdict


def median_abs(values):
    return f"{statistics.median(abs(v) for v in values):.1f} %" if values else "-"


def table(title, groups):
    print(f"\n{title}\n")
    print("| constant | fits | interval holds the truth | before the refit check | identified | "
          "identified, truth outside | median error, identified | largest error, identified | median error, all |")
    print("|---|---|---|---|---|---|---|---|---|")
    for key in sorted(groups):
        rows = groups[key]
        n = len(rows)
        covered = sum(r["covered"] == "1" for r in rows)
        before = sum(r["likelihood_covered"] == "1" for r in rows)
        ident = [r for r in rows if r["identified"] == "1"]
        ident_missed = sum(r["covered"] == "0" for r in ident)
        errs_ident = [float(r["error_pct"]) for r in ident]
        errs_all = [float(r["error_pct"]) for r in rows]
        largest = f"{max(abs(e) for e in errs_ident):.1f} %" if errs_ident else "-"
        name = key if isinstance(key, str) else f"{key[0]:g} g cm^2, noise {key[1]:g}: {key[2]}"
        print(f"| {name} | {n} | {covered} ({100 * covered / n:.0f} %) | {before} ({100 * before / n:.0f} %) | "
              f"{len(ident)} | {ident_missed} | "
              f"{median_abs(errs_ident)} | {largest} | {median_abs(errs_all)} |")


def main(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{path}: no rows")
    fits = {(r["load_gcm2"], r["noise_counts"], r["truth"]) for r in rows}
    cpu = {(r["load_gcm2"], r["noise_counts"], r["truth"]): float(r["cpu_s"]) for r in rows}
    inadequate = {(r["load_gcm2"], r["noise_counts"], r["truth"]) for r in rows if r["adequate"] == "0"}
    print(f"{len(fits)} fits; CPU per fit: median {statistics.median(cpu.values()):.1f} s, "
          f"largest {max(cpu.values()):.1f} s; flagged inadequate: {len(inadequate)}")
    by_load = defaultdict(list)
    overall = defaultdict(list)
    for r in rows:
        by_load[(float(r["load_gcm2"]), float(r["noise_counts"]), r["constant"])].append(r)
        overall[r["constant"]].append(r)
    table("Per load and noise", by_load)
    table("Over every load and noise", overall)


if __name__ == "__main__":
    main(sys.argv[1])
