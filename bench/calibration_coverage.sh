#!/bin/bash
# The coverage benchmark of issue 36 (docs/calibration.md "Coverage"), one
# command: truths drawn from the card's ranges for the five default
# constants, the plan's moves 0, 1, 2 and 7 (fast out and back: the load
# rings; near full speed: viscous friction; a crawl: Coulomb) at 0, 5000 and
# 15000 g cm^2, with and without +-1 count of noise, each log fitted from
# the card as `calibrate` does (three starts, the bootstrap's three
# refits); then the summary per constant. One process, nice 19, two
# threads; each fit is written as it ends, so a stopped run keeps its
# truths (truth by truth, every load and noise).
#   bench/calibration_coverage.sh BUILD [TRUTHS [FIRST]] > summary.md
# (BUILD: the build folder; TRUTHS 20 by default: 120 fits, 40-100 s of
# CPU a fit with the bootstrap, about 2.5 hours of CPU; the CSV goes to
# BUILD/calibration_coverage.csv.)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$1
truths=${2:-20}
first=${3:-0}
csv="$build/calibration_coverage.csv"
rm -f "$csv"
nice -n 19 "$build/bench/calibration_coverage_bench" --truths "$truths" --first "$first" --loads 0,5000,15000 \
  --noise 0,1 --moves 0,1,2,7 --starts 3 --threads 2 --csv "$csv" >&2
/usr/bin/python3 "$here/calibration_coverage.py" "$csv"
