#!/usr/bin/env bash
# Outputs under hostile paths and signals (issue 26 items 2-5, 11, 15; issue 30 item 7):
# devices and FIFOs are written directly and stay what they are; `-` is standard output and
# `ncvm run -` reads the program from standard input; SIGINT, SIGTERM and SIGHUP leave no
# temporary file; a file-size limit (SIGXFSZ) is an error naming the file (exit 2); a trace
# that cannot be written names the trace; a killed run's temporaries go at the next run;
# --stock-out is replaced as a set. Every wait is bounded.
set -u
set -m  # background jobs in their own process groups: without job control they ignore SIGINT
ncvm=$1
golden=$2
tmp=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
temps() { find "$tmp" -name '*.ncvm-*.tmp*' | wc -l; }

printf 'O0001\n#500=#500+1\nG0X#500\nM30\n' >"$tmp/one.nc"
# An endless loop of moves, bounded by the block limit (a few seconds of trace).
printf 'O0002\nWHILE[1EQ1]DO1\nG0X1.Y2.\nG0X0Y0\nEND1\nM30\n' >"$tmp/loop.nc"

# A FIFO given as --state is written through and stays a FIFO.
mkfifo "$tmp/fifo"
timeout 10 cat "$tmp/fifo" >"$tmp/fromfifo" &
reader=$!
timeout 10 "$ncvm" run "$tmp/one.nc" --state "$tmp/fifo" -q || fail "state into a FIFO: exit $?"
wait $reader
[ -p "$tmp/fifo" ] || fail "the FIFO was replaced"
grep -q '"end": "M30"' "$tmp/fromfifo" || fail "nothing came through the FIFO"

# `-`: the program from standard input, the trace or the state on standard output, the
# summary on standard error.
printf 'O0003\nG0X5.\nM30\n' | "$ncvm" run - --trace - >"$tmp/stdout" 2>"$tmp/stderr" || fail "run - --trace -: exit $?"
python3 -c 'import json,sys; [json.loads(l) for l in open(sys.argv[1])]' "$tmp/stdout" || fail "stdout is not the trace"
grep -q '"end":\[5' "$tmp/stdout" || fail "trace without the move: $(cat "$tmp/stdout")"
grep -q 'ended: M30' "$tmp/stderr" || fail "summary not on stderr: $(cat "$tmp/stderr")"
[ ! -e ./- ] || fail "a file named - was written"
printf 'O0003\nG0X5.\nM30\n' | "$ncvm" run - --state - -q >"$tmp/stdout" || fail "--state -: exit $?"
python3 -c 'import json,sys; assert json.load(open(sys.argv[1]))["end"] == "M30"' "$tmp/stdout" || fail "--state - is not the state"
printf 'O0004\n#1=0\n#2=1/#1\nM30\n' | "$ncvm" run - >"$tmp/stdout" 2>&1
grep -q '^<stdin>:3:' "$tmp/stdout" || fail "an alarm in standard input: $(cat "$tmp/stdout")"
printf 'O0005\nG0X5.\nM30\n' | "$ncvm" check - >"$tmp/stdout" || fail "check -: exit $?"
grep -q '0 alarm' "$tmp/stdout" || fail "check -: $(cat "$tmp/stdout")"
"$ncvm" run "$tmp/one.nc" --trace - --state - -q >/dev/null 2>"$tmp/err" && fail "two outputs on stdout accepted"
grep -q 'only one of' "$tmp/err" || fail "two outputs on stdout: $(cat "$tmp/err")"

# Signals: the run dies of the signal as before, and leaves no temporary file.
for sig in INT TERM HUP; do
  "$ncvm" run "$tmp/loop.nc" --trace "$tmp/sig.jsonl" --machine-state "$tmp/sig.json" \
    --set limits.max_blocks=50000000 --set limits.max_trace_bytes=200000000 -q &
  pid=$!
  for _ in $(seq 1 100); do [ "$(temps)" -gt 0 ] && break; sleep 0.02; done
  [ "$(temps)" -gt 0 ] || fail "SIG$sig: no temporary trace to remove (the run ended too early)"
  kill -s "$sig" $pid
  wait $pid
  rc=$?
  [ $rc -gt 128 ] || fail "SIG$sig: exit $rc"
  [ "$(temps)" = 0 ] || fail "SIG$sig left $(find "$tmp" -name '*.ncvm-*')"
done

