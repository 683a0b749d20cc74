#!/usr/bin/env bash
# casts_shadow = false end to end. The camera looks down at a floor; a ball and a box above
# it, outside the view, stand between the floor and the lights (a point light and an area
# light). With casts_shadow = false on the ball and on the group holding the box, the image
# must be byte-identical to the scene without them; with casts_shadow left true it must not
# be (their shadows fall in view). A part of a CSG block with casts_shadow = false is a
# located warning.
source "$(dirname "$0")/lib.sh"
cd "$TMP"
size=(--width 48 --height 36 --threads 2 --no-progress)
head='settings { width = 48  height = 36  samples = 4 }
camera { position = <0, 4, 0>  look_at = <0, 0, 0.01>  fov = 50 }
point_light { position = <0, 12, 3> }
area_light { position = <0, 12, -3>  u = <1, 0, 0>  v = <0, 0, 1>  samples = 4  intensity = 0.5 }
plane { normal = <0, 1, 0>  material = material { color = rgb(0.8) } }'
ball='sphere { center = <0, 6, 1.5>  radius = 0.8 CAST }
group { box { min = <-0.6, 5.5, -2> max = <0.6, 6.5, -1> } CAST }'
echo "$head" > none.rts
{ echo "$head"; echo "${ball//CAST/casts_shadow = false}"; } > shadowless.rts
{ echo "$head"; echo "${ball//CAST/}"; } > casting.rts
for v in none shadowless casting; do
  expect_exit 0 "render ($v)" -- "$RTS" render "$v.rts" -o "$v.png" "${size[@]}"
done
cmp -s none.png shadowless.png || { echo "FAIL: objects that cast no shadow changed the picture"; FAILS=$((FAILS + 1)); }
cmp -s none.png casting.png && { echo "FAIL: the objects' shadows are not in view: the test checks nothing"; FAILS=$((FAILS + 1)); }
{ echo "$head"; echo 'sphere { center = <0, 6, 1.5>  radius = 0.8 }'; } > ball.rts
{ echo "$head"; echo 'sphere { center = <0, 6, 1.5>  radius = 0.8  casts_shadow = true }'; } > ball_true.rts
expect_exit 0 "render (ball)" -- "$RTS" render ball.rts -o ball.png "${size[@]}"
expect_exit 0 "render (ball, casts_shadow = true)" -- "$RTS" render ball_true.rts -o ball_true.png "${size[@]}"
cmp -s ball.png ball_true.png || { echo "FAIL: casts_shadow = true is not the default"; FAILS=$((FAILS + 1)); }

printf 'union {\n  sphere { radius = 1  casts_shadow = false }\n  box { min = <0, 0, 0>  max = <1, 1, 1> }\n}\n' > part.rts
expect_exit 0 "a CSG part's casts_shadow is a warning" -- "$RTS" render part.rts -o part.png "${size[@]}"
expect_grep "$TMP/err" "^part.rts:2:3: warning: casts_shadow = false on a part of 'union' has no effect" "located warning"
finish
