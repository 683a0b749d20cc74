#!/usr/bin/env bash
# Hostile and mistaken inputs (issue 7; docs/reliability.md has the table): each ends within
# bounded time and memory with a located error and the right exit code, never a crash.
source "$(dirname "$0")/lib.sh"
RTS="$(cd "$(dirname "$RTS")" && pwd)/$(basename "$RTS")"  # some cases run from another folder
# Address-space limits (ulimit -v) cannot be combined with AddressSanitizer's shadow memory.
if grep -q __asan_init "$RTS"; then SANITIZED=1; else SANITIZED=0; fi
# The memory limit for the --max-memory cases. It bounds the whole process's resident size, and
# a sanitized rts starts at about 80 MB (shadow memory), so there it is 160M; every case below
# still needs far more than the limit leaves.
if [[ $SANITIZED == 1 ]]; then MEM=160M MEM_WORDS="160 MiB"; else MEM=64M MEM_WORDS="64 MiB"; fi
T=(timeout 60)  # a hang fails the test instead of hanging it
# expect_no_grep FILE PATTERN DESCRIPTION
expect_no_grep() {
  if grep -qE -- "$2" "$1"; then echo "FAIL: $3: /$2/ found in:"; cat "$1"; FAILS=$((FAILS + 1)); fi
}
ok_scene='settings { width = 8 height = 8 }
point_light { position = <0, 5, -5> }
sphere { radius = 1 }'
printf '%s\n' "$ok_scene" > "$TMP/ok.rts"

# ---- flags: negative, overflowing, fractional values are usage errors naming the range -----
for flag in --max-iterations --max-steps --max-objects --max-mesh-triangles --max-recursion; do
  for bad in -1 99999999999999999999 1.5 0; do
    expect_exit 2 "check $flag $bad" -- "$RTS" check "$TMP/ok.rts" "$flag" "$bad"
    expect_grep "$TMP/err" "$flag.*must be a whole number from 1 to [0-9,]+, got '$bad'" "$flag $bad names the range"
  done
done
expect_exit 2 "--max-recursion past what the stack holds" -- "$RTS" check "$TMP/ok.rts" --max-recursion 1000000
for args in "--seed -1" "--seed 9007199254740993" "--threads -1" "--width 0" "--height -5" \
            "--samples 0" "--samples 1000000000" "--max-depth -1" "--max-depth 99999999999" \
            "--max-memory -1" "--max-memory 1K" "--max-memory 12X"; do
  # shellcheck disable=SC2086
  expect_exit 2 "render $args" -- "$RTS" render "$TMP/ok.rts" -o "$TMP/flags.png" --no-progress $args
  expect_grep "$TMP/err" "must be a (whole number from|size of at least)" "render $args states the range"
done
expect_no_grep "$TMP/err" "1797693134862315" "ranges are in words, not DBL_MAX"
expect_exit 2 "empty output name" -- "$RTS" render "$TMP/ok.rts" -o '' --no-progress
expect_grep "$TMP/err" "file name is empty" "-o '' says why"
expect_exit 0 "sizes with units" -- "$RTS" check "$TMP/ok.rts" --max-memory 2G --max-steps 1000 --max-recursion 100000

# ---- runaway evaluation: step budget, memory budget -----------------------------------------
printf 'macro f(d) {\n  if d > 0 { f(d - 1)  f(d - 1) }\n}\nf(60)\n' > "$TMP/macro_bomb.rts"
expect_exit 1 "doubling macro recursion (defect 3)" -- "${T[@]}" "$RTS" check "$TMP/macro_bomb.rts" --max-steps 100000
expect_grep "$TMP/err" "macro_bomb.rts:2:[0-9]+: error: evaluation ran more than 100000 steps.*calls to macro 'f'.*--max-steps" \
  "the runaway macro and the flag are named"
