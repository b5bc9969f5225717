#!/usr/bin/env bash
# `--setup NAME` is the bundled preset NAME.toml when no file of that name is there
# (src/cli/main.cpp, setupFile): from any folder. A file of that name wins; an unknown name
# stays a setup error naming it.
#   preset_names.sh NCVM
set -u
ncvm=$(realpath "$1")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; cat "$tmp/out" 2>/dev/null; exit 1; }
cd "$tmp"
printf 'G0 X10. Z5.\nM30\n' >p.nc
"$ncvm" run p.nc --setup fanuc-0i-tf --state s.json -q >out 2>&1 || fail "--setup fanuc-0i-tf (exit $?)"
# A lathe's modal group 2 is G96/G97 (G97 at power-on); a mill's is the plane (G17).
lathe() { python3 -c 'import json, sys; sys.exit(json.load(open(sys.argv[1]))["modal"]["2"] != 97)' "$1"; }
lathe s.json || fail "the preset's lathe is not in the state"
"$ncvm" run p.nc --state d.json -q >out 2>&1 || fail "default setup"
lathe d.json && fail "the default setup is a lathe too: the test proves nothing"
"$ncvm" run p.nc --setup fanuc-0i-tf.toml --state s2.json -q >out 2>&1 || fail "--setup fanuc-0i-tf.toml"
cmp -s s.json s2.json || fail "NAME and NAME.toml differ"
printf '[machine]\nkind = "mill"\n' >fanuc-0i-tf
"$ncvm" run p.nc --setup fanuc-0i-tf --state f.json -q >out 2>&1 || fail "a local file named like the preset"
lathe f.json && fail "the preset won over a file of that name"
"$ncvm" run p.nc --setup no-such-preset >out 2>&1
[ $? = 2 ] || fail "an unknown name: exit 2"
grep -q "no-such-preset" out || fail "the error names the setup"
echo "preset names: ok"
