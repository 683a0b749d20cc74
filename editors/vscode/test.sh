#!/usr/bin/env bash
# Builds and tests the VS Code extension from the repository:
#   1. the grammar's assertions (tests/*.rts, vscode-tmgrammar-test);
#   2. the grammar over every example, with assertions an independent small lexer derives
#      (tests/assertions_from_examples.py: comments, strings, declarations, block kinds);
#   3. the extension packaged into a .vsix with vsce, and its contents checked.
# Needs `npm ci` here first (scripts/vscode-setup); without node_modules it exits 77 (skipped).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
cd "$here"
if [[ ! -d node_modules/vscode-tmgrammar-test || ! -d node_modules/@vscode/vsce ]] || ! command -v node >/dev/null; then
  echo "SKIP: editors/vscode/node_modules is missing (run scripts/vscode-setup, which runs npm ci)"
  exit 77
fi
bin="$here/node_modules/.bin"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

echo "== grammar assertions"
"$bin/vscode-tmgrammar-test" -g syntaxes/rts.tmLanguage.json 'tests/*.rts'

echo "== grammar over examples/ (assertions from tests/assertions_from_examples.py)"
python3 tests/assertions_from_examples.py "$tmp/examples" "$root"/examples/*.rts
"$bin/vscode-tmgrammar-test" -g syntaxes/rts.tmLanguage.json "$tmp/examples/*.rts" | grep -v "run successfuly" || true
"$bin/vscode-tmgrammar-test" -g syntaxes/rts.tmLanguage.json "$tmp/examples/*.rts" >/dev/null

echo "== package"
"$bin/vsce" package --allow-missing-repository --skip-license -o "$tmp/rts-language.vsix" >/dev/null
python3 - "$tmp/rts-language.vsix" <<'PY'
import sys, zipfile
names = set(zipfile.ZipFile(sys.argv[1]).namelist())
need = {"extension/package.json", "extension/language-configuration.json",
        "extension/syntaxes/rts.tmLanguage.json", "extension/src/extension.js",
        "extension/node_modules/vscode-languageclient/package.json"}
missing = need - names
if missing:
    sys.exit("FAIL: the .vsix lacks " + ", ".join(sorted(missing)))
if any(n.startswith("extension/tests/") for n in names):
    sys.exit("FAIL: the .vsix carries the tests")
print("ok: %s holds %d files" % (sys.argv[1].rsplit("/", 1)[-1], len(names)))
PY
echo "all passed"
