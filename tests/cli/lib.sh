# Helpers for the CLI tests: run a command, capture exit code and output, compare.
set -u
RTS="$1"; SRC="$2"
TMP="$(mktemp -d)"; trap 'rm -rf "$TMP"' EXIT
FAILS=0
# expect_exit CODE DESCRIPTION -- COMMAND...; CODE may list several ("0 1 3": any of them)
expect_exit() {
  local want="$1" what="$2"; shift 3
  "$@" >"$TMP/out" 2>"$TMP/err"; local got=$?
  if [[ " $want " != *" $got "* ]]; then
    echo "FAIL: $what: exit $got, expected $want"; echo "--- stdout"; cat "$TMP/out"; echo "--- stderr"; cat "$TMP/err"
    FAILS=$((FAILS + 1))
  else
    echo "ok: $what (exit $got)"
  fi
}
# expect_grep FILE PATTERN DESCRIPTION
expect_grep() {
  if ! grep -qE -- "$2" "$1"; then
    echo "FAIL: $3: /$2/ not found in:"; cat "$1"; FAILS=$((FAILS + 1))
  fi
}
finish() { if [[ $FAILS -gt 0 ]]; then echo "$FAILS failure(s)"; exit 1; fi; echo "all passed"; }
