#!/usr/bin/env bash
# One rule for program files and for the setup a program runs with (core/program_files.hpp):
# a --lib folder finds a macro saved as O9100.EIA, o9100.ptp or o9100; `ncvm list` (what
# `make demo` runs) pairs a program with its own NAME.toml, a NAME-VARIANT with NAME.toml,
# else the folder's setup.toml, else nothing; `ncvm serve` lists the same files and setups.
set -u
ncvm=$(realpath "$1")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; cat "$tmp/out" 2>/dev/null; exit 1; }

printf '%%\nO1 (MAIN)\nG65 P9100 A2.\nM30\n%%\n' >"$tmp/main.nc"
for name in O9100.EIA o9100.ptp o9100 O9100.Iso o9100.ANC; do
  lib="$tmp/lib-$name"
  mkdir -p "$lib"
  printf '%%\nO9100 (MACRO)\n#500=#1\nM99\n%%\n' >"$lib/$name"
  "$ncvm" run "$tmp/main.nc" --lib "$lib" --no-macros >"$tmp/out" 2>&1 || fail "macro saved as $name not found"
done
# A file that is neither: not loaded (no duplicate, no alarm from its text).
mkdir -p "$tmp/lib-other"
printf 'not a program\n' >"$tmp/lib-other/notes.md"
printf 'not a program\n' >"$tmp/lib-other/ORDERS"
"$ncvm" run "$tmp/main.nc" --lib "$tmp/lib-other" --no-macros >"$tmp/out" 2>&1 && fail "a .md or ORDERS file taken as the macro"

d="$tmp/ex"
mkdir -p "$d/a" "$d/b" "$d/c"
for f in a/part.nc a/part-x150.NC a/other.tap b/one.eia b/O1234 c/lone.nc; do printf '%%\nO1\nM30\n%%\n' >"$d/$f"; done
printf 'project(x)\n' >"$d/c/CMakeLists.txt"
touch "$d/a/part.toml" "$d/a/setup.toml" "$d/b/setup.toml" "$d/b/one-x.toml" "$d/c/extra.toml" "$d/a/README.md"
(cd "$tmp" && "$ncvm" list ex) >"$tmp/out" || fail "list exit $?"
expect=$(printf 'ex/a/other.tap\tex/a/setup.toml\nex/a/part-x150.NC\tex/a/part.toml\nex/a/part.nc\tex/a/part.toml\nex/b/O1234\tex/b/setup.toml\nex/b/one.eia\tex/b/setup.toml\nex/c/lone.nc\t-')
[ "$(cat "$tmp/out")" = "$expect" ] || fail "list: expected
$expect"

# ncvm serve: the same files, the same setups.
"$ncvm" serve --port 0 --root "$d" >"$tmp/serve.out" 2>"$tmp/serve.err" &
pid=$!
trap 'kill $pid 2>/dev/null; rm -rf "$tmp"' EXIT
url=""
for _ in $(seq 100); do
  url=$(grep -oE 'http://127\.0\.0\.1:[0-9]+' "$tmp/serve.out" | head -1)
  [ -n "$url" ] && break
  sleep 0.1
done
[ -n "$url" ] || fail "serve did not start: $(cat "$tmp/serve.err")"
python3 - "$url" >"$tmp/out" <<'PY' || fail "serve listing"
import json, sys, urllib.request
files = json.load(urllib.request.urlopen(sys.argv[1] + "/api/files"))
for root in files["roots"]:
    if root["name"] == "ex":
        for f in root["files"]:
            print(f["path"], f["setup"] or "-")
PY
expect=$(printf 'a/other.tap a/setup.toml\na/part-x150.NC a/part.toml\na/part.nc a/part.toml\nb/O1234 b/setup.toml\nb/one.eia b/setup.toml\nc/lone.nc -')
[ "$(cat "$tmp/out")" = "$expect" ] || fail "serve listing: expected
$expect"
echo ok
