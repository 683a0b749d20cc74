#!/usr/bin/env python3
"""Writes the meshes of bench/csg/mesh.rts: assets/icosphere.obj (a once-subdivided icosahedron,
80 faces) and assets/torus_lowpoly.obj (16 x 8 quads), both closed and wound outwards, and
assets/meshes.inc with the same triangles for the POV-Ray twin, mesh.pov."""
import math
import os

here = os.path.dirname(os.path.abspath(__file__))


def icosphere(sub):
    t = (1 + 5 ** 0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    v = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in v]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
         (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
         (8, 6, 7), (9, 8, 1)]
    for _ in range(sub):
        cache, nf = {}, []

        def mid(a, b):
            k = (min(a, b), max(a, b))
            if k not in cache:
                p = [(v[a][i] + v[b][i]) / 2 for i in range(3)]
                n = math.sqrt(sum(x * x for x in p))
                v.append(tuple(x / n for x in p))
                cache[k] = len(v) - 1
            return cache[k]

        for a, b, c in f:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    return v, f


def torus(major, minor, nu, nv):
    v, f = [], []
    for i in range(nu):
        u = 2 * math.pi * i / nu
        for j in range(nv):
            w = 2 * math.pi * j / nv
            r = major + minor * math.cos(w)
            v.append((r * math.cos(u), minor * math.sin(w), r * math.sin(u)))
    for i in range(nu):
        for j in range(nv):
            a, b = i * nv + j, ((i + 1) % nu) * nv + j
            c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
            f += [(a, d, c), (a, c, b)]
    return v, f


def signed_volume(v, f):
    s = 0.0
    for a, b, c in f:
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = v[a], v[b], v[c]
        s += (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6
    return s


inc = ['// Written by assets/make_meshes.py with assets/*.obj (the same triangles): mesh.pov\'s meshes.']
for name, decl, (v, f) in [('icosphere', 'Ico', icosphere(1)), ('torus_lowpoly', 'TorusMesh', torus(0.8, 0.3, 16, 8))]:
    if signed_volume(v, f) < 0:
        f = [(a, c, b) for a, b, c in f]  # outwards
    v = [tuple(float('%.6f' % x) for x in p) for p in v]  # what both files hold
    with open(os.path.join(here, name + '.obj'), 'w') as o:
        o.write('# %s: written by make_meshes.py for bench/csg/mesh.rts (closed, wound outwards)\n' % name)
        for p in v:
            o.write('v %.6f %.6f %.6f\n' % p)
        for a, b, c in f:
            o.write('f %d %d %d\n' % (a + 1, b + 1, c + 1))
    inc.append('#declare %s = mesh {' % decl)
    for tri in f:
        inc.append('  triangle { ' + ', '.join('<%.6f, %.6f, %.6f>' % v[k] for k in tri) + ' }')
    inc.append('  inside_vector <0.13, 0.71, 0.29>\n}')
with open(os.path.join(here, 'meshes.inc'), 'w') as o:
    o.write('\n'.join(inc) + '\n')
