#!/usr/bin/env bash
# --stock-out DIR and --report FILE: the files appear, the analysis is in the state JSON,
# the report inlines the pictures; a mill block gives its pictures, mesh and height map.
set -u
ncvm=$1
golden=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

prog="$golden/stock/convex_arc_no_tnrc.nc"
setup="$golden/stock/convex_arc_no_tnrc.toml"
"$ncvm" run "$prog" --setup "$setup" --stock-out "$tmp/stock" --state "$tmp/state.json" --report "$tmp/r.html" >"$tmp/out" \
  || fail "run exit $?: $(cat "$tmp/out")"
for f in analysis.json profile.csv profile.svg deviation.svg revolved.png; do
  [ -s "$tmp/stock/$f" ] || fail "missing $f"
done
grep -q '"stock": {' "$tmp/state.json" || fail "no stock in the state"
grep -q 'stock: deviation max 0.33' "$tmp/out" || fail "summary line: $(cat "$tmp/out")"
grep -q '<svg' "$tmp/r.html" || fail "report without inline SVG"
grep -q 'data:image/png;base64,' "$tmp/r.html" || fail "report without inline PNG"
grep -q 'Deviation from the target' "$tmp/r.html" || fail "report without deviation table"
head -c 8 "$tmp/stock/revolved.png" | od -c | grep -q 'P   N   G' || fail "not a PNG"

# --report alone simulates into a temporary folder and removes it.
"$ncvm" run "$prog" --setup "$setup" --report "$tmp/r2.html" -q || fail "report-only exit $?"
grep -q 'data:image/png;base64,' "$tmp/r2.html" || fail "report-only without pictures"

# The mill model: a block cut by the program, its pictures and mesh.
printf '[stock]\nmin = [0, 0, -10]\nmax = [50, 50, 0]\n' >"$tmp/mill.toml"
"$ncvm" run "$golden/../cli/ok.nc" --setup "$tmp/mill.toml" --stock-out "$tmp/m" 2>"$tmp/err"; rc=$?
[ $rc = 0 ] || fail "mill stock exit $rc: $(cat "$tmp/err")"
for f in analysis.json top_view.png height_map.png stock.stl stock.hmap; do
  [ -s "$tmp/m/$f" ] || fail "mill: missing $f"
done
# No [stock]: a warning naming the section; the run goes on and nothing is written there
# (tests/cli/report.sh: the report says so).
printf '[machine]\nkind = "lathe"\n' >"$tmp/lathe.toml"
"$ncvm" run "$prog" --setup "$tmp/lathe.toml" --stock-out "$tmp/y" 2>"$tmp/err"; rc=$?
[ $rc = 0 ] && grep -q 'warning: --stock-out .*no stock in the setup (no \[stock\] section)' "$tmp/err" \
  || fail "no [stock]: exit $rc $(cat "$tmp/err")"
[ ! -e "$tmp/y" ] || fail "no [stock]: the folder was made"
echo "cli stock output: ok"
