#!/usr/bin/env bash
# A stock analysis that measured nothing reads "not measured" with the reason, never a pass:
# O0402 with its stock setup and a [target] block range that runs no feed move (N10).
# The summary, analysis.json, the state (what the viewer's panel shows), the HTML report and
# the sweep table.
set -u
ncvm=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; cat "$tmp/out" 2>/dev/null; exit 1; }
L="$src/examples/lathe-cycles"
args=("$L/g71-g70-rough-turning.nc" --setup "$L/setup.toml" --setup "$L/stock-o0402.toml" --set target.blocks=N10)

"$ncvm" run "${args[@]}" --stock-out "$tmp/stock" --state "$tmp/state.json" --report "$tmp/r.html" >"$tmp/out" ||
  fail "run exit $?"
grep -q 'stock: deviation not measured (no feed move of the target.s blocks N10..N10 ran' "$tmp/out" ||
  fail "summary does not say not measured"
grep -qE '100\.0 %|deviation max' "$tmp/out" && fail "summary shows a pass"
python3 - "$tmp/stock/analysis.json" "$tmp/state.json" <<'PY' || fail "analysis.json / state"
import json, sys
a = json.load(open(sys.argv[1]))["deviation"]
s = json.load(open(sys.argv[2]))["stock"]["deviation"]
for d in (a, s):
    assert d["samples"] == 0 and d["measured"] is False, d
    assert d["in_tolerance"] is None and d["max"] is None, d
    assert "N10" in d["not_measured"], d
PY
grep -q 'Deviation not measured (no feed move' "$tmp/r.html" || fail "report does not say not measured"
grep -q '100.0 %' "$tmp/r.html" && fail "report shows 100.0 %"

"$ncvm" sweep "${args[@]}" --vary target.tolerance=0.001,0.002 >"$tmp/out" || fail "sweep exit $?"
[ "$(grep -c 'not measured' "$tmp/out")" -ge 2 ] || fail "sweep table does not say not measured"
echo ok
