#!/usr/bin/env bash
# --report FILE.html on real examples: every part of the page is there and says what it
# measured, with units: the time charts (labelled modelled or length / feed), the tool path
# (mill plan view, lathe half-section), the G31 moves and the offsets the program wrote, the
# height map with its colour scale, and no stock part (said so) when the setup has none.
set -u
ncvm=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
has() { grep -q -- "$2" "$1" || fail "$1: no '$2'"; }
count() { grep -o -- "$2" "$1" | wc -l; }

# The probe example: mills a bore, centres on it with 12 G31 moves, writes G54 X and Y.
probe="$src/examples/probe-milled-bore"
"$ncvm" run "$probe/bore-o5001.nc" --setup "$probe/bore-o5001.toml" --stock-out "$tmp/stock" \
  --report "$tmp/p.html" -q || fail "probe run exit $?"
r="$tmp/p.html"
has "$r" '<tr><th class="l">units</th><td class="l">mm'
has "$r" 'path length</th><td class="l">rapid 217.453 mm / feed 410.555 mm'
# Time: the simple model is not a modelled time, and says so; bars by kind, tool, operation.
has "$r" 'cycle time</th><td class="l">230.15 s (0:03:50.15), length &divide; feed, not modelled'
has "$r" 'length &divide; feed</strong>: <strong>not modelled</strong>'
[ "$(count "$r" '<svg xmlns="http://www.w3.org/2000/svg" class="chart"')" = 3 ] || fail "not 3 time charts"
has "$r" '<title>cutting: 229.79 s</title>'
has "$r" '<title>T20: 201.90 s</title>'
has "$r" 'time, length ÷ feed (s)'
# Tool path: a plan view with mm axes, feeds, rapids and the G31 moves, 6 touch points.
has "$r" '<svg xmlns="http://www.w3.org/2000/svg" class="toolpath"'
has "$r" '>X (mm)</text>'
has "$r" '>Y (mm)</text>'
for kind in feed rapid probe; do has "$r" "<path class=\"$kind\" d=\"M"; done
[ "$(count "$r" '<circle class="probe-hit"')" = 6 ] || fail "not 6 touch points drawn"
[ "$(count "$r" '<circle class="probe-miss"')" = 6 ] || fail "not 6 G31 without touch drawn"
has "$r" 'Plan view from above (X right, Y up), mm'
# Probing: the 12 G31 moves with their latched positions, the two G54 writes of O5001.
has "$r" '12 G31 moves, 6 touched'
[ "$(grep -c '<td class="l">touch</td>' "$r")" = 6 ] || fail "not 6 touch rows"
has "$r" '<th>X (mm)</th><th>Y (mm)</th><th>Z (mm)</th>'
has "$r" 'O5001.nc:232 N511</td><td class="l">touch</td><td>25.2600</td><td>-6.7000</td><td>-6.0000</td>'
has "$r" 'O5001.nc:212</td><td class="l">work</td><td class="l">G54</td><td class="l">X</td><td>112.3500</td>'
has "$r" 'O5001.nc:213</td><td class="l">work</td><td class="l">G54</td><td class="l">Y</td><td>42.1000</td>'
# The height map: a colour scale from the bore bottom (Z-12) to the top (Z0) with a legend.
has "$r" '<svg xmlns="http://www.w3.org/2000/svg" class="legend"'
has "$r" '>Z (mm)</text>'
has "$r" 'text-anchor="middle">-12</text>'
has "$r" 'Height map (Z: violet lowest, yellow highest). Covers X (left to right) -10.000 &hellip; 35.000 mm, Y (bottom to top) -30.000 &hellip; 15.000 mm.'
grep -q '"from": -12' "$tmp/stock/analysis.json" || fail "analysis: no height-map scale"

# A target: the deviation map's legend, from -10 to +10 tolerances (0.01 mm here).
face="$src/examples/face-milling-g42"
"$ncvm" run "$face/face-milling-g42.nc" --setup "$face/face-milling-g42.toml" --report "$tmp/f.html" -q \
  || fail "face milling run exit $?"
has "$tmp/f.html" '>deviation, stock - target (mm), log scale past the tolerance</text>'
for tick in -0.100 -0.010 0.000 +0.010 +0.100; do has "$tmp/f.html" "text-anchor=\"middle\">$tick</text>"; done

# The machine model: the time is modelled, and said to be.
"$ncvm" run "$probe/bore-o5001.nc" --setup "$src/presets/fanuc-0i-mf.toml" --setup "$probe/bore-o5001.toml" \
  --report "$tmp/d.html" -q || fail "dynamic run exit $?"
has "$tmp/d.html" 'Cycle time <strong>237.75 s (0:03:57.75), modelled</strong>'
has "$tmp/d.html" 'Length &divide; feed alone: 230.15 s'
has "$tmp/d.html" 'modelled time (s)'

# A lathe: the half-section, Z right and X as a radius up, in inch for this example.
lathe="$src/examples/lathe-cycles"
"$ncvm" run "$lathe/g71-g70-rough-turning.nc" --setup "$lathe/setup.toml" --report "$tmp/l.html" -q \
  || fail "lathe run exit $?"
r="$tmp/l.html"
has "$r" '>Z (inch)</text>'
has "$r" '>X radius (diameter / 2) (inch)</text>'
has "$r" 'Half-section through the spindle axis'
has "$r" 'stroke-dasharray="14 3 2 3"'  # the spindle axis
has "$r" '<p>No G31 move.</p>'
has "$r" '<p>No offset written by the program.</p>'
# The example's stock (a lathe profile) with its extent.
"$ncvm" run "$lathe/g71-g70-rough-turning.nc" --setup "$lathe/setup.toml" --setup "$lathe/stock-o0402.toml" \
  --report "$tmp/ls.html" -q || fail "lathe stock run exit $?"
has "$tmp/ls.html" 'Covers Z (left to right)'

# --stock-out without [stock]: a warning, the run and the report go on without a stock part.
printf '[machine]\nkind = "lathe"\n' >"$tmp/lathe.toml"
"$ncvm" run "$lathe/g90-taper.nc" --setup "$tmp/lathe.toml" --stock-out "$tmp/none" --report "$tmp/n.html" \
  >"$tmp/out" 2>"$tmp/err"; rc=$?
[ $rc = 0 ] || fail "no [stock]: exit $rc $(cat "$tmp/err")"
grep -q 'warning: --stock-out .*none: no stock in the setup (no \[stock\] section)' "$tmp/err" \
  || fail "no [stock]: warning: $(cat "$tmp/err")"
[ ! -e "$tmp/none" ] || fail "no [stock]: the folder was made"
has "$tmp/n.html" '<p class="no-stock">No stock in the setup'
has "$tmp/n.html" 'class="toolpath"'
grep -q 'report: ' "$tmp/out" || fail "no [stock]: summary $(cat "$tmp/out")"
echo "cli report: ok"
