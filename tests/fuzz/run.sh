#!/usr/bin/env bash
# Fuzzing (issue 12): builds the libFuzzer targets with clang (ASan + UBSan)
# in build-fuzz/ and runs each one, seeded with its committed corpus
# (tests/fuzz/corpus/<target>) and the shipped scenarios. New inputs go to a
# scratch folder; the committed corpus is only read.
#   tests/fuzz/run.sh                   every target for 20 s (CI)
#   tests/fuzz/run.sh 600 scenario      one target for 600 s
#   SREH_FUZZ_RUNS=10000000 tests/fuzz/run.sh 0 isdu   a number of executions instead of time
#   SREH_FUZZ_TIMEOUT=60 ...            per-input timeout in s (default 10; long runs under nice on a
#                                       loaded machine see inputs of 0.1 s descheduled for > 10 s)
#   SREH_FUZZ_MERGE=1 ...               afterwards merge what was found into the committed corpus
#                                       (edge coverage only, -use_counters=0, to keep it small)
# A crash, leak, sanitizer report, timeout (10 s unless SREH_FUZZ_TIMEOUT) or out-of-memory (2 GB)
# fails the script (exit 1); the reproducer is left in build-fuzz/findings/.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$PWD
seconds=${1:-20}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(pd_codec isdu scenario load modbus http_body)
build=build-fuzz
log=$build/fuzz-build.log
mkdir -p "$build"
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSREH_FUZZ=ON \
  -DSREH_BUILD_TESTS=OFF -DSREH_BUILD_BENCH=OFF -DSREH_WITH_RENDER=OFF -DSREH_WITH_PYTHON=OFF > "$log" 2>&1 || { cat "$log"; exit 1; }
cmake --build "$build" -j"$(nproc)" --target $(printf '%s_fuzz ' "${targets[@]}") >> "$log" 2>&1 ||
  { tail -50 "$log"; exit 1; }
mkdir -p "$build/findings"
for t in "${targets[@]}"; do
  corpus=tests/fuzz/corpus/$t
  scratch=$(mktemp -d "$PWD/$build/findings/$t.XXXXXX")
  seeds=("$corpus")
  case $t in
    scenario) seeds+=(scenarios tests/scenarios/bad) ;;
    load) seeds+=(tests/sizing/data) ;;
  esac
  budget=(-max_total_time="$seconds")
  [ -n "${SREH_FUZZ_RUNS:-}" ] && budget=(-runs="$SREH_FUZZ_RUNS")
  echo "fuzz $t: ${budget[*]}"
  (cd "$build/findings" && ASAN_OPTIONS=detect_leaks=1 "../tests/fuzz/${t}_fuzz" "${budget[@]}" -timeout="${SREH_FUZZ_TIMEOUT:-10}" \
     -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 "$scratch" "${seeds[@]/#/$root/}") \
     > "$build/findings/$t.log" 2>&1 || { tail -60 "$build/findings/$t.log"; echo "fuzz $t: FAILED"; exit 1; }
  grep -E "stat::number_of_executed_units|Done [0-9]+ runs" "$build/findings/$t.log" | tail -2
  if [ -n "${SREH_FUZZ_MERGE:-}" ]; then
    mkdir -p "$corpus"
    "$build/tests/fuzz/${t}_fuzz" -merge=1 -use_counters=0 -max_len=16384 "$corpus" "$scratch" > /dev/null 2>&1
  fi
  rm -rf "$scratch"
done
echo "fuzz: all targets clean"
