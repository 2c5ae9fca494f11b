#!/bin/bash
# The coverage benchmark of issue 36 (docs/calibration.md "Coverage"), one
# command: truths drawn from the card's ranges for the five default
# constants, the plan's moves 0, 1, 2 and 7 (fast out and back: the load
# rings; near full speed: viscous friction; a crawl: Coulomb) at 0, 5000 and
# 15000 g cm^2, with and without +-1 count of noise, each log fitted from
# the card; then the summary per constant. One process, niced, two
# threads; each fit is written as it ends, so a stopped run keeps its
# truths (truth by truth, every load and noise).
#   bench/calibration_coverage.sh BUILD [TRUTHS [FIRST]] > summary.md
# (BUILD: the build folder; TRUTHS 20 by default: 120 fits, about 90 min
# of CPU at a median 43 s a fit; the CSV goes to BUILD/calibration_coverage.csv.)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$1
truths=${2:-20}
first=${3:-0}
csv="$build/calibration_coverage.csv"
rm -f "$csv"
nice -n 10 "$build/bench/calibration_coverage_bench" --truths "$truths" --first "$first" --loads 0,5000,15000 \
  --noise 0,1 --moves 0,1,2,7 --starts 3 --threads 2 --csv "$csv" >&2
/usr/bin/python3 "$here/calibration_coverage.py" "$csv"
