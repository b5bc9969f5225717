#!/usr/bin/env bash
# On a terminal (util-linux `script` gives the run one): the summary's end and alarm in colour,
# a progress line on standard error for a run longer than a second, erased before the summary.
# NO_COLOR set: no colour. Into a pipe: no colour and no progress line.
set -u
ncvm=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
command -v script >/dev/null || { echo "terminal: skipped: no 'script' (util-linux) to give the run a terminal"; exit 77; }
esc=$(printf '\033')

printf 'O0001\n#1=0\nWHILE[#1LT8000000]DO1\nG01 X[[#1 MOD 2]*0.01] F1000.\n#1=#1+1\nEND1\nM30\n' >"$tmp/long.nc"
printf 'O0002\nG01 X10.\nM30\n' >"$tmp/alarm.nc"

script -qec "'$ncvm' run '$tmp/long.nc'" /dev/null >"$tmp/long.out" 2>&1
grep -q "ncvm: .*long.nc: [0-9]* moves, [0-9]* s" "$tmp/long.out" || fail "no progress line: $(cat -v "$tmp/long.out")"
grep -q "${esc}\[K" "$tmp/long.out" || fail "the progress line is not erased"
grep -q "ended: ${esc}\[32mM30${esc}\[0m" "$tmp/long.out" || fail "M30 not green: $(cat -v "$tmp/long.out")"

script -qec "'$ncvm' run '$tmp/alarm.nc'" /dev/null >"$tmp/alarm.out" 2>&1
grep -q "${esc}\[31m.*alarm.nc:2:1: PS0011" "$tmp/alarm.out" || fail "alarm line not red: $(cat -v "$tmp/alarm.out")"

NO_COLOR=1 script -qec "'$ncvm' run '$tmp/alarm.nc'" /dev/null >"$tmp/nocolour.out" 2>&1
grep -q "${esc}\[3" "$tmp/nocolour.out" && fail "colour with NO_COLOR: $(cat -v "$tmp/nocolour.out")"
grep -q "^/.*alarm.nc:2:1: PS0011" <(tr -d '\r' <"$tmp/nocolour.out") || fail "NO_COLOR: no alarm line"

"$ncvm" run "$tmp/long.nc" >"$tmp/pipe.out" 2>&1
grep -q "$esc" "$tmp/pipe.out" && fail "escape codes into a pipe: $(cat -v "$tmp/pipe.out")"
grep -q "moves, [0-9]* s" "$tmp/pipe.out" && fail "a progress line into a pipe"
echo "terminal: ok"
