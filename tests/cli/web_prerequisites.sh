#!/usr/bin/env bash
# tests/web_prerequisites.sh: the browser tests never go missing silently. With each thing
# they need taken away in turn (a missing Chromium, one that does not start, no npm packages,
# no built viewer, no Node.js) the check fails and names it; NCVM_NO_BROWSER_TESTS=1 turns
# that into a skip (exit 77) that still says why.
set -u
check=$1
node=${2:-}
missing() { [ -z "$1" ] || [[ "$1" == *-NOTFOUND ]]; }
missing "$node" && node=$(command -v node || true)
[ -n "$node" ] || { echo "FAIL: this test needs node"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

mkdir -p "$tmp/web/node_modules/vite" "$tmp/web/node_modules/playwright-core" "$tmp/out"
echo '{}' >"$tmp/web/node_modules/vite/package.json"
echo '{}' >"$tmp/web/node_modules/playwright-core/package.json"
echo '<!DOCTYPE html>' >"$tmp/out/index.html"
printf '#!/bin/sh\necho "Chromium 1.2.3"\n' >"$tmp/chromium"
printf '#!/bin/sh\necho "cannot open display" >&2\nexit 1\n' >"$tmp/broken"
chmod +x "$tmp/chromium" "$tmp/broken"
run() { env -u NCVM_NO_BROWSER_TESTS "$check" "$@" >"$tmp/o" 2>&1; echo $?; }

[ "$(run "$node" "$tmp/web" "$tmp/out" "$tmp/chromium")" = 0 ] || fail "all there: $(cat "$tmp/o")"
grep -q "browser tests: node v.*, Chromium 1.2.3" "$tmp/o" || fail "all there: $(cat "$tmp/o")"

[ "$(run "$node" "$tmp/web" "$tmp/out" /nonexistent/chromium)" = 1 ] || fail "no chromium: $(cat "$tmp/o")"
grep -q "Chromium not found: /nonexistent/chromium (scripts/install-deps installs Debian's chromium)" "$tmp/o" \
  || fail "no chromium, message: $(cat "$tmp/o")"
grep -q "NCVM_NO_BROWSER_TESTS=1 makes this a skip" "$tmp/o" || fail "no opt-out hint: $(cat "$tmp/o")"
[ "$(run "$node" "$tmp/web" "$tmp/out" NCVM_CHROMIUM-NOTFOUND)" = 1 ] || fail "chromium NOTFOUND"
grep -q "Chromium not found" "$tmp/o" || fail "chromium NOTFOUND, message: $(cat "$tmp/o")"

# The explicit opt-out: a skip, still with the reason.
NCVM_NO_BROWSER_TESTS=1 "$check" "$node" "$tmp/web" "$tmp/out" /nonexistent/chromium >"$tmp/o" 2>&1; rc=$?
[ $rc = 77 ] || fail "opt-out: exit $rc $(cat "$tmp/o")"
grep -q "skipped on request (NCVM_NO_BROWSER_TESTS=1)" "$tmp/o" && grep -q "Chromium not found" "$tmp/o" \
  || fail "opt-out, message: $(cat "$tmp/o")"

[ "$(run "$node" "$tmp/web" "$tmp/out" "$tmp/broken")" = 1 ] || fail "broken chromium"
grep -q "does not start: cannot open display" "$tmp/o" || fail "broken chromium, message: $(cat "$tmp/o")"

rm -r "$tmp/web/node_modules/vite"
[ "$(run "$node" "$tmp/web" "$tmp/out" "$tmp/chromium")" = 1 ] || fail "no vite"
grep -q "node_modules/vite is missing: run scripts/install-deps (npm ci in web/)" "$tmp/o" \
  || fail "no vite, message: $(cat "$tmp/o")"

rm "$tmp/out/index.html"
[ "$(run "$node" "$tmp/web" "$tmp/out" "$tmp/chromium")" = 1 ] || fail "not built"
grep -q "the web viewer is not built" "$tmp/o" || fail "not built, message: $(cat "$tmp/o")"

[ "$(run NCVM_NODE-NOTFOUND "$tmp/web" "$tmp/out" "$tmp/chromium")" = 1 ] || fail "no node"
grep -q "Node.js not found" "$tmp/o" || fail "no node, message: $(cat "$tmp/o")"
echo "cli web prerequisites: ok"
