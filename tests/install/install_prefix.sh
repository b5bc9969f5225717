#!/usr/bin/env bash
# Fixture of the install tests: `cmake --install BUILD --prefix PREFIX` into a fresh PREFIX
# (a folder of the build tree that only these tests use).
set -euo pipefail
build=$1 prefix=$2
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >"$prefix.log" 2>&1 || { cat "$prefix.log"; exit 1; }
echo "installed into $prefix"
