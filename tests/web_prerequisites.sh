#!/usr/bin/env bash
# What the browser tests (web/tests, Playwright driving Debian's Chromium) need, checked as a
# test of its own so that a machine without them fails `make test` and says why, instead of
# the tests quietly not being there. Arguments: NODE WEB_SOURCE_DIR WEB_BUILD_DIR CHROMIUM
# (a CMake NOTFOUND or empty value counts as missing).
# NCVM_NO_BROWSER_TESTS=1 turns the failure into a skip (CTest shows the test as Skipped, with
# the reasons), for a machine that has no browser on purpose; CI never sets it.
set -u
node=${1:-}
web_src=${2:-}
web_out=${3:-}
chromium=${4:-}
missing() { [ -z "$1" ] || [[ "$1" == *-NOTFOUND ]]; }
why=()

if missing "$node" || ! [ -x "$node" ]; then
  why+=("Node.js not found (scripts/install-deps installs Debian's nodejs and npm)")
else
  major=$("$node" -p 'process.versions.node.split(".")[0]' 2>/dev/null || echo 0)
  if [ "${major:-0}" -lt 18 ]; then
    why+=("Node.js $("$node" --version 2>/dev/null) is too old: the viewer's Vite needs 18 or newer")
  fi
fi
for pkg in vite playwright-core; do
  [ -f "$web_src/node_modules/$pkg/package.json" ] \
    || why+=("$web_src/node_modules/$pkg is missing: run scripts/install-deps (npm ci in web/), then configure again")
done
[ -f "$web_out/index.html" ] \
  || why+=("the web viewer is not built ($web_out/index.html is missing): it is built with the rest (target ncvm_web) once web/node_modules is there")
if missing "$chromium" || ! [ -x "$chromium" ]; then
  why+=("Chromium not found${chromium:+: $chromium} (scripts/install-deps installs Debian's chromium)")
else
  err=$(mktemp)
  # Debian's /usr/bin/chromium wrapper may print shell noise on stderr: only stdout is the
  # version; stderr is the reason when it does not start.
  if ! version=$(timeout 60 "$chromium" --headless --no-sandbox --version 2>"$err"); then
    why+=("Chromium at $chromium does not start: $(tail -n 3 "$err")")
  fi
  rm -f "$err"
fi

if [ ${#why[@]} -eq 0 ]; then
  echo "browser tests: node $("$node" --version), $version, viewer built in $web_out"
  exit 0
fi
if [ "${NCVM_NO_BROWSER_TESTS:-}" = 1 ]; then
  echo "browser tests skipped on request (NCVM_NO_BROWSER_TESTS=1); they could not run here:"
  printf '  - %s\n' "${why[@]}"
  exit 77
fi
echo "browser tests cannot run:"
printf '  - %s\n' "${why[@]}"
echo "(on a machine without a browser on purpose, NCVM_NO_BROWSER_TESTS=1 makes this a skip)"
exit 1
