#!/usr/bin/env bash
# ctest lsp_stdio: the stdio test with the client library of tests/lsp/package-lock.json.
# It fails (never skips) when Node.js or the library is missing: scripts/install-deps
# installs both.
set -euo pipefail
node_bin="$1" ncvm="$2"
here="$(cd "$(dirname "$0")" && pwd)"
if [ -z "$node_bin" ] || ! command -v "$node_bin" >/dev/null 2>&1; then
  echo "lsp_stdio: Node.js is missing (scripts/install-deps installs it)" >&2
  exit 1
fi
if [ ! -f "$here/node_modules/vscode-languageserver-protocol/package.json" ]; then
  echo "lsp_stdio: tests/lsp/node_modules is missing: run scripts/install-deps (npm ci in tests/lsp)" >&2
  exit 1
fi
NCVM_BIN="$ncvm" exec "$node_bin" --test "$here/stdio.test.mjs"
