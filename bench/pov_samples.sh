#!/usr/bin/env bash
# POV-Ray's own sample scenes through `rts import`: imports every scene under
# /usr/share/povray-3.7/scenes (Debian's povray-examples; read from there, never copied),
# renders the translation with rts at 320x240 and the scene with POV-Ray 3.7 in the same run
# (both without antialiasing), and compares them: a scene MATCHES when the mean absolute
# difference is at most 2 codes of 255 (for scenes with noise patterns, whose noise differs in
# detail, the mean over 40-pixel blocks). For each failure the first missing feature: the
# import's first warning, rts's error, or the difference.
#
#   bench/pov_samples.sh [OUT_DIR] [FILTER]     # FILTER: a grep -E pattern on the scene paths
#   bench/pov_samples.sh --summary OUT_DIR      # the table of a run so far
#
# Writes OUT_DIR/results.tsv (one row per scene) and prints the summary table for
# docs/from-povray.md. Needs povray and povray-examples (scripts/ensure-deps --bench).
# Long: run it in the background with nice. RTS_BINARY picks the rts to test;
# POV_SAMPLES_TIMEOUT (default 120) the seconds each program gets per scene.
set -u
summary() {
  local results="$1/results.tsv" total imp ren mat
  total=$(($(wc -l < "$results") - 1))
  imp=$(awk -F'\t' 'NR > 1 && $2 == "yes"' "$results" | wc -l)
  ren=$(awk -F'\t' 'NR > 1 && $3 == "yes"' "$results" | wc -l)
  mat=$(awk -F'\t' 'NR > 1 && $7 == "yes"' "$results" | wc -l)
  pct() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%d (%.0f%%)", a, b ? 100 * a / b : 0 }'; }
  echo "| scenes | import | render in rts | match POV-Ray (MAD <= 2) |"
  echo "|---|---|---|---|"
  echo "| $total | $(pct "$imp" "$total") | $(pct "$ren" "$total") | $(pct "$mat" "$total") |"
  echo
  echo "First missing feature, by how many scenes it stops:"
  awk -F'\t' 'NR > 1 && $7 != "yes" { m = $8; sub(/;.*/, "", m); print m }' "$results" |
    sed -E 's/\(MAD [0-9.]+\)//; s/ +$//' | sort | uniq -c | sort -rn | head -30
}
if [[ "${1:-}" == "--summary" ]]; then summary "$2"; exit 0; fi

root="$(cd "$(dirname "$0")/.." && pwd)"
scenes=/usr/share/povray-3.7/scenes
out="${1:-$root/build/pov_samples}"
filter="${2:-.}"
rts="${RTS_BINARY:-$root/build/cli/rts}"
timeout_s="${POV_SAMPLES_TIMEOUT:-120}"
[[ -x "$rts" ]] || { echo "no rts at $rts (build first or set RTS_BINARY)" >&2; exit 2; }
command -v povray >/dev/null || { echo "povray is not installed (scripts/ensure-deps --bench)" >&2; exit 2; }
[[ -d "$scenes" ]] || { echo "$scenes is missing (apt-get install povray-examples)" >&2; exit 2; }
mkdir -p "$out"
out="$(cd "$out" && pwd)"
results="$out/results.tsv"
printf 'scene\timported\trendered\tmad\tblock_mad\tnoise\tmatch\tfirst_missing\n' > "$results"
# (also the library's names built on noise patterns, which a scene may use through an include)
noise='bozo|spotted|granite|marble|wood|agate|leopard|wrinkles|crackle|bumps|dents|ripples|waves|turbulence|cells|onion|T_Wood|P_WoodGrain|T_Stone|T_Grnt'
find -L "$scenes" -name '*.pov' | sort | grep -E -- "$filter" | while read -r scene; do
  rel="${scene#$scenes/}"
  name="$(echo "${rel%.pov}" | tr '/' '_')"
  dir="$out/$name"
  mkdir -p "$dir"
  imported=no rendered=no mad=- block=- match=no missing=-
  grep -qE "$noise" "$scene" && is_noise=yes || is_noise=no
  if timeout "$timeout_s" "$rts" import "$scene" -o "$dir/scene.rts" 2> "$dir/import.log" < /dev/null; then
    imported=yes
    grep -qE "$noise" "$dir"/*.rts && is_noise=yes   # the scene's own includes, translated beside it
    missing="$(grep -m1 -oE "warning: .*" "$dir/import.log" | sed 's/^warning: //' | cut -c1-110)"
    [[ -z "$missing" ]] && missing=-
    # The translation lives in its own folder: images beside the POV-Ray scene, or in its
    # library folder, are read from there (rts reads outside a scene's folder only where allowed;
    # Debian's scenes folder is a link to /usr/share/doc/povray/examples, the path rts checks).
    if (cd "$dir" && timeout "$timeout_s" nice "$rts" render scene.rts -o rts.png --width 320 --height 240 --threads 1 \
          --no-progress --allow-read "$(dirname "$scenes")" --allow-read "$(readlink -f "$scenes")") 2> "$dir/render.log" < /dev/null; then
      rendered=yes
    else
      missing="rts: $(grep -m1 -E "error" "$dir/render.log" | sed 's/^[^ ]*: error: //' | cut -c1-110)"
      [[ "$missing" == "rts: " ]] && missing="rts: timed out after ${timeout_s}s"
    fi
  else
    missing="import: $(grep -m1 -E "error" "$dir/import.log" | sed 's/^[^ ]*: error: //' | cut -c1-110)"
  fi
  if [[ $rendered == yes ]]; then
    (cd "$(dirname "$scene")" && timeout "$timeout_s" nice povray +I"$scene" +O"$dir/pov.png" +W320 +H240 -A -D -V +WT1 \
        +FN +L/usr/share/povray-3.7/include > "$dir/povray.log" 2>&1 < /dev/null)
    if [[ -f "$dir/pov.png" ]]; then
      read -r mad block < <(python3 "$root/bench/png_compare.py" "$dir/pov.png" "$dir/rts.png" 40 || echo "- -")
      value="$mad"
      [[ $is_noise == yes ]] && value="$block"
      if [[ "$value" != "-" ]] && awk -v m="$value" 'BEGIN { exit !(m <= 2) }'; then
        match=yes
      elif [[ "$missing" == "-" ]]; then
        missing="picture differs (MAD $mad)"
      fi
    else
      missing="POV-Ray itself did not render it in ${timeout_s}s"
    fi
  fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$rel" "$imported" "$rendered" "$mad" "$block" "$is_noise" "$match" \
      "$missing" >> "$results"
  echo "$rel: imported=$imported rendered=$rendered mad=$mad block=$block match=$match  $missing"
done
echo
summary "$out"
