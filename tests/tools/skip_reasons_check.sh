#!/usr/bin/env bash
# Issue 39: ./test.sh prints each skipped test with its reason. A throwaway
# CTest project with a passing test, a script that skips (exit 77) and a
# GoogleTest-style skip; ctest writes its JUnit file, tests/skip_reasons.py
# must name both skipped tests with the reasons they printed, and not the
# passing one. Usage: skip_reasons_check.sh SOURCE_DIR
set -euo pipefail
src=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.21)
project(skips NONE)
enable_testing()
add_test(NAME passes COMMAND true)
add_test(NAME script_skips COMMAND sh -c "echo looking for chromium; echo 'chromium not installed (./setup.sh installs it)'; exit 77")
set_tests_properties(script_skips PROPERTIES SKIP_RETURN_CODE 77)
add_test(NAME gtest_skips COMMAND sh -c "echo '[ RUN      ] Video.Mp4'; echo 'video_test.cpp:24: Skipped'; echo 'ffmpeg not installed'; echo '[  SKIPPED ] Video.Mp4 (0 ms)'")
set_tests_properties(gtest_skips PROPERTIES SKIP_REGULAR_EXPRESSION "\\[  SKIPPED \\]")
CMAKE
cmake -S "$work" -B "$work/build" > /dev/null
ctest --test-dir "$work/build" --output-junit "$work/junit.xml" > /dev/null
out=$(/usr/bin/python3 "$src/tests/skip_reasons.py" "$work/junit.xml")
echo "$out"
grep -q "^2 tests skipped:" <<< "$out"
grep -Eq "^  script_skips +chromium not installed \(./setup.sh installs it\)$" <<< "$out"
grep -Eq "^  gtest_skips +ffmpeg not installed$" <<< "$out"
! grep -q passes <<< "$out"
# test.sh hands ctest's JUnit file to it.
grep -q 'skip_reasons.py' "$src/test.sh"
