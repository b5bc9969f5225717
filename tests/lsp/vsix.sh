#!/usr/bin/env bash
# ctest vscode_vsix: the VS Code extension packages (scripts/package-vscode-extension) and the
# .vsix holds the compiled client, the grammar, the language configuration and the client
# library it starts the server with.
set -euo pipefail
root="$1" out="$2"
# @vscode/vsce's dependencies need Node.js 20; Debian 12's is 18 (docs/editors.md).
node_major=$(node -p 'process.versions.node.split(".")[0]')
if [ "$node_major" -lt 20 ]; then
  echo "vscode_vsix: skipped: packaging the extension needs Node.js 20 or newer, this is $(node --version)"
  exit 77
fi
rm -f "$out"
"$root/scripts/package-vscode-extension" "$out" >/dev/null
python3 - "$out" <<'PY'
import json, sys, zipfile
names = set(zipfile.ZipFile(sys.argv[1]).namelist())
need = ["extension/out/extension.js", "extension/syntaxes/fanuc.tmLanguage.json",
        "extension/language-configuration.json", "extension/package.json",
        "extension/node_modules/vscode-languageclient/package.json"]
missing = [n for n in need if n not in names]
if missing:
    sys.exit(f"vscode_vsix: the package lacks {missing}")
manifest = json.loads(zipfile.ZipFile(sys.argv[1]).read("extension/package.json"))
assert manifest["contributes"]["languages"][0]["id"] == "fanuc"
print(f"vscode_vsix: {sys.argv[1]}: {len(names)} files")
PY
