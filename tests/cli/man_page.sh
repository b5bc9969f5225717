#!/usr/bin/env bash
# docs/man/ncvm.1 (the installed man page) keeps up with the command: every command that
# `ncvm --help` lists has its entry under COMMANDS, and the page renders without warnings.
#   man_page.sh NCVM MAN_PAGE
set -uo pipefail
ncvm=$1 page=$2
fail() { echo "FAIL: $*"; exit 1; }
commands=$("$ncvm" --help |
  awk 'tolower($0) ~ /^subcommands:/ { on = 1; next } /^$/ { on = 0 } on && /^  [a-z]/ { print $1 }')
[ -n "$commands" ] || fail "no commands found in ncvm --help"
for c in $commands; do
  awk '/^\.SH COMMANDS/ { on = 1; next } /^\.SH/ { on = 0 } on && /^\.B / { print $2 }' "$page" |
    grep -qx "$c" || fail "ncvm $c is not in $page (COMMANDS)"
done
warnings=$(groff -man -ww -z "$page" 2>&1)
[ -z "$warnings" ] || fail "groff: $warnings"
echo "man page: $(echo $commands | wc -w) commands, all described"
