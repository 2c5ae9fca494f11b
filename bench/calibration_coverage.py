#!/usr/bin/env python3
"""Summarises calibration_coverage_bench's CSV (issue 36): per constant, over
its fits, how often the reported 95 % interval contains the truth
(coverage), how often the constant is flagged identified and how often an
identified one's interval holds the truth, the median half-width of the
identified intervals and of the bootstrap's (A-CAL-12) on every fit, and
the fits' errors; per load and noise, then over all. Markdown tables for
docs/calibration.md.

The verdict is derived from the CSV's raw columns with the rule of
calibration/fit_refit.cpp (the likelihood interval, the bootstrap's refits,
the card's ranges from models/sreh50-model.yaml), so a CSV recorded by an
earlier binary of the same fits is summarised by today's rule;
--multiple K replaces the t multiple (a sensitivity check: a K chosen
after seeing a CSV must be checked on truths not in it).

    bench/calibration_coverage.py coverage.csv [--multiple K] [--truths A-B]
"""
import argparse
import csv
import math
import os
import re
import statistics
from collections import defaultdict

T95 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228]
WIDE = 0.10  # an interval wider than +-10 % of the value: not identified (--wide)


def card_ranges():
    path = os.path.join(os.path.dirname(__file__), "..", "models", "sreh50-model.yaml")
    ranges, name = {}, None
    for line in open(path):
        m = re.match(r"^  ([a-z_0-9]+):\s*$", line)
        if m:
            name = m.group(1)
        m = re.match(r"^    range: \[([^,]+), ([^\]]+)\]", line)
        if m and name:
            ranges[name] = (float(m.group(1)), float(m.group(2)))
    return ranges


def verdict(r, ranges, multiple):
    """(reported lo, hi, identified, the bootstrap's interval lo, hi within the range, its half-width in % of the
    value before the range clips it)."""
    v = float(r["fitted"])
    lo, hi = float(r["likelihood_lo"]), float(r["likelihood_hi"])
    refits = [float(x) for x in r["refits"].split()]
    k = multiple if multiple else T95[len(refits) - 1]
    half = k * math.sqrt(sum((x - v) ** 2 for x in refits) / len(refits))
    lo, hi = min(lo, v - half), max(hi, v + half)
    rlo, rhi = ranges[r["constant"]]
    wide = 0.5 * (hi - lo) > WIDE * abs(v)
    # A CSV of a binary with a wider limit: its likelihood-stage "wide interval" note is re-judged here.
    # Identified before the bootstrap: the CSV's note is empty or the
    # bootstrap's own "wide interval: the refits ..." (the earlier reasons
    # come first and keep their note).
    before = r["adequate"] == "1" and (r["note"] == "" or r["note"].startswith("wide interval"))
    identified = before and not wide
    blo, bhi, bhalf = max(rlo, lo), min(rhi, hi), 100 * 0.5 * (hi - lo) / abs(v)
    if identified:
        return blo, bhi, True, blo, bhi, bhalf
    return rlo, rhi, False, blo, bhi, bhalf  # not identified: the card's range


def pct(a, n):
    return f"{a} of {n} ({100 * a / n:.0f} %)" if n else "-"


def med(values, fmt="{:.1f} %"):
    return fmt.format(statistics.median(values)) if values else "-"


def table(title, groups, ranges, multiple):
    print(f"\n{title}\n")
    print("| constant | fits | reported interval holds the truth | identified | identified, interval holds the truth | "
          "median half-width, identified | median half-width, bootstrap (all) | bootstrap interval holds the truth (all) | "
          "median error, identified | largest error, identified | median error, all |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for key in sorted(groups):
        rows = groups[key]
        n = len(rows)
        covered = ident = ident_cov = boot_cov = 0
        half_ident, half_all, err_ident, err_all = [], [], [], []
        for r in rows:
            t = float(r["truth_value"])
            lo, hi, idf, blo, bhi, half = verdict(r, ranges, multiple)
            v = float(r["fitted"])
            inside = lo <= t <= hi
            covered += inside
            boot_cov += blo <= t <= bhi
            half_all.append(half)
            err = 100 * (v / t - 1)
            err_all.append(abs(err))
            if idf:
                ident += 1
                ident_cov += inside
                half_ident.append(half)
                err_ident.append(abs(err))
        name = key if isinstance(key, str) else f"{key[0]:g} g cm^2, noise {key[1]:g}: {key[2]}"
        print(f"| {name} | {n} | {pct(covered, n)} | {ident} | {pct(ident_cov, ident)} | {med(half_ident)} | "
              f"{med(half_all)} | {pct(boot_cov, n)} | {med(err_ident)} | "
              f"{f'{max(err_ident):.1f} %' if err_ident else '-'} | {med(err_all)} |")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("--multiple", type=float, default=None)
    ap.add_argument("--truths", default=None, help="A-B: only truths A..B")
    ap.add_argument("--wide", type=float, default=None, help="the identified half-width limit, fraction (0.10)")
    a = ap.parse_args()
    with open(a.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    if a.truths:
        t0, t1 = (int(x) for x in a.truths.split("-"))
        rows = [r for r in rows if t0 <= int(r["truth"]) <= t1]
    if not rows:
        raise SystemExit(f"{a.csv}: no rows")
    ranges = card_ranges()
    if a.wide:
        global WIDE
        WIDE = a.wide
    key = lambda r: (r["load_gcm2"], r["noise_counts"], r["truth"])
    cpu = {key(r): float(r["cpu_s"]) for r in rows}
    inadequate = {key(r) for r in rows if r["adequate"] == "0"}
    truths = sorted({int(r["truth"]) for r in rows})
    print(f"{len(cpu)} fits (truths {truths[0]}..{truths[-1]}); CPU per fit: median {statistics.median(cpu.values()):.1f} s, "
          f"largest {max(cpu.values()):.1f} s; flagged inadequate: {len(inadequate)}; "
          f"multiple: {a.multiple if a.multiple else 't95(B)'}; identified within +-{100 * WIDE:.0f} %")
    by_load = defaultdict(list)
    overall = defaultdict(list)
    for r in rows:
        by_load[(float(r["load_gcm2"]), float(r["noise_counts"]), r["constant"])].append(r)
        overall[r["constant"]].append(r)
    table("Per load and noise", by_load, ranges, a.multiple)
    table("Over every load and noise", overall, ranges, a.multiple)


if __name__ == "__main__":
    main()
