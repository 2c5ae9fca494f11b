#!/bin/bash
# Issue 12: `run` streams checks, failures and moves to temporaries, and
# with --report hands them to the report's recorder as well: the output is
# the same bytes with and without --report, --json and text, for a passing
# and a failing scenario. (Streamed = in-memory bytes: the unit tests
# ResultJsonStream.StreamedBytesEqualTheInMemoryJson.)
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
    "$bin" run "$scenario" $json --report "$dir/report" > "$dir/with_report"
    b=$?
    rm -rf "$dir/report"
    [ "$a" = "$b" ] || { echo "exit $a without --report, $b with: $scenario $json"; exit 1; }
    [ -s "$dir/streamed" ] || { echo "no output: $scenario $json"; exit 1; }
    if [ -n "$json" ]; then # wall_s and real_time_factor are measured: compare the rest
      /usr/bin/python3 "$(dirname "$0")/strip_timing.py" "$dir/streamed" > "$dir/streamed.det" || exit 1
      /usr/bin/python3 "$(dirname "$0")/strip_timing.py" "$dir/with_report" > "$dir/with_report.det" || exit 1
      cmp "$dir/streamed.det" "$dir/with_report.det" || { echo "bytes differ: $scenario $json"; exit 1; }
    else
      cmp "$dir/streamed" "$dir/with_report" || { echo "bytes differ: $scenario $json"; exit 1; }
    fi
  done
done
echo "output identical with and without --report"
