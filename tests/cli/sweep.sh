#!/usr/bin/env bash
# ncvm sweep: the table, the clean combinations, --out folders, and bad --vary specs.
set -u
ncvm=$1
root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
ex="$root/examples/face-milling-g42"

"$ncvm" sweep "$ex/face-milling-g42-x150.nc" --setup "$ex/face-milling-g42.toml" --set stock.cell=0.5 \
  --vary tool_offsets.52.d_geometry=10,30 --vary tools.1.diameter=50,80 --out "$tmp/s" >"$tmp/out" \
  || fail "sweep exit $?: $(cat "$tmp/out")"
[ "$(grep -c '^| 10 \|^| 30 ' "$tmp/out")" = 4 ] || fail "four rows: $(cat "$tmp/out")"
grep -q '^| 10 | 80 | M30 | 0.0 | 0.0 |.*\*\*yes\*\*' "$tmp/out" || fail "D10 Ø80 clean: $(cat "$tmp/out")"
grep -q '^| 30 | 50 | alarm: PS0041' "$tmp/out" || fail "D30: PS0041: $(cat "$tmp/out")"
grep -q 'Nothing uncut: tool_offsets.52.d_geometry = 10, tools.1.diameter = 80.' "$tmp/out" || fail "summary"
[ -s "$tmp/s/sweep.md" ] || fail "no sweep.md"
[ -s "$tmp/s/tool_offsets.52.d_geometry=10_tools.1.diameter=80/top_view.png" ] || fail "no run folder"

"$ncvm" sweep "$ex/face-milling-g42.nc" --setup "$ex/face-milling-g42.toml" --vary x=1:0:1 2>"$tmp/err"; rc=$?
[ $rc = 2 ] || fail "bad range exit $rc"
"$ncvm" sweep "$root/tests/cli/ok.nc" --vary tools.1.diameter=5 2>"$tmp/err"; rc=$?
[ $rc = 2 ] && grep -q '\[stock\]' "$tmp/err" || fail "no stock: exit $rc $(cat "$tmp/err")"
echo "cli sweep: ok"
