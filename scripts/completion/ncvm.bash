# bash completion for ncvm (installed to share/bash-completion/completions/ncvm).
# The subcommands and their options are read from `ncvm --help` and `ncvm COMMAND --help`,
# so this file never falls behind the command line; files and folders complete as usual.
_ncvm_words() {
  # $1: the subcommand or empty. Options (--x, -x) of its help, or the subcommand names.
  local help
  if [[ -n $1 ]]; then
    help=$("${_ncvm_bin:-ncvm}" "$1" --help 2>/dev/null) || return
    grep -oE '(^|[ ,])--?[A-Za-z][A-Za-z0-9-]*' <<<"$help" | tr -d ' ,' | sort -u
  else
    help=$("${_ncvm_bin:-ncvm}" --help 2>/dev/null) || return
    awk 'tolower($0) ~ /^subcommands:/ { on = 1; next } /^$/ { on = 0 } on && /^  [a-z]/ { print $1 }' <<<"$help"
  fi
}

_ncvm() {
  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]} sub="" k
  local _ncvm_bin=${COMP_WORDS[0]}
  for ((k = 1; k < COMP_CWORD; k++)); do
    [[ ${COMP_WORDS[k]} != -* ]] && { sub=${COMP_WORDS[k]}; break; }
  done
  if [[ -z $sub ]]; then
    mapfile -t COMPREPLY < <(compgen -W "$(_ncvm_words '') --help --version" -- "$cur")
    return
  fi
  case $prev in
    --set | --vary | --port | --bind | --jobs | -j | --timeout | --lock-wait | --max-*)
      return ;;  # a value: nothing to offer
    --lib | --root | --out | --stock-out)
      mapfile -t COMPREPLY < <(compgen -d -- "$cur")
      return ;;
  esac
  if [[ $cur == -* ]]; then
    mapfile -t COMPREPLY < <(compgen -W "$(_ncvm_words "$sub")" -- "$cur")
  else
    mapfile -t COMPREPLY < <(compgen -f -- "$cur")
  fi
}
complete -o filenames -o bashdefault -F _ncvm ncvm
