#!/usr/bin/env bash
# Every persistent output survives a run killed at any point: the machine state
# (--machine-state), the trace (--trace), the final state (--state) and the DPRNT output
# (--output) each hold either the previous run's whole file or the new run's whole file,
# never a mix or a truncated file. Runs are killed with SIGKILL at random moments, some
# before the end (old files expected) and some during or after the writes (new files).
set -u
ncvm=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
runs=${KILL_RUNS:-24}

# A program that writes persistent memory, runs long enough to be killed halfway, and
# leaves its run number (#500) in every output: a G54 offset and a move in the trace,
# #500 in the state, "RUN n" in the DPRNT output.
cat >"$tmp/long.nc" <<'NC'
O0001
#500=#500+1
G10 L2 P1 X#500
#1=0
WHILE[#1LT[#100]]DO1
#1=#1+1
END1
POPEN
DPRNT[RUN*#500[50]]
PCLOS
G0 X#500
M30
NC
state="$tmp/machine.json"
outputs=(--trace "$tmp/trace.jsonl" --state "$tmp/state.json" --output "$tmp/out.txt")
"$ncvm" run "$tmp/long.nc" --machine-state "$state" "${outputs[@]}" --set vars.#100=1 -q || fail "first run"

# Prints the run number each file holds: machine state, trace, state, output. A file that
# is not whole (unreadable JSON, a trace without its last move, an output without its
# line) makes it fail.
read_all() {
  python3 - "$tmp" <<'PY'
import json, re, sys
d = sys.argv[1]
m = json.load(open(f"{d}/machine.json"))
v, x = int(m["vars"]["#500"]), int(m["work_offsets"]["G54"]["X"])
assert v == x, f"machine state mixes two runs: #500={v}, G54 X={x}"
lines = [json.loads(l) for l in open(f"{d}/trace.jsonl")]
assert len(lines) == 2 and lines[0]["type"] == "offset" and lines[1]["type"] == "move", lines
t = int(lines[0]["value"])
assert round(lines[1]["end"][0]) == t, f"trace mixes two runs: {lines}"
s = json.load(open(f"{d}/state.json"))
assert s["end"] == "M30", s["end"]
st = int(s["vars"]["#500"])
out = open(f"{d}/out.txt").read()
mo = re.fullmatch(r"RUN +(\d+)\n?", out)
assert mo, f"output not whole: {out!r}"
print(v, t, st, int(mo.group(1)))
PY
}
read -r -a prev <<<"$(read_all)" || fail "first outputs"
[ "${prev[*]}" = "1 1 1 1" ] || fail "first run wrote ${prev[*]}"

kills=0 finished=0
names=(machine-state trace state output)
for i in $(seq 1 "$runs"); do
  # From an instant run (killed during or after its writes, or not at all) to a long one.
  sizes=(0 2000 300000 1500000)
  iterations=${sizes[RANDOM % 4]}
  "$ncvm" run "$tmp/long.nc" --machine-state "$state" "${outputs[@]}" --set vars.#100=$iterations -q &
  pid=$!
  sleep "0.$(( RANDOM % 40 ))"
  if kill -9 "$pid" 2>/dev/null; then kills=$((kills + 1)); fi
  wait "$pid" 2>/dev/null
  now=$(read_all) || fail "run $i left an output that is not whole"
  read -r -a cur <<<"$now"
  # The machine state is written first: it moves by one or stays. Each other output holds
  # its previous run or the machine state's run, nothing else.
  if [ "${cur[0]}" = $((prev[0] + 1)) ]; then finished=$((finished + 1));
  elif [ "${cur[0]}" != "${prev[0]}" ]; then fail "run $i: #500 went from ${prev[0]} to ${cur[0]}"; fi
  for k in 1 2 3; do
    [ "${cur[k]}" = "${prev[k]}" ] || [ "${cur[k]}" = "${cur[0]}" ] ||
      fail "run $i: ${names[k]} holds run ${cur[k]}, expected ${prev[k]} or ${cur[0]}"
  done
  prev=("${cur[@]}")
  # A SIGKILLed run's temporaries are removed by the next run writing the same outputs.
  [ "$(find "$tmp" -name '*.ncvm-*.tmp' | wc -l)" -le 4 ] || fail "run $i: temporaries pile up"
done
echo "kill test: $runs runs, $kills SIGKILLs delivered, $finished runs completed; machine state, trace, state and output always whole"
