#!/usr/bin/env bash
# What a newcomer reads: an unknown command named with the nearest one, an empty program
# named by its file, --stock-out failures in words, --help with FILE/DIR, exit codes and an
# example, and control bytes of a program escaped in alarm lines.
set -u
ncvm=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; cat "$tmp/err" "$tmp/out" 2>/dev/null; exit 1; }

"$ncvm" rnu "$dir/ok.nc" >"$tmp/out" 2>"$tmp/err"; rc=$?
[ $rc = 2 ] || fail "unknown command: exit $rc"
grep -q '^ncvm: unknown command rnu (did you mean run?)$' "$tmp/err" || fail "unknown command message"

: >"$tmp/empty.nc"
"$ncvm" run "$tmp/empty.nc" >"$tmp/out" 2>"$tmp/err"; rc=$?
# An empty file is an alarm with its file and line (issue 24.1), so it names the file too.
[ $rc = 3 ] || fail "empty program: exit $rc"
grep -q "$tmp/empty.nc:1:1: PS9008" "$tmp/out" || fail "the empty file's alarm without the file"

printf '[stock]\ndiameter = 50\nlength = 60\n[machine]\nkind = "lathe"\n' >"$tmp/stock.toml"
: >"$tmp/afile"
"$ncvm" run "$dir/ok.nc" --setup "$tmp/stock.toml" --stock-out "$tmp/afile/sub" >"$tmp/out" 2>"$tmp/err"; rc=$?
[ $rc = 2 ] || fail "--stock-out under a file: exit $rc"
grep -q "^ncvm: --stock-out $tmp/afile/sub: cannot create: Not a directory" "$tmp/err" || fail "--stock-out message"
grep -qi 'filesystem error' "$tmp/err" && fail "raw std::filesystem error"

"$ncvm" run --help >"$tmp/out" 2>&1 || fail "--help exit $?"
grep -q 'TEXT' "$tmp/out" && fail "--help shows TEXT"
grep -qE '^  --setup FILE' "$tmp/out" || fail "--setup FILE"
grep -qE '^  --lib DIR' "$tmp/out" || fail "--lib DIR"
grep -qE '^  --stock-out DIR' "$tmp/out" || fail "--stock-out DIR"
grep -q '^Exit status: 0 ' "$tmp/out" || fail "--help without exit codes"
grep -q '^Example:' "$tmp/out" || fail "--help without an example"
"$ncvm" --help >"$tmp/out" 2>&1 || fail "ncvm --help exit $?"
grep -q '^Exit status: 0 ' "$tmp/out" || fail "ncvm --help without exit codes"

printf 'O1\n#3000=1(BAD\033[2J\007)\nM30\n' >"$tmp/ctl.nc"
"$ncvm" run "$tmp/ctl.nc" >"$tmp/out" 2>"$tmp/err"; rc=$?
[ $rc = 3 ] || fail "control bytes: exit $rc"
LC_ALL=C grep -q $'\033' "$tmp/out" && fail "ESC printed raw in the alarm line"
grep -qF 'BAD\x1B[2J\x07' "$tmp/out" || fail "control bytes not escaped as \\xNN"
"$ncvm" check "$tmp/ctl.nc" >"$tmp/out" 2>"$tmp/err"
LC_ALL=C grep -q $'\033' "$tmp/out" && fail "ESC printed raw by check"
echo ok
