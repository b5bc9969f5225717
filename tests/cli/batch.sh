#!/usr/bin/env bash
# `ncvm run --batch`: every file runs as its own program (in parallel), each with its own
# trace and state in the named folders; reports in command-line order; the worst exit wins.
set -u
ncvm=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

cp "$dir/ok.nc" "$tmp/a.nc"
cp "$dir/ok.nc" "$tmp/b.nc"
"$ncvm" run --batch -j 2 "$tmp/a.nc" "$tmp/b.nc" --trace "$tmp/tr" --state "$tmp/st" >"$tmp/out"; rc=$?
[ $rc = 0 ] || fail "two good programs exit $rc"
for p in a b; do
  grep -q '"end": "M30"' "$tmp/st/$p.json" || fail "state of $p"
  [ "$(grep -c '"type":"move"' "$tmp/tr/$p.jsonl")" = 2 ] || fail "two moves in the trace of $p"
done
# One report per program, in command-line order.
[ "$(grep -c 'ended: M30' "$tmp/out")" = 2 ] || fail "two reports: $(cat "$tmp/out")"
head -1 "$tmp/out" | grep -q 'a.nc' || fail "a.nc reported first: $(cat "$tmp/out")"

# An alarm in one program: the others still run, the exit status is 3.
"$ncvm" run --batch "$tmp/a.nc" "$dir/alarm.nc" "$tmp/b.nc" --state "$tmp/st2" >"$tmp/out"; rc=$?
[ $rc = 3 ] || fail "batch with an alarm exit $rc"
grep -qE 'alarm.nc:3:[0-9]+: PS0112' "$tmp/out" || fail "alarm line: $(cat "$tmp/out")"
[ -f "$tmp/st2/b.json" ] || fail "b.nc ran after the alarm of alarm.nc"
grep -q '"end": "M30"' "$tmp/st2/b.json" || fail "state of b after the alarm"

# Without --batch, extra files stay library files: only the first program runs.
"$ncvm" run "$tmp/a.nc" "$tmp/b.nc" >"$tmp/out"; rc=$?
[ $rc = 0 ] || fail "library form exit $rc"
[ "$(grep -c 'ended:' "$tmp/out")" = 1 ] || fail "library form ran one program: $(cat "$tmp/out")"

# Two files whose outputs would collide, a missing file: usage errors (2).
mkdir -p "$tmp/x"
cp "$dir/ok.nc" "$tmp/x/a.nc"
"$ncvm" run --batch "$tmp/a.nc" "$tmp/x/a.nc" 2>"$tmp/err"; rc=$?
[ $rc = 2 ] || fail "colliding stems exit $rc"
"$ncvm" run --batch "$tmp/a.nc" "$tmp/missing.nc" >"$tmp/out" 2>"$tmp/err"; rc=$?
[ $rc = 2 ] || fail "missing file in a batch exit $rc"
grep -q 'ended: M30' "$tmp/out" || fail "a.nc still ran beside the missing file"
echo "cli batch: ok"
