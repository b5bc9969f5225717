#!/usr/bin/env bash
# A machine-state file survives a run killed at any point: afterwards it holds either the
# old state or the new one, never a mix or a truncated file. Runs are killed with SIGKILL
# at random moments, some before the end (old state expected) and some after (new state).
set -u
ncvm=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# A program that writes persistent memory and runs long enough to be killed halfway.
cat >"$tmp/long.nc" <<'NC'
O0001
#500=#500+1
G10 L2 P1 X#500
#1=0
WHILE[#1LT[#100]]DO1
#1=#1+1
END1
M30
NC
state="$tmp/machine.json"
"$ncvm" run "$tmp/long.nc" --machine-state "$state" --set vars.#100=1 -q || fail "first run"
python3 - "$state" <<'PY' || fail "first state"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["vars"]["#500"] == 1 and s["work_offsets"]["G54"]["X"] == 1, s
PY

old=1 kills=0 finished=0
for i in $(seq 1 24); do
  iterations=$(( (RANDOM % 4 + 1) * 1500000 ))
  "$ncvm" run "$tmp/long.nc" --machine-state "$state" --set vars.#100=$iterations -q &
  pid=$!
  sleep "0.$(( RANDOM % 40 ))"
  if kill -9 "$pid" 2>/dev/null; then kills=$((kills + 1)); fi
  wait "$pid" 2>/dev/null
  value=$(python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); print(int(s["vars"]["#500"]), int(s["work_offsets"]["G54"]["X"]))' "$state") \
    || fail "run $i left an unreadable state file"
  read -r v x <<<"$value"
  [ "$v" = "$x" ] || fail "run $i: #500=$v but G54 X=$x (a mix of two states)"
  if [ "$v" = $((old + 1)) ]; then finished=$((finished + 1)); old=$v;
  elif [ "$v" != "$old" ]; then fail "run $i: #500 went from $old to $v"; fi
  ls "$tmp" | grep -q '\.tmp\.' && [ -z "$(jobs -r)" ] && rm -f "$tmp"/*.tmp.*
done
echo "machine-state kill test: 24 runs, $kills killed, $finished completed, state always whole"
