#!/bin/bash
# Sizing throughput before / after (issue 31): the 200-point grid and the
# 1000-point sweep of docs/performance-sizing.md with /usr/bin/time, on one
# or two sreh-twin binaries in one run, and whether their CSVs are the same
# byte for byte. CPU time (user + sys) is the cost on a shared machine; wall
# time counts only on an idle one (the load average is printed).
#   bench/sizing_throughput.sh BUILD/sreh-twin [OTHER/sreh-twin]
set -euo pipefail
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
L=0,1500,3000,4500,6000,7500,9000,10500,12000,15000
A=5,10,20,30,45,60,90,120,180,360
V=16,18,19,20,22,24,26,28,30,32
n=0
for bin in "$@"; do
  n=$((n + 1))
  echo "== $bin (load average: $(cut -d' ' -f1-3 /proc/loadavg))"
  /usr/bin/time -f "grid200: %e s wall, %U s user, %S s sys, %M kB" \
    "$bin" sweep --loads-gcm2 "$(seq -s, 0 750 14250)" --angles-deg 10,30,45,60,90,120,180,270,360,720 \
    --csv "$out/g200_$n.csv" --threads 2 > /dev/null
  /usr/bin/time -f "sweep1000: %e s wall, %U s user, %S s sys, %M kB" \
    "$bin" sweep --loads-gcm2 $L --angles-deg $A --voltages-V $V --csv "$out/s1000_$n.csv" --threads 2 > /dev/null
done
if [ "$n" = 2 ]; then
  cmp "$out/g200_1.csv" "$out/g200_2.csv" && cmp "$out/s1000_1.csv" "$out/s1000_2.csv" && echo "CSVs identical"
fi
