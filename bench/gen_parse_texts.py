#!/usr/bin/env python3
"""Texts for the parser's memory beyond bench/parse.sh's generated scene (issue 24): each
about --mb megabytes, written to OUT_DIR:

  rich.rts    objects with inline materials, rgb() calls and transforms (3-digit numbers)
  vectors.rts one list of <x, y, z> vectors with 4- and 5-digit numbers (denser in numbers
              than any scene)
  arith.rts   only arithmetic: `let v1 = 4 + 3 * x - (9 / 2)` a line (denser in operators
              than any scene)

Each is a valid scene (`rts check`). Measure with `/usr/bin/time -f %M rts parse --quiet
OUT_DIR/rich.rts` (docs/performance.md, "Tenth session").
"""
import argparse
import os
import random


def rich(f, size, rnd):
    r = lambda a, b: '%.3g' % rnd.uniform(a, b)
    f.write('camera { position = <0, 5, -20> look_at = <0, 0, 0> }\n'
            'point_light { position = <10, 20, -10> }\n')
    n = i = 0
    while n < size:
        k = i % 4
        if k == 0:
            line = ('sphere { center = <%s, %s, %s> radius = %s material = material { color = rgb(%s, %s, %s) '
                    'diffuse = 0.7 specular = 0.3 } }\n' % (r(-50, 50), r(-50, 50), r(-50, 50), r(0.1, 2),
                                                           r(0, 1), r(0, 1), r(0, 1)))
        elif k == 1:
            line = 'box { min = <%s, %s, %s> max = <%s, %s, %s> } rotate <0, %s, 0> translate <%s, 0, %s>\n' % (
                r(-1, 0), r(-1, 0), r(-1, 0), r(0, 1), r(0, 1), r(0, 1), r(0, 360), r(-50, 50), r(-50, 50))
        elif k == 2:
            line = ('cylinder { from = <%s, 0, %s> to = <%s, %s, %s> radius = %s material = material '
                    '{ color = rgb(%s) reflect = 0.2 } }\n' % (r(-50, 50), r(-50, 50), r(-50, 50), r(1, 5),
                                                              r(-50, 50), r(0.1, 1), r(0, 1)))
        else:
            line = 'let p%d = <%s * 2, %s + 1, %s / 3>\n' % (i, r(-5, 5), r(-5, 5), r(-5, 5))
        f.write(line)
        n += len(line)
        i += 1


def vectors(f, size, rnd):
    f.write('let pts = [\n')
    n = 0
    while n < size:
        line = '  <%.3f, %.3f, %.3f>,\n' % (rnd.uniform(-100, 100), rnd.uniform(-100, 100), rnd.uniform(-100, 100))
        f.write(line)
        n += len(line)
    f.write(']\n')


def arith(f, size, rnd):
    f.write('let x = 1\n')
    n = i = 0
    while n < size:
        line = 'let v%d = %d + %d * x - (%d / 2)\n' % (i, i, i % 7, i % 13)
        f.write(line)
        n += len(line)
        i += 1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('out_dir')
    ap.add_argument('--mb', type=float, default=50.0)
    args = ap.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    size = int(args.mb * 1e6)
    for name, gen, seed in (('rich', rich, 7), ('vectors', vectors, 1), ('arith', arith, 0)):
        with open(os.path.join(args.out_dir, name + '.rts'), 'w') as f:
            gen(f, size, random.Random(seed))


if __name__ == '__main__':
    main()
