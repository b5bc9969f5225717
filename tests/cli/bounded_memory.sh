#!/usr/bin/env bash
# Memory stays bounded whatever the run length (issue 26 item 10): a comment-only block of an
# M99 loop started a new time-report operation on every pass (about 1.4 KB a block: 1.4 GB in
# 1,000,000 blocks). Each loop runs 400,000 blocks (the block limit ends it) and may not grow
# the peak resident memory by more than 20 MB over a run of 2,000 blocks of the same loop
# (getrusage of the child, so the comparison holds in any build, sanitizers included).
set -u
ncvm=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# One comment and one move; a bar feeder's loop (two operations by comment, two tools, a dwell).
printf 'O0001\n(ONE COMMENT)\nG91 G01 X1. F1000.\nM99\n' >"$tmp/comment.nc"
printf 'O0002\n(BAR FEED)\nT1 M06\nG91 G01 X1. F1000.\n(SECOND)\nG04 X0.001\nT2 M06\nG01 Y1.\nM99\n' >"$tmp/bar.nc"

# Peak RSS in kB of one run (exit 3: the block limit's alarm, as expected).
peak() {
  python3 - "$@" <<'PY'
import resource, subprocess, sys
rc = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL).returncode
if rc != 3:
    sys.exit(f"exit {rc}, expected 3 (the block limit)")
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
PY
}

for prog in comment bar; do
  for model in simple dynamic; do
    run=("$ncvm" run "$tmp/$prog.nc" --set timing.model=$model --state "$tmp/s.json")
    short=$(peak "${run[@]}" --set limits.max_blocks=2000) || fail "$prog $model short run"
    long=$(peak "${run[@]}" --set limits.max_blocks=400000) || fail "$prog $model long run"
    growth=$((long - short))
    [ "$growth" -le 20480 ] ||
      fail "$prog ($model): 400,000 blocks peak at $long kB, 2,000 at $short kB (+$growth kB)"
    # One operation per place in the program, each entered once a pass.
    python3 - "$tmp/s.json" "$prog" <<'PY' || fail "$prog $model: operations"
import json, sys
ops = json.load(open(sys.argv[1]))["timing"]["operations"]
want = 1 if sys.argv[2] == "comment" else 3
assert len(ops) == want, [(o["label"], o["tool"]) for o in ops]
assert all(o["runs"] > 1000 for o in ops), [o["runs"] for o in ops]
PY
  done
done
echo "bounded memory: 400,000 blocks of comment and bar-feeder M99 loops within 20 MB"