printf 'let xs = [1]\nfor i in 0 .. 64 { xs = xs + xs }\n' > "$TMP/list_bomb.rts"
expect_exit 1 "doubling list, memory budget (defect 4)" -- "${T[@]}" "$RTS" check "$TMP/list_bomb.rts" --max-memory 256M
expect_grep "$TMP/err" "list_bomb.rts:2:[0-9]+: error: .*memory limit of 256 MiB.*--max-memory" "memory error is located"
expect_exit 1 "doubling list, step budget" -- "${T[@]}" "$RTS" check "$TMP/list_bomb.rts" --max-steps 10000000
expect_grep "$TMP/err" "list_bomb.rts:2:[0-9]+: error: .*list elements built.*--max-steps" "step budget names the list"
printf 'let s = "ab"\nfor i in 0 .. 64 { s = s + s }\n' > "$TMP/string_bomb.rts"
expect_exit 1 "doubling string (defect 4)" -- "${T[@]}" "$RTS" check "$TMP/string_bomb.rts"
expect_grep "$TMP/err" "string_bomb.rts:2:[0-9]+: error: " "string error is located"
# A list that holds itself twice, 40 times over, is small, but its text has 2^40 elements:
# print, str, format, error and assert stop converting it at the step or memory budget.
for fn in print str error; do
  printf 'let xs = [1]\nfor i in 0 .. 40 { xs = [xs, xs] }\n%s(xs)\n' "$fn" > "$TMP/text_bomb_$fn.rts"
  expect_exit 1 "$fn of a self-doubled list, step budget" -- "${T[@]}" "$RTS" check "$TMP/text_bomb_$fn.rts" \
    --max-steps 1000000
  expect_grep "$TMP/err" "text_bomb_$fn.rts:3:1: error: evaluation ran more than 1000000 steps.*string bytes built" \
    "$fn's runaway text is located"
done
expect_exit 1 "print of a self-doubled list, memory budget" -- "${T[@]}" "$RTS" check "$TMP/text_bomb_print.rts" \
  --max-memory "$MEM" --max-steps 100000000000
expect_grep "$TMP/err" "text_bomb_print.rts:3:1: error: this text would need more than [0-9.]+ MiB more memory, past the memory limit of $MEM_WORDS" \
  "the text's memory error is located"
# Under an address-space ulimit the system refuses first: still located, exit 1, never
# "internal error: std::bad_alloc" (exit 70).
if [[ $SANITIZED == 0 ]]; then
  expect_exit 1 "doubling list under ulimit -v (defect 4)" -- "${T[@]}" bash -c \
    "ulimit -v 800000; exec \"\$0\" check \"\$1\" --max-memory 100G --max-steps 100000000000" "$RTS" "$TMP/list_bomb.rts"
  expect_grep "$TMP/err" "list_bomb.rts:2:[0-9]+: error: out of memory" "bad_alloc becomes a located error"
  expect_no_grep "$TMP/err" "internal error" "no internal error"

  # A small scene under address-space limits from too small (the program maps ~18 MB itself) to
  # plenty: it renders, or says it ran out of memory or threads (exit 1 or 3); never an internal
  # error. The evaluation thread's stack once took what would map, leaving a small file's
  # evaluation a few MB: "internal error: std::bad_alloc" under 100 MB but not under 80 (the
  # limit counts mapped ranges, not use).
  for limit in 30000 45000 60000 80000 100000 150000 300000; do
    expect_exit "0 1 3" "small render under ulimit -v $limit" -- "${T[@]}" bash -c \
      "ulimit -v $limit; exec \"\$0\" render \"\$1\" -o \"\$2\" --no-progress" "$RTS" "$TMP/ok.rts" "$TMP/limited.png"
    expect_no_grep "$TMP/err" "internal error" "no internal error under ulimit -v $limit"
  done
  expect_exit 0 "small check under ulimit -v 100000" -- "${T[@]}" bash -c \
    "ulimit -v 100000; exec \"\$0\" check \"\$1\"" "$RTS" "$TMP/ok.rts"

  # ---- deep recursion when the stack it needs cannot be mapped (defect 2) ---------------------
  # 60 nested ifs make each level use ~17 KB of stack: 40,000 levels need far more than the
  # ~200 MB stack that fits under this ulimit (about 700 MB).
  { printf 'macro f(d) { '; for i in $(seq 60); do printf 'if d > 0 { '; done; printf 'f(d - 1)'
    for i in $(seq 60); do printf ' }'; done; printf ' }\nf(40000)\n'; } > "$TMP/deep.rts"
  expect_exit 1 "deep recursion, stack cannot be mapped (defect 2)" -- "${T[@]}" bash -c \
    "ulimit -v 400000; exec \"\$0\" check \"\$1\" --max-recursion 100000" "$RTS" "$TMP/deep.rts"
  expect_grep "$TMP/err" "deep.rts:1:[0-9]+: error: (evaluation nested too deeply for its [0-9]+ MiB stack|out of memory)" \
    "stack exhaustion is a located error"
fi

# The image and its AOVs are checked against --max-memory before they are allocated.
expect_exit 3 "image past the memory limit" -- "$RTS" render "$TMP/ok.rts" -o "$TMP/big.png" --no-progress \
  --width 20000 --height 5000 --aov normal,depth --max-memory "$MEM"