# A file-size limit: an error naming the trace (exit 2), the machine state still saved.
(
  ulimit -f 64  # 64 KiB
  "$ncvm" run "$tmp/loop.nc" --trace "$tmp/big.jsonl" --machine-state "$tmp/fs.json" \
    --set limits.max_blocks=2000000 -q >/dev/null 2>"$tmp/err"
  echo $? >"$tmp/rc"
)
[ "$(cat "$tmp/rc")" = 2 ] || fail "file-size limit: exit $(cat "$tmp/rc") $(cat "$tmp/err")"
grep -q "big.jsonl: cannot write the trace: File too large" "$tmp/err" || fail "file-size limit: $(cat "$tmp/err")"
grep -q "fs.json" "$tmp/err" && fail "file-size limit names the machine state: $(cat "$tmp/err")"
[ -s "$tmp/fs.json" ] || fail "file-size limit: no machine state"
[ "$(temps)" = 0 ] || fail "file-size limit left $(find "$tmp" -name '*.ncvm-*')"
# A full device (/dev/full) as the trace: the message names it.
"$ncvm" run "$tmp/one.nc" --trace /dev/full --machine-state "$tmp/full.json" -q 2>"$tmp/err"
rc=$?
[ $rc = 2 ] || fail "/dev/full: exit $rc"
grep -Eq "/dev/full: cannot write( the trace)?: No space left on device" "$tmp/err" || fail "/dev/full: $(cat "$tmp/err")"
[ -c /dev/full ] || fail "/dev/full replaced"

# The trace limit names its setting and value.
"$ncvm" run "$tmp/loop.nc" --trace "$tmp/t.jsonl" --set limits.max_trace_bytes=5000 >"$tmp/out"
grep -q 'PS9006 TRACE LIMIT REACHED (limits.max_trace_bytes = 5000)' "$tmp/out" || fail "trace limit: $(cat "$tmp/out")"

# A killed run's temporary goes at the next run; a live process's stays.
"$ncvm" run "$tmp/loop.nc" --trace "$tmp/k.jsonl" --set limits.max_blocks=50000000 --set limits.max_trace_bytes=200000000 -q &
pid=$!
for _ in $(seq 1 100); do [ "$(temps)" -gt 0 ] && break; sleep 0.02; done
kill -KILL $pid
wait $pid 2>/dev/null
[ "$(temps)" = 1 ] || fail "SIGKILL: expected its temporary to stay until the next run"
"$ncvm" run "$tmp/one.nc" --trace "$tmp/k.jsonl" -q || fail "the run after a kill"
[ "$(temps)" = 0 ] || fail "a dead run's temporary was not removed: $(find "$tmp" -name '*.ncvm-*')"

# --stock-out as a set: replaced whole; a folder of other files is refused and kept.
prog="$golden/stock/convex_arc_no_tnrc.nc"
setup="$golden/stock/convex_arc_no_tnrc.toml"
"$ncvm" run "$prog" --setup "$setup" --stock-out "$tmp/stock" -q || fail "stock-out: exit $?"
echo stale >"$tmp/stock/stale.txt"
"$ncvm" run "$prog" --setup "$setup" --stock-out "$tmp/stock" -q || fail "stock-out again: exit $?"
[ ! -e "$tmp/stock/stale.txt" ] || fail "stock-out: files of two runs side by side"
[ -s "$tmp/stock/analysis.json" ] || fail "stock-out: no analysis"
mkdir "$tmp/mine" && echo precious >"$tmp/mine/notes.txt"
"$ncvm" run "$prog" --setup "$setup" --stock-out "$tmp/mine" -q 2>"$tmp/err" && fail "stock-out over a user's folder"
grep -q "not a stock output" "$tmp/err" || fail "stock-out over a user's folder: $(cat "$tmp/err")"
[ "$(cat "$tmp/mine/notes.txt")" = precious ] || fail "the user's folder was touched"
[ "$(temps)" = 0 ] || fail "stock-out left $(find "$tmp" -name '*.ncvm-*')"
# SIGTERM while the set is being made: its temporary folder goes too.
printf '[stock]\nmin = [0, 0, -10]\nmax = [50, 50, 0]\n' >"$tmp/mill.toml"
printf 'O0006\nT1M6\nG0X0Y0Z1.\nG1Z-1.F1000.\nWHILE[1EQ1]DO1\nG1X50.Y50.\nX0Y0\nEND1\nM30\n' >"$tmp/cut.nc"
"$ncvm" run "$tmp/cut.nc" --setup "$tmp/mill.toml" --stock-out "$tmp/millstock" --set limits.max_blocks=20000000 -q &
pid=$!
for _ in $(seq 1 100); do [ "$(temps)" -gt 0 ] && break; sleep 0.02; done
[ "$(temps)" -gt 0 ] || fail "stock-out: no temporary folder to remove"
kill -TERM $pid
wait $pid
[ $? = 143 ] || fail "stock-out under SIGTERM: not killed by it"
[ "$(temps)" = 0 ] || fail "SIGTERM left the stock set's $(find "$tmp" -name '*.ncvm-*')"
echo "atomic outputs: FIFO, stdin/stdout, 3 signals, file-size limit, /dev/full, a killed run's temporary, stock set (and under SIGTERM): ok"
