#!/usr/bin/env bash
# The --machine-state file under concurrent runs (issue 26 items 1 and 6): runs sharing one
# machine state take turns (a lock beside it), so no update is lost; a run that cannot get
# the lock within --lock-wait stops with a clear message (exit 2) and writes nothing; a file
# with a value the control would not hold is refused with its key and value and left as it is.
set -u
ncvm=$1
tmp=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
runs=${LOCK_RUNS:-60}

printf 'O0001\n#500=#500+1\nM30\n' >"$tmp/inc.nc"
state="$tmp/m.json"
increment() {
  for _ in $(seq 1 "$runs"); do
    "$ncvm" run "$tmp/inc.nc" --machine-state "$state" -q || echo "run failed: $?" >>"$tmp/errors"
  done
}
increment &
increment &
wait
[ ! -s "$tmp/errors" ] || fail "$(cat "$tmp/errors")"
total=$(python3 -c 'import json,sys; print(int(json.load(open(sys.argv[1]))["vars"]["#500"]))' "$state")
[ "$total" = $((2 * runs)) ] || fail "2 x $runs increments gave #500 = $total"

# Another holder of the lock (a run in progress): a bounded wait, then a clear refusal.
python3 - "$state.lock" "$tmp/held" <<'PY' &
import fcntl, sys, time, pathlib
f = open(sys.argv[1], "a")
fcntl.flock(f, fcntl.LOCK_EX)
pathlib.Path(sys.argv[2]).touch()
time.sleep(20)
PY
holder=$!
for _ in $(seq 1 100); do [ -e "$tmp/held" ] && break; sleep 0.05; done
[ -e "$tmp/held" ] || fail "the lock holder did not start"
cp "$state" "$tmp/before.json"
start=$(date +%s%N)
"$ncvm" run "$tmp/inc.nc" --machine-state "$state" --lock-wait 0.5 -q 2>"$tmp/err"
rc=$?
waited=$((($(date +%s%N) - start) / 1000000))
kill "$holder"
[ $rc = 2 ] || fail "a held lock: exit $rc"
grep -q "m.json: in use by another run (its lock .*m.json.lock was held for 0.5 s; --lock-wait" "$tmp/err" ||
  fail "a held lock: $(cat "$tmp/err")"
[ "$waited" -ge 450 ] && [ "$waited" -lt 10000 ] || fail "a held lock: waited $waited ms"
cmp -s "$state" "$tmp/before.json" || fail "a run without the lock changed the machine state"

# Out-of-range values are refused with the key and the value; the file stays as it was.
bad() {
  printf '%s\n' "$1" >"$tmp/bad.json"
  cp "$tmp/bad.json" "$tmp/bad.orig"
  "$ncvm" run "$tmp/inc.nc" --machine-state "$tmp/bad.json" $3 -q 2>"$tmp/err"
  rc=$?
  [ $rc = 2 ] || fail "$2: exit $rc"
  grep -qF "$2" "$tmp/err" || fail "$2 not named: $(cat "$tmp/err")"
  grep -q "left as it is" "$tmp/err" || fail "$2: $(cat "$tmp/err")"
  cmp -s "$tmp/bad.json" "$tmp/bad.orig" || fail "$2: the bad file was rewritten"
}
head='"format":"ncvm-machine-state/1","units":"mm"'
bad "{$head,\"work_offsets\":{\"G54\":{\"X\":1e13}}}" "work_offsets.G54.X = 10000000000000.0" ""
bad "{$head,\"tool_offsets\":{\"1\":{\"tip\":1e300}}}" "tool_offsets.1.tip = 1e+300" "--set machine.kind=lathe"
bad "{$head,\"tool_offsets\":{\"1\":{\"tip\":-7}}}" "tool_offsets.1.tip = -7" "--set machine.kind=lathe"
bad "{$head,\"tool_offsets\":{\"1\":{\"tip\":99}}}" "tool_offsets.1.tip = 99" "--set machine.kind=lathe"
bad "{$head,\"vars\":{\"#500\":\"x\"}}" "vars.#500 = \"x\"" ""
echo "machine state: 2 x $runs concurrent increments kept, a held lock refused after ${waited} ms, 5 bad files refused untouched"
