#!/usr/bin/env bash
# The command's contract: exit 0 on a normal end, 3 on an alarm (with the alarm line in
# FILE:LINE:COL: CODE message (Nnnn) form), 2 on a usage or setup error.
set -u
ncvm=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$ncvm" run "$dir/ok.nc" --state "$tmp/state.json" --trace "$tmp/trace.jsonl" >"$tmp/out" || fail "ok.nc exit $?"
grep -q '"end": "M30"' "$tmp/state.json" || fail "state end"
[ "$(grep -c '"type":"move"' "$tmp/trace.jsonl")" = 2 ] || fail "two moves in the trace"

"$ncvm" run "$dir/alarm.nc" >"$tmp/out"; rc=$?
[ $rc = 3 ] || fail "alarm.nc exit $rc"
grep -qE 'alarm.nc:3:[0-9]+: PS0112 ZERO DIVIDE \(N30\)' "$tmp/out" || fail "alarm line: $(cat "$tmp/out")"

"$ncvm" run "$dir/ok.nc" --set nonsense.key=1 2>"$tmp/err"; rc=$?
[ $rc = 2 ] || fail "bad --set exit $rc"
"$ncvm" run "$dir/missing.nc" 2>"$tmp/err"; rc=$?
[ $rc = 2 ] || fail "missing file exit $rc"
"$ncvm" run 2>"$tmp/err"; rc=$?
[ $rc = 2 ] || fail "no arguments exit $rc"

"$ncvm" check "$dir/alarm.nc" >"$tmp/out"; rc=$?
[ $rc = 0 ] || fail "check of a program without static errors exit $rc"
# A file without program text is an alarm (PS9008 with file and line), in run and check; bytes
# after the closing '%' are not read, and text there is named by a warning in both.
: >"$tmp/empty.nc"
"$ncvm" run "$tmp/empty.nc" >"$tmp/out" 2>"$tmp/err"; rc=$?
[ $rc = 3 ] || fail "empty file exit $rc"
grep -qE 'empty.nc:1:1: PS9008 NO PROGRAM IN FILE' "$tmp/out" || fail "empty file alarm: $(cat "$tmp/out")"
printf '%%\n' >"$tmp/percent.nc"
"$ncvm" check "$tmp/percent.nc" >"$tmp/out"; rc=$?
[ $rc = 3 ] || fail "check of '%' alone exit $rc"
printf '%%\nO0001\nG00 X1.\nM30\n%%\n\032' >"$tmp/dos.nc"
"$ncvm" check "$tmp/dos.nc" >"$tmp/out" 2>"$tmp/err"; rc=$?
[ $rc = 0 ] || fail "check with a DOS EOF after the closing %: exit $rc $(cat "$tmp/out")"
[ ! -s "$tmp/err" ] || fail "DOS EOF after the closing % warned: $(cat "$tmp/err")"
printf 'O0001\nG00 X1.\nM30\n%%\n\032' >"$tmp/trailing.nc"
"$ncvm" run "$tmp/trailing.nc" >"$tmp/out"; rc=$?
[ $rc = 0 ] || fail "only a trailing %: exit $rc"
printf '%%\nO0001\nM30\n%%\nO0002\n' >"$tmp/after.nc"
"$ncvm" check "$tmp/after.nc" >"$tmp/out" 2>"$tmp/err" || fail "check with text after the closing %"
grep -q "after.nc:5: text after the closing '%' is not read" "$tmp/err" || fail "no warning: $(cat "$tmp/err")"
echo "cli exit codes: ok"
