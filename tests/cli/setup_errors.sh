#!/usr/bin/env bash
# Setup files and settings that are wrong are refused with exit 2 and a message that says
# where and what: a folder or a device given as --setup, a file that cannot be read
# ("permission denied"), FILE:LINE:COL on every error of a file (also when several are
# given), the nearest key for a mistyped one, and bit parameters that take only 0 or 1.
set -u
ncvm=$(realpath "$1")
dir=$(realpath "$2")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; cat "$tmp/err" 2>/dev/null; exit 1; }
prog="$dir/ok.nc"
expect2() { # DESCRIPTION PATTERN ARGS...
  local what=$1 pattern=$2
  shift 2
  "$ncvm" run "$prog" "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  [ $rc = 2 ] || fail "$what: exit $rc"
  grep -qE -e "$pattern" "$tmp/err" || fail "$what: message does not match $pattern"
}

mkdir "$tmp/folder"
expect2 "a folder" "setup error: $tmp/folder: is a folder, not a setup file" --setup "$tmp/folder"
expect2 "a device" "setup error: /dev/null: not a regular file" --setup /dev/null
expect2 "a missing file" "setup error: $tmp/none.toml: no such file" --setup "$tmp/none.toml"
printf '[machine]\nkind = "mill"\n' >"$tmp/locked.toml"
chmod 000 "$tmp/locked.toml"
if [ "$(id -u)" = 0 ]; then
  # root reads any file: read it as nobody (the folder must let nobody in).
  if command -v setpriv >/dev/null; then
    chmod 755 "$tmp"
    cp "$prog" "$tmp/ok.nc" && chmod 644 "$tmp/ok.nc"
    setpriv --reuid=65534 --regid=65534 --clear-groups "$ncvm" run "$tmp/ok.nc" --setup "$tmp/locked.toml" \
      >"$tmp/out" 2>"$tmp/err"
    rc=$?
    [ $rc = 2 ] || fail "an unreadable file: exit $rc"
    grep -q "setup error: $tmp/locked.toml: permission denied" "$tmp/err" || fail "an unreadable file"
  fi
else
  expect2 "an unreadable file" "setup error: $tmp/locked.toml: permission denied" --setup "$tmp/locked.toml"
fi

# FILE:LINE:COL, with the second of two files named; the nearest key suggested.
printf '[machine]\nkind = "mill"\n' >"$tmp/a.toml"
printf '# job\nmachin.kind = "lathe"\n' >"$tmp/b.toml"
expect2 "unknown key" "setup error: $tmp/b.toml:2:[0-9]+: machin.kind: unknown key \(did you mean machine.kind\?\)$" \
  --setup "$tmp/a.toml" --setup "$tmp/b.toml"
printf '[target]\n  tolerence = 0.01\n' >"$tmp/c.toml"
expect2 "unknown target key" "$tmp/c.toml:2:3: target.tolerence: .*\(did you mean target.tolerance\?\)$" --setup "$tmp/c.toml"
printf '[axes.Z]\nrapd = 100\n' >"$tmp/d.toml"
expect2 "unknown axis key" "$tmp/d.toml:2:1: axes.Z.rapd: unknown axis key .* \(did you mean axes.Z.rapid\?\)$" --setup "$tmp/d.toml"
printf '[machine]\nkind = "lath"\n' >"$tmp/e.toml"
expect2 "bad value" "$tmp/e.toml:2:1: machine.kind: " --setup "$tmp/e.toml"
printf '[machine\n' >"$tmp/f.toml"
expect2 "TOML syntax" "$tmp/f.toml:[0-9]+:[0-9]+: " --setup "$tmp/f.toml"
expect2 "--set unknown" "--set limits.max_blocs=5: limits.max_blocs: unknown key \(did you mean limits.max_blocks\?\)" \
  --set limits.max_blocs=5

# Bit parameters: 0 or 1 only.
expect2 "DPI=2" "--set DPI=2: DPI: 3401#0 is a bit parameter: 0 or 1" --set DPI=2
expect2 "3401#0=-1" "3401#0 is a bit parameter: 0 or 1" --set 3401#0=-1
printf '"3401#0" = 2\n' >"$tmp/g.toml"
expect2 "bit in a file" "$tmp/g.toml:1:1: 3401#0: 3401#0 is a bit parameter" --setup "$tmp/g.toml"
"$ncvm" run "$prog" --set DPI=1 --set 3401#0=0 --set 3410=2000 >/dev/null 2>"$tmp/err" || fail "DPI=1 / 3410=2000 refused"
echo ok
