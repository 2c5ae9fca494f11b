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
#   SREH_FUZZ_BUILD=build-asan ...      use that build (configured with -DSREH_FUZZ=ON: ./test.sh --sanitize
#                                       makes one, CI) instead of configuring build-fuzz/
#   SREH_FUZZ_JOBS=1 ...                targets one after another (default: one per CPU, side by side)
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
build=${SREH_FUZZ_BUILD:-build-fuzz}
case $build in /*) ;; *) build=$root/$build ;; esac
log=$build/fuzz-build.log
mkdir -p "$build"
if [ -z "${SREH_FUZZ_BUILD:-}" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSREH_FUZZ=ON \
    -DSREH_BUILD_TESTS=OFF -DSREH_BUILD_BENCH=OFF -DSREH_WITH_RENDER=OFF -DSREH_WITH_PYTHON=OFF > "$log" 2>&1 || { cat "$log"; exit 1; }
elif ! grep -q "^SREH_FUZZ:BOOL=ON" "$build/CMakeCache.txt" 2>/dev/null; then
  echo "SREH_FUZZ_BUILD=$build: not a build configured with -DSREH_FUZZ=ON (./test.sh --sanitize makes one)" >&2
  exit 2
fi
cmake --build "$build" -j"$(nproc)" --target $(printf '%s_fuzz ' "${targets[@]}") >> "$log" 2>&1 ||
  { tail -50 "$log"; exit 1; }
mkdir -p "$build/findings"
# One target: its own scratch folder and log; the reproducer stays in findings/.
fuzz_one() {
  local t=$1 corpus=tests/fuzz/corpus/$1 scratch
  scratch=$(mktemp -d "$build/findings/$t.XXXXXX")
  local seeds=("$corpus")
  case $t in
    scenario) seeds+=(scenarios tests/scenarios/bad) ;;
    load) seeds+=(tests/sizing/data) ;;
  esac
  local budget=(-max_total_time="$seconds")
  [ -n "${SREH_FUZZ_RUNS:-}" ] && budget=(-runs="$SREH_FUZZ_RUNS")
  echo "fuzz $t: ${budget[*]}"
  (cd "$build/findings" && ASAN_OPTIONS=detect_leaks=1 "../tests/fuzz/${t}_fuzz" "${budget[@]}" -timeout="${SREH_FUZZ_TIMEOUT:-10}" \
     -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 "$scratch" "${seeds[@]/#/$root/}") \
     > "$build/findings/$t.log" 2>&1 || { tail -60 "$build/findings/$t.log"; echo "fuzz $t: FAILED"; return 1; }
  grep -E "stat::number_of_executed_units|Done [0-9]+ runs" "$build/findings/$t.log" | tail -2 | sed "s/^/$t: /"
  if [ -n "${SREH_FUZZ_MERGE:-}" ]; then
    mkdir -p "$corpus"
    "$build/tests/fuzz/${t}_fuzz" -merge=1 -use_counters=0 -max_len=16384 "$corpus" "$scratch" > /dev/null 2>&1
  fi
  rm -rf "$scratch"
}
# Targets run side by side, one per CPU (SREH_FUZZ_JOBS): each fuzzer is
# single-threaded, so CI's budget is spent on every core.
jobs=${SREH_FUZZ_JOBS:-$(nproc)}
failed=0
running=0
for t in "${targets[@]}"; do
  if [ "$running" -ge "$jobs" ]; then
    wait -n || failed=1
    running=$((running - 1))
  fi
  fuzz_one "$t" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || failed=1
  running=$((running - 1))
done
[ "$failed" -eq 0 ] || { echo "fuzz: a target FAILED (log and reproducer in $build/findings/)"; exit 1; }
echo "fuzz: all targets clean"
