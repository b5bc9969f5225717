#!/usr/bin/env bash
# `ncvm compare`: the seed-000 deep-hole study (G83 Q7. against O9503 with the paper's
# arguments, examples/deep-hole-o9503) on the 0i-MF preset: pecks, full retracts and the
# time difference; exit codes as for run.
set -u
ncvm=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; cat "$tmp/out" 2>/dev/null; exit 1; }
ex="$src/examples/deep-hole-o9503"

"$ncvm" compare "$ex/g83-mill.nc" "$ex/o9503-mill.nc" --setup "$src/presets/fanuc-0i-mf.toml" >"$tmp/out" ||
  fail "compare exit $?"
# G83 Q7.: 7 pecks, back to R after each but the last; O9503: 12 pecks, H3 = every third.
grep -qE '^pecks +7 +12 +\+5 ' "$tmp/out" || fail "pecks"
grep -qE '^full retracts +6 +3 +-3 ' "$tmp/out" || fail "full retracts"
grep -qE '^  dwell, s +0\.000 +0\.807 ' "$tmp/out" || fail "dwell (12 x 2 rev + 3 x 5 rev at 2900 rpm)"
grep -qE '^cycle time \(length/feed\), s +11\.313 +13\.606 ' "$tmp/out" || fail "simple times"
grep -qE '^cycle time \(modelled\), s ' "$tmp/out" || fail "modelled time row"
grep -qE '^B is [0-9.]+ s \([0-9.]+%\) (slower|faster) than A$' "$tmp/out" || fail "verdict line"

# Operations (examples/README.md's example): the hole beside the hole, not beside a step of the
# macro (O9503's comments inside its WHILE loop and call are no operations): one operation of
# T1 each, with the hole at X0 Y0 under it, and the operation rows add up to the cycle times.
python3 - "$tmp/out" <<'PY' || fail "operations of the README example"
import re, sys
rows = open(sys.argv[1]).read().splitlines()
def cells(line):
    return [float(v) for v in line.split(", s", 1)[1].split()[:3]]
total = cells(next(l for l in rows if l.startswith("cycle time (modelled)")))
ops = [l for l in rows if re.match(r"^  op [0-9]+ T", l)]
holes = [l for l in rows if re.match(r"^    hole X", l)]
assert len(ops) == 1 and ops[0].startswith("  op 1 T1 "), ops
assert len(holes) == 1 and holes[0].startswith("    hole X0 Y0, s"), holes
a, b, d = cells(holes[0])
assert a > 0 and b > 0 and abs(b - a - d) < 0.002, holes[0]
for k in range(3):
    assert abs(sum(cells(l)[k] for l in ops) - total[k]) < 0.002 * len(ops), (k, ops, total)
PY

"$ncvm" compare "$ex/g83-mill.nc" "$ex/o9503-mill.nc" --setup "$src/presets/fanuc-0i-mf.toml" --json >"$tmp/out" ||
  fail "compare --json exit $?"
grep -q '"full_retracts": -3' "$tmp/out" || fail "json difference of full retracts"
python3 - "$tmp/out" <<'PY' || fail "json operations"
import json, sys
j = json.load(open(sys.argv[1]))
ops = j["operations"]
assert [(o["a"], o["b"]) for o in ops] == [(0, 0)], ops
assert [(h["x"], h["y"], h["a"], h["b"]) for h in ops[0]["holes"]] == [(0, 0, 0, 0)], ops
assert abs(sum(o["difference"] for o in ops) - j["difference"]["cycle_time"]) < 1e-9
PY

# Operations by comment, side by side (the golden test's program against itself).
ops="$src/tests/golden/timing/operations_by_comment"
"$ncvm" compare "$ops.nc" "$ops.nc" --setup "$ops.toml" >"$tmp/out" || fail "operations compare exit $?"
grep -qE '^  op 1 T1 ROUGH FACE, s +3\.550 +3\.550 ' "$tmp/out" || fail "operation 1 row"
grep -qE '^  op 2 T1 FINISH PASS, s +0\.550 +0\.550 ' "$tmp/out" || fail "operation 2 row"
grep -qE '^  op 3 T2 DRILL, s +4\.000 +4\.000 ' "$tmp/out" || fail "operation 3 row"

# Without a setup the simple model is compared (no modelled row).
"$ncvm" compare "$ex/g83-mill.nc" "$ex/o9503-mill.nc" >"$tmp/out" || fail "simple compare exit $?"
grep -q 'modelled' "$tmp/out" && fail "simple compare shows a modelled time"

# Exit codes: 3 when a program alarms (its alarm line is printed), 2 on usage errors.
"$ncvm" compare "$src/tests/cli/ok.nc" "$src/tests/cli/alarm.nc" >"$tmp/out"; rc=$?
[ $rc = 3 ] || fail "alarm exit $rc"
grep -qE 'alarm.nc:3:[0-9]+: PS0112' "$tmp/out" || fail "alarm line"
"$ncvm" compare "$src/tests/cli/ok.nc" >"$tmp/out" 2>&1; rc=$?
[ $rc = 2 ] || fail "one program exit $rc"
"$ncvm" compare "$src/tests/cli/ok.nc" "$src/tests/cli/ok.nc" --setup "$tmp/missing.toml" >"$tmp/out" 2>&1; rc=$?
[ $rc = 2 ] || fail "missing setup exit $rc"
echo "cli compare: ok"
