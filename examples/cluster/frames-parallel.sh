#!/bin/bash
# The same frames with GNU parallel on one or more machines: 4 tasks, 2 at a time here
# (add -S host1,host2 to spread them over ssh; the folder must be shared). Rerun the same
# line after a crash: --skip-existing renders only the missing frames.
mkdir -p out
parallel -j2 rts render examples/cluster/bounce.rts -o out/bounce_####.png \
  --threads 1 --skip-existing --no-progress --task-count 4 --task-index ::: 0 1 2 3
