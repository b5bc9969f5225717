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
echo "cli exit codes: ok"
