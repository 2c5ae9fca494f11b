#!/usr/bin/env bash
# CTest cli.bash_completion (issue 16): the completion script offers the
# subcommands and options that sreh-twin itself lists.
# usage: completion_check.sh SREH_TWIN SCRIPT
set -euo pipefail
tool=$1
source "$2"
complete_words() { # words... -> COMPREPLY for the last word
  COMP_WORDS=("$tool" "$@"); COMP_CWORD=$(( ${#COMP_WORDS[@]} - 1 )); COMPREPLY=()
  _sreh_twin
  printf '%s\n' "${COMPREPLY[@]}"
}
fail() { echo "completion: $*" >&2; exit 1; }
# offers WORD WORDS...: the completion of WORDS includes WORD. No pipe into
# grep -q: with pipefail its early exit would fail the pipeline by SIGPIPE.
offers() { local want=$1; shift; local got; got=$(complete_words "$@"); grep -qx -- "$want" <<< "$got"; }
offers run "" || fail "no 'run' at the top level"
offers params "" || fail "no 'params' at the top level"
[ "$(complete_words pa)" = params ] || fail "'pa' does not complete to params"
offers export params "" || fail "no 'export' under params"
offers --json run --js || fail "run --js does not complete to --json"
offers --iodd params export --io || fail "params export --io"
offers --version --ver || fail "--ver"
offers --shard run scenarios --sha || fail "run --sha does not complete to --shard"
offers auto run scenarios --shard "" || fail "run --shard offers no auto"
echo "completion: subcommands and options offered"
