#!/bin/bash
# Measures a build (docs/performance-ci.md): a compiler and linker launcher
# that appends "wall user sys maxRSS-kB cc|link output" per command to
# $SREH_TIME_LOG. Use it on a clean build tree without ccache:
#   cmake -B build-timed ... -DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/cmake/time-launcher.sh \
#         -DCMAKE_C_COMPILER_LAUNCHER=$PWD/cmake/time-launcher.sh -DCMAKE_CXX_LINKER_LAUNCHER=$PWD/cmake/time-launcher.sh
#   SREH_TIME_LOG=$PWD/times.log cmake --build build-timed -j2
#   awk '{cpu += $2 + $3} END {print cpu}' times.log     # CPU seconds of the whole build
log=${SREH_TIME_LOG:?set SREH_TIME_LOG to the log file}
out=?
prev=
for a in "$@"; do
  [ "$prev" = "-o" ] && out=$a
  prev=$a
done
kind=cc
case " $* " in *" -c "*) ;; *) kind=link ;; esac
exec /usr/bin/time -a -o "$log" -f "%e %U %S %M $kind $out" "$@"
