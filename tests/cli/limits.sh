#!/usr/bin/env bash
# Limits seen from the command line: the trace size limit (PS9006) ends the run with an
# alarm, exit status 3, and leaves a trace of whole JSON lines that ends with the alarm;
# a program file over limits.max_file_bytes is PS9005 at line 1, exit status 3.
set -u
ncvm=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

printf 'O0001\nG0X1.\nG0X2.\nG0X3.\nG0X4.\nM30\n' >"$tmp/moves.nc"
"$ncvm" run "$tmp/moves.nc" --trace "$tmp/t.jsonl" --state "$tmp/s.json" --set limits.max_trace_bytes=300 >"$tmp/out"
rc=$?
[ $rc = 3 ] || fail "trace limit: exit $rc"
grep -q 'PS9006 TRACE LIMIT REACHED' "$tmp/out" || fail "trace limit alarm: $(cat "$tmp/out")"
python3 - "$tmp/t.jsonl" "$tmp/s.json" <<'PY' || fail "trace after the limit"
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
assert lines[-1]["type"] == "alarm" and lines[-1]["code"] == "PS9006", lines[-1]
assert sum(l["type"] == "move" for l in lines) < 4, "the run went on after the limit"
s = json.load(open(sys.argv[2]))
assert s["alarm"]["code"] == "PS9006" and s["end"] == "alarm", s["alarm"]
PY

# The dynamic time model holds cutting moves in its look-ahead when the limit comes: they do
# not reach the trace after it (nor throw again).
printf 'O0002\nG1F1000.\n' >"$tmp/cut.nc"
for k in $(seq 1 2000); do echo "X$k.Y$((k % 7))." >>"$tmp/cut.nc"; done
echo M30 >>"$tmp/cut.nc"
"$ncvm" run "$tmp/cut.nc" --trace "$tmp/c.jsonl" --set limits.max_trace_bytes=20000 \
  --set timing.model=dynamic >"$tmp/out"
rc=$?
[ $rc = 3 ] || fail "trace limit with held moves: exit $rc $(cat "$tmp/out")"
tail -1 "$tmp/c.jsonl" | grep -q '"code":"PS9006"' || fail "trace limit with held moves: no alarm line"
[ "$(grep -c '"code":"PS9006"' "$tmp/c.jsonl")" = 1 ] || fail "trace limit with held moves: the alarm twice"

"$ncvm" run "$tmp/moves.nc" --set limits.max_file_bytes=10 >"$tmp/out"
rc=$?
[ $rc = 3 ] || fail "file size: exit $rc"
grep -qE 'moves.nc:1:1: PS9005 PROGRAM TOO LARGE \([0-9]+ bytes; limits.max_file_bytes = 10\)' "$tmp/out" ||
  fail "file size alarm: $(cat "$tmp/out")"
echo "limits: trace size PS9006 and file size PS9005 alarm cleanly"
