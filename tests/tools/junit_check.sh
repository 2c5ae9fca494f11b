#!/bin/bash
# Issue 29: `run FILE|DIR --junit FILE` for CI servers: valid against the
# common JUnit schema (xmllint), one testcase per scenario, a failure with
# the failing step's line for the failing one; the exit codes are run's.
# Issue 39: logs with real line breaks, the failure naming the error code,
# read back by Debian's python3-junitparser (junit_read.py).
# usage: junit_check.sh SREH_TWIN PASSING.yaml FAILING.yaml BLOCKED.yaml
set -euo pipefail
bin=$1
passing=$2
failing=$3
blocked=$4
here=$(dirname "$(realpath "$0")")
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
mkdir "$dir/folder"
cp "$passing" "$dir/folder/a_passes.yaml"
cp "$failing" "$dir/folder/b_fails.yaml"
cp "$blocked" "$dir/folder/c_blocked.yaml"
status=0
"$bin" run "$dir/folder" --junit "$dir/folder.xml" > /dev/null || status=$?
[ "$status" = 1 ] || fail "run DIR with one failing file: exit $status, want 1"
xmllint --noout --schema "$here/junit.xsd" "$dir/folder.xml" || fail "not valid JUnit XML"
[ "$(grep -c '<testcase ' "$dir/folder.xml")" = 3 ] || fail "want 3 testcases"
[ "$(grep -c '<failure ' "$dir/folder.xml")" = 2 ] || fail "want 2 failures"
grep -q '<testsuites name="sreh-twin" tests="3" failures="2" errors="0"' "$dir/folder.xml" || fail "suite counts"
/usr/bin/python3 "$here/junit_read.py" "$dir/folder.xml" || fail "junitparser did not read it as written"
grep -q 'name="b_fails"' "$dir/folder.xml" || fail "testcase named after the file"
grep -qE '<failure message="step [0-9]+ \(line [0-9]+\)' "$dir/folder.xml" || fail "failure names the step and line"
"$bin" run "$passing" --junit "$dir/one.xml" > /dev/null || fail "run FILE --junit on a passing scenario"
xmllint --noout --schema "$here/junit.xsd" "$dir/one.xml" || fail "FILE: not valid JUnit XML"
grep -q 'tests="1" failures="0"' "$dir/one.xml" || fail "FILE: counts"
echo "JUnit XML valid: 3 testcases, 2 failures, read back by junitparser"