expect_grep "$TMP/err" "ok.rts:1:1: error: a 20000x5000 image and its AOVs needs [0-9.]+ GiB, past the memory limit of $MEM_WORDS" \
  "image memory error is located"
# So is an image texture, from its header, before its pixels are decoded: a 4000x4000 PNG of
# 16 KB needs about 240 MiB as linear floats.
python3 - "$TMP/huge_texture.png" <<'PY'
import struct, sys, zlib
w = h = 4000
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
rows = zlib.compress((b"\0" + bytes(w)) * h, 9)
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0)) + chunk(b"IDAT", rows) + chunk(b"IEND", b"")
open(sys.argv[1], "wb").write(png)
PY
printf 'settings { width = 8 height = 8 }
point_light { position = <0, 5, -5> }
sphere { radius = 1
  material = material { texture = image_texture { file = "huge_texture.png" } } }
' \
  > "$TMP/huge_texture.rts"
expect_exit 3 "image texture past the memory limit" -- "${T[@]}" "$RTS" render "$TMP/huge_texture.rts" \
  -o "$TMP/huge_texture_out.png" --no-progress --max-memory "$MEM"
expect_grep "$TMP/err" "huge_texture.rts:4:[0-9]+: error: cannot read image .*huge_texture.png': its 4000x4000 pixels need [0-9.]+ MiB more memory, past the memory limit of $MEM_WORDS \(raise it with --max-memory\)" \
  "texture memory error is located"
expect_exit 0 "the same texture within the default limit" -- "${T[@]}" "$RTS" render "$TMP/huge_texture.rts" \
  -o "$TMP/huge_texture_out.png" --no-progress

# ---- groups multiplying instances (defect 6) ------------------------------------------------
printf 'let g = group { sphere { radius = 1 } }\nfor i in 0 .. 40 {\n  g = group { g  g translate <1,0,0> }\n}\ng\n' \
  > "$TMP/group_bomb.rts"
expect_exit 1 "check: groups doubling 40 times" -- "${T[@]}" "$RTS" check "$TMP/group_bomb.rts"
expect_grep "$TMP/err" "group_bomb.rts:3:[0-9]+: error: this group expands to [0-9]+ objects.*--max-objects" \
  "the expanding group is located"
expect_exit 1 "render: groups doubling 40 times" -- "${T[@]}" "$RTS" render "$TMP/group_bomb.rts" -o "$TMP/g.png" --no-progress

# ---- samples (defect 12) --------------------------------------------------------------------
printf 'settings { width = 16 height = 16\n  samples = 1000000000 }\nsphere { radius = 1 }\n' > "$TMP/samples.rts"
expect_exit 1 "samples = 1e9" -- "$RTS" check "$TMP/samples.rts"
expect_grep "$TMP/err" "samples.rts:2:[0-9]+: error: property 'samples' of settings must be from 1 to 65536" "samples cap"
printf '%s\narea_light { position = <0, 5, 0>  u = <1, 0, 0>  v = <0, 0, 1>\n  samples = 5000 }\n' "$ok_scene" \
  > "$TMP/area.rts"
expect_exit 0 "area light samples clamped" -- "$RTS" check "$TMP/area.rts"
expect_grep "$TMP/err" "area.rts:5:3: warning: area_light samples 5000 is more than 4096; 4096 are used" \
  "the clamp is announced"

# ---- files: OBJ mtllib, FIFOs, directories, read restrictions -------------------------------
mkdir -p "$TMP/scene/sub" "$TMP/outside" "$TMP/cwd"; export TMP
printf 'mtllib ../../../../../../../../dev/zero\nmtllib /etc/passwd\nusemtl x\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' \
  > "$TMP/scene/evil.obj"
printf '%s\nmesh { file = "evil.obj" }\n' "$ok_scene" > "$TMP/scene/mtl.rts"
expect_exit 0 "OBJ mtllib naming /dev/zero and /etc/passwd is never read (defect 7)" -- \
  "${T[@]}" "$RTS" render "$TMP/scene/mtl.rts" -o "$TMP/mtl.png" --no-progress
# Mesh triangles are counted while the file is read, before its arrays are built.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\nf 1 2 4 3\n' > "$TMP/scene/quads.obj"
printf '%s\nmesh { file = "quads.obj" }\n' "$ok_scene" > "$TMP/scene/tris.rts"
expect_exit 1 "OBJ past --max-mesh-triangles" -- "$RTS" check "$TMP/scene/tris.rts" --max-mesh-triangles 3
expect_grep "$TMP/err" "tris.rts:4:[0-9]+: error: mesh file quads.obj:7: more than 3 triangles.*--max-mesh-triangles" \
  "the OBJ line that passes the limit is named"
