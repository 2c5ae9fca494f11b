#!/usr/bin/env bash
# Issue 39: ctest's lines stay readable: every test name at most 64
# characters (ctest pads every line to the longest) and unique.
# Usage: test_names_check.sh BUILD_DIR
set -euo pipefail
names=$(ctest --test-dir "$1" -N | sed -n 's/^ *Test *#[0-9]*: //p')
[ -n "$names" ]
long=$(awk 'length($0) > 64' <<< "$names")
if [ -n "$long" ]; then echo "test names over 64 characters:"; echo "$long"; exit 1; fi
dup=$(sort <<< "$names" | uniq -d)
if [ -n "$dup" ]; then echo "test names given twice:"; echo "$dup"; exit 1; fi
echo "$(wc -l <<< "$names") tests, the longest name $(awk '{ print length($0) }' <<< "$names" | sort -n | tail -1) characters"
