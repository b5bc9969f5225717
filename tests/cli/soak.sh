#!/usr/bin/env bash
# Soak test (issue 26): for SOAK_SECONDS (default 20), several processes run programs against
# one machine state while others, started beside them, are killed at random points (SIGKILL,
# SIGTERM, SIGINT, SIGHUP). Afterwards: no increment of a run that ended normally is lost,
# none is counted twice, the machine state was never torn (whole JSON, #500 equal to the G54
# X the same run wrote) and, after one more run, no temporary file is left.
set -u
set -m  # background jobs in their own process groups: without job control they ignore SIGINT
ncvm=$1
tmp=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
seconds=${SOAK_SECONDS:-20}
workers=${SOAK_WORKERS:-3}

cat >"$tmp/inc.nc" <<'NC'
O0001
#500=#500+1
G10 L2 P1 X#500
#1=0
WHILE[#1LT#100]DO1
#1=#1+1
END1
G0 X#500
M30
NC
state="$tmp/m.json"
# Prints #500 when the machine state is whole and #500 equals the G54 X the same run wrote.
# (Plain shell: a Python start costs more than a run on a loaded machine.)
check_state() {
  local text v x
  text=$(<"$state")
  [[ $text == '{'*'}' ]] || return 1
  # One read: the workers replace the file meanwhile.
  v=$(sed -n 's/^ *"#500": \([0-9]*\)\.0,\{0,1\}$/\1/p' <<<"$text")
  x=$(grep -A1 '"G54": {' <<<"$text" | sed -n 's/^ *"X": \([0-9]*\)\.0,$/\1/p')
  [ -n "$v" ] && [ "$v" = "$x" ] || return 1
  echo "$v"
}
end=$((SECONDS + seconds))
worker() {
  local ok=0 k=0
  while [ $SECONDS -lt $end ]; do
    k=$((k + 1))
    if "$ncvm" run "$tmp/inc.nc" --machine-state "$state" --set vars.#100=$((RANDOM % 2000)) \
      --trace "$tmp/w$1.jsonl" --state "$tmp/w$1.json" -q; then
      ok=$((ok + 1))
    else
      echo "worker $1 run $k: exit $?" >>"$tmp/errors"
    fi
  done
  echo $ok >"$tmp/ok$1"
}
for w in $(seq 1 "$workers"); do worker "$w" & done

signals=(KILL TERM INT HUP)
victims=0 kills=0 torn=0
while [ $SECONDS -lt $end ]; do
  "$ncvm" run "$tmp/inc.nc" --machine-state "$state" --set vars.#100=$((RANDOM % 20000)) \
    --trace "$tmp/victim.jsonl" --state "$tmp/victim.json" -q 2>/dev/null &
  pid=$!
  victims=$((victims + 1))
  sleep "0.0$((RANDOM % 10))$((RANDOM % 10))"
  sig=${signals[$((RANDOM % 4))]}
  kill -s "$sig" $pid 2>/dev/null && kills=$((kills + 1))
  wait $pid 2>/dev/null
  if [ -e "$state" ]; then check_state >/dev/null || torn=$((torn + 1)); fi
done
wait
[ ! -s "$tmp/errors" ] || fail "$(head -5 "$tmp/errors")"
[ $torn = 0 ] || fail "the machine state was torn $torn times"
completed=0
for w in $(seq 1 "$workers"); do completed=$((completed + $(cat "$tmp/ok$w"))); done
total=$(check_state) || fail "final machine state"
# Every worker run counts; a victim's counts only when it saved before its signal.
[ "$total" -ge "$completed" ] || fail "lost updates: #500 = $total after $completed completed runs"
[ "$total" -le $((completed + victims)) ] || fail "counted twice: #500 = $total > $completed + $victims"
# One more run of each output removes what the SIGKILLed runs left.
"$ncvm" run "$tmp/inc.nc" --machine-state "$state" --trace "$tmp/victim.jsonl" --state "$tmp/victim.json" -q ||
  fail "the last run"
left=$(find "$tmp" -name '*.ncvm-*' | wc -l)
[ "$left" = 0 ] || fail "temporaries left: $(find "$tmp" -name '*.ncvm-*')"
echo "soak: ${seconds} s, $workers workers, $completed completed runs, $victims victims ($kills signalled), #500 = $total, never torn, no temporary left"