expect_exit 0 "OBJ within --max-mesh-triangles" -- "$RTS" check "$TMP/scene/tris.rts" --max-mesh-triangles 4
mkfifo "$TMP/scene/pipe.png" "$TMP/scene/pipe.rts" "$TMP/scene/pipe.obj"
printf '%s\nsphere { radius = 1 material = material { color = image_texture("pipe.png") } }\n' "$ok_scene" \
  > "$TMP/scene/fifo_tex.rts"
expect_exit 1 "check: image texture on a FIFO (defect 8)" -- "${T[@]}" "$RTS" check "$TMP/scene/fifo_tex.rts"
expect_grep "$TMP/err" "fifo_tex.rts:4:[0-9]+: error: cannot read image 'pipe.png': it is a FIFO" "the FIFO is named as such"
expect_exit 1 "render: image texture on a FIFO" -- "${T[@]}" "$RTS" render "$TMP/scene/fifo_tex.rts" -o "$TMP/f.png" --no-progress
printf '%s\nmesh { file = "pipe.obj" }\n' "$ok_scene" > "$TMP/scene/fifo_mesh.rts"
expect_exit 1 "mesh on a FIFO" -- "${T[@]}" "$RTS" check "$TMP/scene/fifo_mesh.rts"
expect_grep "$TMP/err" "it is a FIFO" "mesh FIFO named"
printf 'include "pipe.rts"\n' > "$TMP/scene/inc_fifo.rts"
expect_exit 1 "include of a FIFO" -- "${T[@]}" "$RTS" check "$TMP/scene/inc_fifo.rts"
expect_grep "$TMP/err" "inc_fifo.rts:1:1: error: cannot include 'pipe.rts': .* is a FIFO \(named pipe\)" "include FIFO named"
printf 'include "sub"\n' > "$TMP/scene/inc_dir.rts"
expect_exit 1 "include of a directory" -- "$RTS" check "$TMP/scene/inc_dir.rts"
expect_grep "$TMP/err" "cannot include 'sub': .* is a directory" "include directory named"
printf '%s\nsphere { radius = 1 material = material { color = image_texture("sub") } }\n' "$ok_scene" > "$TMP/scene/tex_dir.rts"
expect_exit 1 "image texture on a directory" -- "$RTS" check "$TMP/scene/tex_dir.rts"
expect_grep "$TMP/err" "it is a directory" "texture directory named"

# Reads outside the scene's folder, -I and the current folder are refused unless allowed.
printf 'let c = rgb(1, 0, 0)\n' > "$TMP/outside/lib.rts"
printf '%s\ninclude "../outside/lib.rts"\n' "$ok_scene" > "$TMP/scene/inc_out.rts"
expect_exit 1 "include outside the scene folder" -- bash -c 'cd "$TMP/cwd" && exec "$0" check "$1"' "$RTS" "$TMP/scene/inc_out.rts"
expect_grep "$TMP/err" "inc_out.rts:4:1: error: reading '../outside/lib.rts' is not allowed.*--allow-read .*outside" \
  "refusal is located and names the flag"
expect_exit 0 "--allow-read widens" -- bash -c 'cd "$TMP/cwd" && exec "$0" check "$1" --allow-read "$2"' "$RTS" "$TMP/scene/inc_out.rts" "$TMP/outside"
expect_exit 0 "-I widens" -- bash -c 'cd "$TMP/cwd" && exec "$0" check "$1" -I "$2"' "$RTS" "$TMP/scene/inc_out.rts" "$TMP/outside"
expect_exit 0 "the current folder is allowed" -- bash -c 'cd "$2" && exec "$0" check "$1"' "$RTS" "$TMP/scene/inc_out.rts" "$TMP/outside"
ln -s "$TMP/outside/lib.rts" "$TMP/scene/link.rts"
printf 'include "link.rts"\n' > "$TMP/scene/inc_link.rts"
expect_exit 1 "a symlink out of the folder is refused" -- bash -c 'cd "$TMP/cwd" && exec "$0" check "$1"' "$RTS" "$TMP/scene/inc_link.rts"
cp "$TMP/scene/evil.obj" "$TMP/outside/m.obj"
printf '%s\nmesh { file = "../outside/m.obj" }\n' "$ok_scene" > "$TMP/scene/mesh_out.rts"
expect_exit 1 "mesh outside the scene folder" -- bash -c 'cd "$TMP/cwd" && exec "$0" check "$1"' "$RTS" "$TMP/scene/mesh_out.rts"
expect_grep "$TMP/err" "mesh_out.rts:4:[0-9]+: error: reading '../outside/m.obj' is not allowed" "mesh refusal located"
printf '%s\nsphere { radius = 1 material = material { color = image_texture("/etc/hostname.png") } }\n' "$ok_scene" \
  > "$TMP/scene/tex_out.rts"
