#!/usr/bin/env bash
# A real editor against `rts lsp`: Debian's Neovim, headless, opens a scene with a mistake
# through editors/vim's own setup and the test reads back the diagnostic Neovim shows (its
# range and message) and a hover. Skipped (77) where Neovim is not installed.
#   neovim_test.sh RTS_BINARY SOURCE_DIR
set -u
rts="$1" src="$2"
if ! command -v nvim >/dev/null; then
  echo "SKIP: nvim not installed (scripts/ensure-deps installs Debian's neovim)"
  exit 77
fi
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/mistake.rts" <<'SCENE'
point_light { position = <5, 5, -5> }
sphere { center = <0, 1, 0>  raduis = 1 }
SCENE
export RTS_BINARY="$rts" RTS_EDITORS="$src/editors" RTS_SCENE="$tmp/mistake.rts" RTS_OUT="$tmp/out.txt"
# HOME and XDG folders in the temporary folder: no user configuration, no shada/log files left.
export HOME="$tmp" XDG_CONFIG_HOME="$tmp/config" XDG_DATA_HOME="$tmp/data" XDG_STATE_HOME="$tmp/state" \
  XDG_CACHE_HOME="$tmp/cache"
timeout 60 nvim --headless --clean -n -c "luafile $src/tests/lsp/neovim_test.lua" </dev/null >"$tmp/nvim.log" 2>&1
status=$?
cat "$tmp/out.txt" 2>/dev/null
fails=0
expect() {
  if grep -qF -- "$1" "$tmp/out.txt" 2>/dev/null; then echo "ok: $2"; else echo "FAIL: $2 (expected: $1)"; fails=$((fails + 1)); fi
}
[[ $status == 0 ]] || { echo "FAIL: nvim exited $status"; cat "$tmp/nvim.log"; fails=$((fails + 1)); }
expect "filetype rts" "editors/vim detects the filetype"
# `raduis` is line 1 (0-based), bytes 29..35; severity 1 is an error.
expect "diagnostic 1:29-1:35 severity 1 unknown property 'raduis' for sphere; did you mean 'radius'?" \
  "the diagnostic's range and message as Neovim holds them"
expect "hover **center** (sphere property): vector" "hover on a property"
[[ $fails == 0 ]] || exit 1
echo "all passed"
