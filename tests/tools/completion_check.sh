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
complete_words "" | grep -qx run || fail "no 'run' at the top level"
complete_words "" | grep -qx params || fail "no 'params' at the top level"
[ "$(complete_words pa)" = params ] || fail "'pa' does not complete to params"
complete_words params "" | grep -qx export || fail "no 'export' under params"
complete_words run --js | grep -qx -- --json || fail "run --js does not complete to --json"
complete_words params export --io | grep -qx -- --iodd || fail "params export --io"
complete_words --ver | grep -qx -- --version || fail "--ver"
echo "completion: subcommands and options offered"
