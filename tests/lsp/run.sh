#!/usr/bin/env bash
# ctest lsp_stdio and vscode_grammar: a node test of tests/lsp with the packages of
# tests/lsp/package-lock.json (the LSP client library, VS Code's TextMate engine).
# It fails (never skips) when Node.js or the packages are missing: scripts/install-deps
# installs both.
#   run.sh NODE NCVM TEST.mjs
set -euo pipefail
node_bin="$1" ncvm="$2" test_file="$3"
here="$(cd "$(dirname "$0")" && pwd)"
if [ -z "$node_bin" ] || ! command -v "$node_bin" >/dev/null 2>&1; then
  echo "tests/lsp: Node.js is missing (scripts/install-deps installs it)" >&2
  exit 1
fi
for pkg in vscode-languageserver-protocol vscode-textmate vscode-oniguruma; do
  if [ ! -f "$here/node_modules/$pkg/package.json" ]; then
    echo "tests/lsp: node_modules/$pkg is missing: run scripts/install-deps (npm ci in tests/lsp)" >&2
    exit 1
  fi
done
NCVM_BIN="$ncvm" exec "$node_bin" --test "$here/$test_file"
