#!/usr/bin/env bash
# `make demo` exactly as a newcomer runs it (scripts/demo on the built binary): every program
# that `ncvm list examples` names runs with its setup and ends as its README says (M30 or
# M02), no false alarm, one row each.
set -u
ncvm=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; cat "$tmp/out"; exit 1; }
NCVM_BIN="$ncvm" NCVM_DEMO_OUT="$tmp/demo" "$src/scripts/demo" >"$tmp/out" 2>&1 || fail "demo exit $?"
listed=$("$ncvm" list "$src/examples" | wc -l)
[ "$listed" -ge 20 ] || fail "ncvm list examples: only $listed programs"
rows=$(grep -cE '^[a-z0-9-]+/[^ ]+ +(M30|M02) +[0-9]+ ' "$tmp/out")
[ "$rows" = "$listed" ] || fail "$rows of $listed examples ended with M30/M02"
grep -qiE 'alarm +[0-9-]|PS[0-9]{4}|error' "$tmp/out" && fail "an alarm or error in the demo"
echo ok