expect_exit 1 "texture outside the scene folder" -- bash -c 'cd "$TMP/cwd" && exec "$0" check "$1"' "$RTS" "$TMP/scene/tex_out.rts"
expect_grep "$TMP/err" "not allowed.*--allow-read /etc" "texture refusal names the folder to allow"

# A file that is not a scene is never shown (its first line used to appear in a syntax error).
printf 'include "/etc/passwd"\n' > "$TMP/scene/passwd.rts"
expect_exit 1 "include /etc/passwd" -- "$RTS" check "$TMP/scene/passwd.rts"
expect_grep "$TMP/err" "passwd.rts:1:1: error: reading '/etc/passwd' is not allowed" "refused by the read rule"
expect_exit 1 "include /etc/passwd with --allow-read /" -- "$RTS" check "$TMP/scene/passwd.rts" --allow-read /
expect_grep "$TMP/err" "included files must be scene files named \*.rts or \*.inc" "refused as not a scene"
expect_no_grep "$TMP/err" "root:" "no line of /etc/passwd is printed"
printf 'v 1 2 secret\nf the password\n' > "$TMP/scene/notes.txt"
printf '%s\nmesh { file = "notes.txt" }\n' "$ok_scene" > "$TMP/scene/mesh_txt.rts"
expect_exit 1 "a mesh file that is not an OBJ" -- "$RTS" check "$TMP/scene/mesh_txt.rts"
expect_grep "$TMP/err" "mesh files must be Wavefront OBJ files named \*.obj" "refused as not an OBJ"
expect_no_grep "$TMP/err" "secret|password" "no line of it is printed"

# ---- messages -------------------------------------------------------------------------------
{ printf 'let xs = ['; for i in $(seq 1 100000); do printf '%d, ' "$i"; done; printf 'oops ]\n'; } > "$TMP/long_line.rts"
expect_exit 1 "error on a 600 KB line" -- "$RTS" check "$TMP/long_line.rts"
expect_grep "$TMP/err" "long_line.rts:1:[0-9]+: error: undefined name 'oops'" "the error is located"
bytes=$(wc -c < "$TMP/err")
if [[ $bytes -gt 1000 ]]; then echo "FAIL: the excerpt of a long line is not bounded ($bytes bytes)"; FAILS=$((FAILS + 1)); fi
expect_grep "$TMP/err" '^    \.\.\..*oops \]$' "the excerpt is a window around the column"
expect_grep "$TMP/err" '^ +\^$' "with a caret"
printf 'settings { width = 8 height = 8 }\nsphere { radius = 1\n  material = material { color = image_texture("missing.png") } }\n' \
  > "$TMP/render_err.rts"
expect_exit 3 "render error" -- "$RTS" render "$TMP/render_err.rts" -o "$TMP/r.png" --no-progress
expect_grep "$TMP/err" "render_err.rts:3:[0-9]+: error: cannot read image" "render error located"
expect_grep "$TMP/err" 'image_texture\("missing.png"\)' "render error shows the source line"
expect_grep "$TMP/err" '^ +\^$' "render error shows a caret"
printf 'let m = material { color = rgb(1, 0, 0) }\n' > "$TMP/nothing.rts"
expect_exit 0 "a scene that places nothing" -- "$RTS" render "$TMP/nothing.rts" -o "$TMP/n.png" --no-progress --width 8 --height 8
expect_grep "$TMP/err" "nothing.rts: warning: the scene places no objects" "placing nothing is announced"
printf 'sphere { radius = 1 }\n' > "$TMP/unlit.rts"
expect_exit 0 "a scene that lights nothing" -- "$RTS" render "$TMP/unlit.rts" -o "$TMP/u.png" --no-progress --width 8 --height 8
expect_grep "$TMP/err" "unlit.rts: warning: the scene places no lights" "lighting nothing is announced"
expect_exit 0 "a lit scene" -- "$RTS" render "$TMP/ok.rts" -o "$TMP/ok.png" --no-progress
expect_no_grep "$TMP/err" "warning" "no warning for a lit scene"
finish
