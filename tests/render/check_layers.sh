#!/usr/bin/env bash
# render/'s stages include one another one way only: each file under render/<stage>/ may include
# render/<stage>/ and the stages render/CMakeLists.txt lets that stage use (written to
# render_layers.txt at configure time); the renderer's own files (render/*.cpp) may include any
# stage; and nothing in render/ includes the scene language (grammar/, parser/, runtime/, cli/).
# Prints every include that points the wrong way and fails if there is one.
# Usage: check_layers.sh <source root> <build dir>/render_layers.txt
set -euo pipefail
root=$1
layers=$2
declare -A uses
while IFS=: read -r stage deps; do
  [[ -n $stage ]] && uses[$stage]="$stage $deps"
done <"$layers"
[[ ${#uses[@]} -ge 6 ]] || { echo "FAIL: $layers names only ${#uses[@]} stages"; exit 1; }

bad=0
checked=0
while IFS= read -r file; do
  rel=${file#"$root"/render/}
  stage=${rel%%/*}
  [[ $rel == */* ]] || stage=""  # render/*.cpp: the renderer on top
  while IFS= read -r line; do
    target=$(sed -E 's/^[0-9]+:#include "([^"]+)".*/\1/' <<<"$line")
    checked=$((checked + 1))
    case $target in
      grammar/* | parser/* | runtime/* | cli/* | dist/* | import/* | lsp/*)
        echo "render/$rel:${line%%:*}: includes $target: render/ knows nothing of the layers above it"
        bad=1
        continue
        ;;
      render/*) ;;
      *) continue ;;
    esac
    [[ -z $stage ]] && continue
    inner=${target#render/}
    if [[ $inner != */* ]]; then
      echo "render/$rel:${line%%:*}: includes $target: the renderer's files are above every stage"
      bad=1
      continue
    fi
    to=${inner%%/*}
    if [[ -z ${uses[$stage]+x} ]]; then
      echo "render/$rel: stage '$stage' is not in $layers (add it to render/CMakeLists.txt)"
      bad=1
      continue
    fi
    if [[ " ${uses[$stage]} " != *" $to "* ]]; then
      echo "render/$rel:${line%%:*}: includes $target: $stage may use only ${uses[$stage]}"
      bad=1
    fi
  done < <(grep -nE '^#include "' "$file" || true)
done < <(find "$root/render" -name '*.cpp' -o -name '*.hpp' -o -name '*.h' | sort)

[[ $checked -gt 100 ]] || { echo "FAIL: only $checked includes found under $root/render"; exit 1; }
if [[ $bad -ne 0 ]]; then
  echo "FAIL: includes above point the wrong way (README.md, Layout, has the layers)"
  exit 1
fi
echo "ok: $checked includes, every one pointing down"
