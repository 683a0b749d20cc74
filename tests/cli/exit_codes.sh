#!/usr/bin/env bash
source "$(dirname "$0")/lib.sh"

# Language errors exit 1 with a located diagnostic.
printf 'sphere { radius = 1\n' > "$TMP/unclosed.rts"
expect_exit 1 "syntax error" -- "$RTS" parse "$TMP/unclosed.rts"
expect_grep "$TMP/err" "unclosed.rts:[0-9]+:[0-9]+: error:" "syntax error is located"

printf 'let a = 1\nlet b = a + undefined_name\n' > "$TMP/undef.rts"
expect_exit 1 "runtime error" -- "$RTS" check "$TMP/undef.rts"
expect_grep "$TMP/err" "undef.rts:2:[0-9]+: error:" "runtime error is located"

expect_exit 1 "missing file" -- "$RTS" parse "$TMP/does-not-exist.rts"
expect_grep "$TMP/err" "does-not-exist.rts" "missing file is named"
expect_exit 1 "directory instead of a file" -- "$RTS" parse "$TMP"
printf 'let a = 1\n\xff\xfe\n' > "$TMP/bad-utf8.rts"
expect_exit 1 "invalid UTF-8" -- "$RTS" parse "$TMP/bad-utf8.rts"
expect_grep "$TMP/err" "UTF-8" "invalid UTF-8 is reported as such"

# A failing render never replaces a good image.
printf 'settings { width = 8 height = 8 }\nsphere { radius = 1 }\n' > "$TMP/good.rts"
expect_exit 0 "good render" -- "$RTS" render "$TMP/good.rts" -o "$TMP/out.png" --no-progress
cp "$TMP/out.png" "$TMP/before.png"
expect_exit 1 "failing render" -- "$RTS" render "$TMP/undef.rts" -o "$TMP/out.png" --no-progress
if ! cmp -s "$TMP/out.png" "$TMP/before.png"; then echo "FAIL: the good image was replaced"; FAILS=$((FAILS + 1)); fi
if ls "$TMP" | grep -q '\.tmp'; then echo "FAIL: temporary file left behind"; ls "$TMP"; FAILS=$((FAILS + 1)); fi

# Render errors exit 3: an image texture that cannot be read.
printf 'sphere { radius = 1 material = material { color = image_texture("missing.png") } }\n' > "$TMP/tex.rts"
expect_exit 3 "unreadable texture" -- "$RTS" render "$TMP/tex.rts" -o "$TMP/tex.png" --no-progress
expect_grep "$TMP/err" "tex.rts:1:[0-9]+: error:.*missing.png" "render error is located at the texture"
finish
