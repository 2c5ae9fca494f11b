#!/usr/bin/env bash
# Output safety of every command (issue 12): one path rule for every output
# option, checked before the run; atomic writes that never follow a link;
# no temporaries left after SIGINT / SIGTERM (exit 130 / 143).
#   check_outputs.sh SREH_TWIN SOURCE_DIR WORK_DIR WITH_RENDER(0|1)
set -uo pipefail
twin=$1 src=$2 work=$3 render=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
scenario=$src/scenarios/t03_t05_t07_absolute_move.yaml
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
# expect RC REGEX CMD...: exit code and a stderr line matching REGEX.
expect() {
  local want=$1 regex=$2
  shift 2
  "$@" > out.txt 2> err.txt
  local rc=$?
  [ "$rc" = "$want" ] || fail "exit $rc, want $want: $* ($(cat err.txt))"
  [ -z "$regex" ] || grep -Eq -- "$regex" err.txt || fail "stderr does not match '$regex': $* ($(cat err.txt))"
}
leftovers() { find "$work" -name '.*tmp*' | grep -q . && fail "temporary files left: $(find "$work" -name '.*tmp*')"; }

# A symlink at the output is replaced, its target untouched.
echo precious > victim && ln -s victim link.csv
expect 0 "" "$twin" run "$scenario" --trace link.csv
[ "$(cat victim)" = precious ] || fail "--trace wrote through a symlink"
[ -L link.csv ] && fail "--trace did not replace the symlink"
# So is one planted at the old fixed temporary name.
echo precious > victim2 && ln -s victim2 t.csv.tmp
expect 0 "" "$twin" run "$scenario" --trace t.csv
[ "$(cat victim2)" = precious ] || fail "--trace wrote through <out>.tmp"
# An output that is an input is refused, the input kept.
cp "$scenario" s.yaml && cp s.yaml s.orig
expect 2 "--trace s.yaml: is the input file" "$twin" run s.yaml --trace s.yaml
expect 2 "--save-nvm ./s.yaml: is the input file" "$twin" run s.yaml --save-nvm ./s.yaml
cmp -s s.yaml s.orig || fail "the scenario was overwritten"
# The parent folder must exist; nothing is created on the way.
expect 2 "--trace no/t.csv: the folder 'no' does not exist" "$twin" run "$scenario" --trace no/t.csv
expect 2 "--csv nodir/s.csv" "$twin" sweep --loads-gcm2 100 --angles-deg 90 --cycles 1 --csv nodir/s.csv
[ -e missing ] && fail "a missing --report parent was created"
# File options refuse folders; a trailing slash names a folder.
mkdir -p adir
expect 2 "--trace adir: is a folder" "$twin" run "$scenario" --trace adir
expect 2 "--trace t.csv/: names a folder" "$twin" run "$scenario" --trace t.csv/
expect 2 "--iodd adir: is a folder" "$twin" params export --iodd adir
expect 2 "--iodd s.yaml/: names a folder" "$twin" params export --iodd s.yaml/
if [ "$render" = 1 ]; then # reports need the renders
  expect 2 "--report missing/rep: the folder 'missing' does not exist" \
    "$twin" size --angle-deg 90 --load-gcm2 100 --cycles 1 --report missing/rep
  expect 2 "--report missing/rep" "$twin" sweep --loads-gcm2 100 --angles-deg 90 --cycles 1 --csv s.csv --report missing/rep
  expect 0 "" "$twin" run "$scenario" --report rep/
  [ -f rep/index.html ] || fail "--report rep/ wrote no index.html"
  expect 0 "" "$twin" size --angle-deg 90 --load-gcm2 100 --cycles 1 --report srep/
  expect 2 "--video adir: is a folder" "$twin" run "$scenario" --video adir
  touch adir/x
  expect 2 "--frames adir: exists and is not empty" "$twin" run "$scenario" --frames adir
  expect 2 "--frames nope/f: the folder 'nope' does not exist" "$twin" run "$scenario" --frames nope/f
  expect 2 "--size 10x10: width and height must be 16 .. 4096" "$twin" run "$scenario" --video v.mp4 --size 10x10
  expect 2 "--size 20000x20000" "$twin" run "$scenario" --video v.mp4 --size 20000x20000
fi
leftovers
# SIGTERM / SIGINT: exit 143 / 130, no output, no temporaries.
long=$src/tests/tools/data/long_wait.yaml
timeout -s TERM --preserve-status 2 "$twin" run "$long" --trace sig.csv --save-nvm sig.nvm > /dev/null 2> err.txt
rc=$?
[ "$rc" = 143 ] || fail "SIGTERM: exit $rc, want 143 ($(cat err.txt))"
timeout -s INT --preserve-status 2 "$twin" run "$long" --trace sig.csv > /dev/null 2> err.txt
rc=$?
[ "$rc" = 130 ] || fail "SIGINT: exit $rc, want 130 ($(cat err.txt))"
# --json spools checks and moves in $TMPDIR (nameless files): nothing there after a signal, no answer.
mkdir spooldir
TMPDIR=$PWD/spooldir timeout -s TERM --preserve-status 2 "$twin" run "$long" --json > sig.json 2> err.txt
rc=$?
[ "$rc" = 143 ] || fail "SIGTERM with --json: exit $rc, want 143 ($(cat err.txt))"
[ -s sig.json ] && fail "an interrupted --json run printed an answer"
[ -z "$(ls -A spooldir)" ] || fail "--json left temporaries: $(ls -A spooldir)"
rm -rf spooldir sig.json
if [ "$render" = 1 ]; then
  timeout -s TERM --preserve-status 4 "$twin" run "$long" --video sig.mp4 --frames sigframes --size 64x48 \
    > /dev/null 2> err.txt
  rc=$?
  [ "$rc" = 143 ] || fail "SIGTERM during a render: exit $rc, want 143 ($(cat err.txt))"
  [ -e sig.mp4 ] || [ -e sigframes ] && fail "an interrupted render left output"
  find . -name '*.log' | grep -q . && fail "ffmpeg log left: $(find . -name '*.log')"
fi
[ -e sig.csv ] || [ -e sig.nvm ] && fail "an interrupted run left output"
leftovers
[ "$fails" = 0 ] && echo "all output checks held"
exit $((fails > 0))
