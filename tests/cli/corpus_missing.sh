#!/usr/bin/env bash
# A clone without ../shared: the corpus test skips (CTest's 77) with a message that says
# what was skipped; with NCVM_CORPUS_REQUIRED it fails.
set -u
runner=$1
ncvm=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=$(env -u NCVM_CORPUS_REQUIRED python3 "$runner" "$ncvm" "$tmp/none" 2>&1)
rc=$?
[ $rc = 77 ] || { echo "FAIL: missing corpus: exit $rc: $out"; exit 1; }
echo "$out" | grep -q "skipped: the shared corpus of real shop programs ($tmp/none) is not here" ||
  { echo "FAIL: message: $out"; exit 1; }
NCVM_CORPUS_REQUIRED=1 python3 "$runner" "$ncvm" "$tmp/none" >/dev/null 2>&1
rc=$?
[ $rc = 1 ] || { echo "FAIL: NCVM_CORPUS_REQUIRED: exit $rc"; exit 1; }
echo ok
