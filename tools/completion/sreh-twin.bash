# bash completion for sreh-twin (issue 16). Debian's CLI11 2.1 has no
# completion generator, so this script asks the program itself: it runs
# `sreh-twin <subcommands so far> --help` and offers the subcommands and
# --options listed there, so it never goes stale when a command changes.
# Files are offered after options that take a path, and for run's SCENARIO
# (a file, or a folder of them: `run DIR --shard i/N`).
# Install: `cmake --install` puts it in share/bash-completion/completions;
# or `source tools/completion/sreh-twin.bash` in a shell.
_sreh_twin() {
  local cur prev words cword
  if declare -F _init_completion > /dev/null; then
    _init_completion || return
  else
    cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}
    words=("${COMP_WORDS[@]}") cword=$COMP_CWORD
  fi
  local prog=${words[0]} path=() i w
  # The subcommand path typed so far (words that are neither options nor their values).
  for ((i = 1; i < cword; i++)); do
    w=${words[i]}
    [[ $w == -* ]] && continue
    local subs
    subs=$("$prog" "${path[@]}" --help 2>/dev/null | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && /^  [a-z]/ { print $1 }')
    if grep -qx -- "$w" <<< "$subs"; then path+=("$w"); fi
  done
  local help
  help=$("$prog" "${path[@]}" --help 2>/dev/null) || return
  case $prev in
    --trace|--video|--frames|--report|--csv|--save-nvm|--load|--cycle|--iodd|--port-config|--token-file|--emit-scenario)
      COMPREPLY=($(compgen -f -- "$cur")); return ;;
    --shard) # run DIR / sweep: i/N typed by hand, or from the job array's environment
      COMPREPLY=($(compgen -W "auto auto/" -- "$cur")); return ;;
  esac
  if [[ $cur == -* ]]; then
    local opts
    opts=$(grep -oE '^ +(-[a-zA-Z],)?--[a-zA-Z0-9-]+' <<< "$help" | sed -E 's/^ +(-[a-zA-Z],)?//')
    COMPREPLY=($(compgen -W "$opts" -- "$cur"))
    return
  fi
  local subs
  subs=$(sed -n '/^Subcommands:/,$p' <<< "$help" | awk 'NR > 1 && /^  [a-z]/ { print $1 }')
  if [[ -n $subs ]]; then
    COMPREPLY=($(compgen -W "$subs" -- "$cur"))
  else
    COMPREPLY=($(compgen -f -- "$cur")) # positional: a scenario file, a folder
  fi
}
complete -F _sreh_twin sreh-twin
