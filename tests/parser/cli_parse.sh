#!/usr/bin/env bash
# `rts parse` end to end: output on stdout, diagnostics on stderr, exit codes, --help.
#   cli_parse.sh RTS_BINARY SOURCE_DIR
set -uo pipefail
rts="$1"
src="$2"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# A golden file parses to its .ast, and --quiet prints nothing.
"$rts" parse "$src/tests/golden/parse/calls.rts" > "$tmp/out" 2> "$tmp/err"; rc=$?
[[ $rc -eq 0 ]] || fail "parse of a valid file exited $rc"
cmp -s "$tmp/out" "$src/tests/golden/parse/calls.ast" || fail "stdout differs from calls.ast"
[[ ! -s "$tmp/err" ]] || fail "stderr not empty for a valid file"
"$rts" parse --quiet "$src/tests/golden/parse/calls.rts" > "$tmp/out"; rc=$?
[[ $rc -eq 0 && ! -s "$tmp/out" ]] || fail "--quiet printed something or failed ($rc)"
"$rts" parse --locations "$src/tests/golden/parse/locations.rts" > "$tmp/out"; rc=$?
cmp -s "$tmp/out" "$src/tests/golden/parse/locations.ast" || fail "--locations output differs"

# A syntax error: exit 1, the diagnostic with source line, caret and note on stderr.
printf 'sphere {\n  radius = 1\n' > "$tmp/bad.rts"
"$rts" parse "$tmp/bad.rts" > "$tmp/out" 2> "$tmp/err"; rc=$?
[[ $rc -eq 1 ]] || fail "syntax error exited $rc, expected 1"
[[ ! -s "$tmp/out" ]] || fail "stdout not empty on a syntax error"
expected="$tmp/bad.rts:2:13: error: expected '}' to close the block
      radius = 1
                ^
$tmp/bad.rts:1:8: note: to match this '{'"
[[ "$(cat "$tmp/err")" == "$expected" ]] || fail "unexpected diagnostic: $(cat "$tmp/err")"

# Files that cannot be read: exit 1 with a message naming the file.
"$rts" parse "$tmp/missing.rts" 2> "$tmp/err"; rc=$?
[[ $rc -eq 1 ]] && grep -q "missing.rts: error: no such file" "$tmp/err" || fail "missing file: $rc $(cat "$tmp/err")"
"$rts" parse "$tmp" 2> "$tmp/err"; rc=$?
[[ $rc -eq 1 ]] && grep -q "is a directory" "$tmp/err" || fail "directory: $rc $(cat "$tmp/err")"
printf 'let a = 1\nlet b = "\xff"\n' > "$tmp/utf8.rts"
"$rts" parse "$tmp/utf8.rts" 2> "$tmp/err"; rc=$?
[[ $rc -eq 1 ]] && grep -q "utf8.rts:2:10: error: invalid UTF-8" "$tmp/err" || fail "bad UTF-8: $rc $(cat "$tmp/err")"
printf 'let a = 1\0\n' > "$tmp/nul.rts"
"$rts" parse "$tmp/nul.rts" 2> "$tmp/err"; rc=$?
[[ $rc -eq 1 ]] && grep -q "NUL byte" "$tmp/err" || fail "NUL byte: $rc $(cat "$tmp/err")"

# An empty file is an empty program.
: > "$tmp/empty.rts"
[[ "$("$rts" parse "$tmp/empty.rts")" == "(program)" ]] || fail "empty file"

# Usage: --help works, a missing argument or unknown flag is a usage error (2).
"$rts" parse --help > "$tmp/out"; rc=$?
[[ $rc -eq 0 ]] && grep -q -- "--locations" "$tmp/out" || fail "parse --help ($rc)"
"$rts" parse > /dev/null 2>&1; rc=$?
[[ $rc -eq 2 ]] || fail "missing FILE exited $rc, expected 2"
"$rts" parse --bogus "$tmp/empty.rts" > /dev/null 2>&1; rc=$?
[[ $rc -eq 2 ]] || fail "unknown flag exited $rc, expected 2"

# Deep nesting is an error, not a crash.
python3 -c "print('let x = ' + '(' * 100000)" > "$tmp/deep.rts"
"$rts" parse "$tmp/deep.rts" 2> "$tmp/err" > /dev/null; rc=$?
[[ $rc -eq 1 ]] && grep -q "nesting too deep (more than 256 levels)" "$tmp/err" || fail "deep nesting: $rc"

[[ $failures -eq 0 ]] && echo "cli_parse: all checks passed"
exit $((failures > 0))
