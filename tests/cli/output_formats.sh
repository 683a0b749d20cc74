#!/usr/bin/env bash
# `rts render -o`: the extension picks the format (.png, .pfm, .exr, any case), an unknown one
# is a usage error before anything is rendered or written, --bits is checked per format,
# --linear stores linear PNG codes, and the course depth/normal options reach the AOVs.
source "$(dirname "$0")/lib.sh"

cat >"$TMP/s.rts" <<'SCENE'
settings { width = 16  height = 12 }
camera { position = <0, 0, -5>  look_at = <0, 0, 0> }
plane { normal = <0, 0, -1>  offset = -1  material = material { emission = rgb(0.5)  ambient = 0  diffuse = 0 } }
SCENE

# Unknown or missing extensions: exit 2, the existing file untouched, nothing new written.
echo "keep me" >"$TMP/x.jpg"
expect_exit 2 "-o x.jpg is a usage error" -- "$RTS" render "$TMP/s.rts" -o "$TMP/x.jpg" --no-progress
expect_grep "$TMP/err" "unknown output format '.jpg'" "the message names the extension"
expect_grep "$TMP/x.jpg" "^keep me$" "x.jpg is left as it was"
expect_exit 2 "-o without an extension" -- "$RTS" render "$TMP/s.rts" -o "$TMP/noext" --no-progress
[[ -e "$TMP/noext" ]] && { echo "FAIL: noext was written"; FAILS=$((FAILS + 1)); }
expect_exit 2 "--bits 32 for png" -- "$RTS" render "$TMP/s.rts" -o "$TMP/a.png" --bits 32 --no-progress
expect_grep "$TMP/err" "not available for .png" "the message says why"
expect_exit 2 "--bits 8 for exr" -- "$RTS" render "$TMP/s.rts" -o "$TMP/a.exr" --bits 8 --no-progress
expect_exit 2 "--depth-range needs two numbers" -- "$RTS" render "$TMP/s.rts" -o "$TMP/a.png" --depth-range 3 --no-progress
expect_exit 2 "--depth-range far before near" -- "$RTS" render "$TMP/s.rts" -o "$TMP/a.png" --depth-range 9,3 --no-progress
expect_exit 2 "--depth-miss nan" -- "$RTS" render "$TMP/s.rts" -o "$TMP/a.png" --depth-miss nan --no-progress

# A device has no extension: PNG, as before.
expect_exit 0 "-o /dev/null is still a PNG device" -- "$RTS" render "$TMP/s.rts" -o /dev/null --no-progress
"$RTS" render "$TMP/s.rts" -o /dev/stdout --no-progress 2>/dev/null | head -c 4 | od -An -tx1 | tr -d ' ' >"$TMP/magic"
expect_grep "$TMP/magic" "^89504e47$" "-o /dev/stdout writes PNG bytes"

# Each format's own bytes.
expect_exit 0 "-o .pfm" -- "$RTS" render "$TMP/s.rts" -o "$TMP/a.pfm" --no-progress
[[ "$(head -c 3 "$TMP/a.pfm" | od -An -c | tr -d ' ')" == 'PF\n' ]] || { echo "FAIL: a.pfm is not a PFM"; FAILS=$((FAILS + 1)); }
expect_exit 0 "-o .EXR (any case) with AOV layers" -- "$RTS" render "$TMP/s.rts" -o "$TMP/a.EXR" --aov depth,normal --no-progress
[[ "$(head -c 4 "$TMP/a.EXR" | od -An -tx1 | tr -d ' ')" == "762f3101" ]] || { echo "FAIL: a.EXR is not OpenEXR"; FAILS=$((FAILS + 1)); }
[[ -e "$TMP/a.depth.EXR" ]] && { echo "FAIL: EXR AOVs should be layers, not files"; FAILS=$((FAILS + 1)); }
expect_exit 0 "--aov-files" -- "$RTS" render "$TMP/s.rts" -o "$TMP/b.exr" --aov depth --aov-files --bits 16 --no-progress
[[ -s "$TMP/b.depth.exr" ]] || { echo "FAIL: --aov-files wrote no b.depth.exr"; FAILS=$((FAILS + 1)); }
expect_exit 0 "-o .png" -- "$RTS" render "$TMP/s.rts" -o "$TMP/a.png" --no-progress
[[ "$(head -c 4 "$TMP/a.png" | od -An -tx1 | tr -d ' ')" == "89504e47" ]] || { echo "FAIL: a.png is not a PNG"; FAILS=$((FAILS + 1)); }

# --linear: emission 0.5 is stored as code 128 (round(0.5 * 255)), sRGB as 188.
expect_exit 0 "--linear" -- "$RTS" render "$TMP/s.rts" -o "$TMP/lin.png" --linear --no-progress
if command -v python3 >/dev/null; then
  code() { python3 -c 'import sys,zlib
d=open(sys.argv[1],"rb").read(); i=8; idat=b""
while i < len(d):
    n=int.from_bytes(d[i:i+4],"big"); t=d[i+4:i+8]
    if t==b"IDAT": idat+=d[i+8:i+8+n]
    i+=12+n
print(zlib.decompress(idat)[1])' "$1"; }
  [[ "$(code "$TMP/lin.png")" == 128 ]] || { echo "FAIL: --linear stored $(code "$TMP/lin.png"), expected 128"; FAILS=$((FAILS + 1)); }
  [[ "$(code "$TMP/a.png")" == 188 ]] || { echo "FAIL: sRGB stored $(code "$TMP/a.png"), expected 188"; FAILS=$((FAILS + 1)); }
fi
finish
