#!/bin/bash
# Issue 12: `run` streams checks, failures and moves to temporaries unless
# --report keeps them in memory; both paths print the same bytes, --json and
# text, for a passing and a failing scenario.
# usage: run_stream_check.sh SREH_TWIN SCENARIO...
set -uo pipefail
bin=$1
shift
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for scenario in "$@"; do
  for json in --json ""; do
    "$bin" run "$scenario" $json > "$dir/streamed"
    a=$?
    "$bin" run "$scenario" $json --report "$dir/report" > "$dir/in_memory"
    b=$?
    rm -rf "$dir/report"
    [ "$a" = "$b" ] || { echo "exit $a streamed, $b in memory: $scenario $json"; exit 1; }
    [ -s "$dir/streamed" ] || { echo "no output: $scenario $json"; exit 1; }
    cmp "$dir/streamed" "$dir/in_memory" || { echo "bytes differ: $scenario $json"; exit 1; }
  done
done
echo "streamed and in-memory output identical"
