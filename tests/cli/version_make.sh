#!/usr/bin/env bash
# The version comes from CMake's project(VERSION) with the git commit; bare `make` lists the
# targets; `make demo` builds only ncvm; install-deps installs clang-format (make format).
set -u
ncvm=$1
src=$2
fail() { echo "FAIL: $*"; exit 1; }
want=$(sed -nE 's/^project\(ncvm VERSION ([0-9.]+) .*/\1/p' "$src/CMakeLists.txt")
[ -n "$want" ] || fail "no project VERSION in CMakeLists.txt"
got=$("$ncvm" --version) || fail "--version exit $?"
if git -C "$src" rev-parse --short HEAD >/dev/null 2>&1; then
  echo "$got" | grep -qE "^ncvm $want \(git [0-9a-f]{7,}\)$" || fail "--version: $got (want ncvm $want (git COMMIT))"
else
  [ "$got" = "ncvm $want" ] || fail "--version: $got"
fi
grep -rn --include=*.cpp --include=*.hpp "\"$want\"\|ncvm $want" "$src/src" && fail "the version written in a source file"
help=$(make -s -C "$src" 2>&1) || fail "bare make: exit $?"
for t in demo test serve build format; do echo "$help" | grep -q "^make $t " || fail "bare make does not list $t"; done
demo=$(make -n -C "$src" demo 2>/dev/null | grep 'cmake --build')
echo "$demo" | grep -q -- '--target ncvm$' || fail "make demo builds more than ncvm: $demo"
grep -qE '^\s*clang-format\b' "$src/scripts/install-deps" || fail "install-deps does not install clang-format"
echo ok
