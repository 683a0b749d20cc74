#!/usr/bin/env python3
"""Writes one height field (2*N*N triangles over x, z in [-10, 10], smooth vertex normals) as an
OBJ file for rts and as a POV-Ray mesh2 include declaring `Terrain`, for bench/race.sh.

    gen_terrain.py N OUT_PREFIX     # OUT_PREFIX.obj and OUT_PREFIX.inc

Large outputs (N = 1000 is 2M triangles, ~150 MB) belong in build/ or /tmp, not the repository.
"""
import math
import sys


def height(x: float, z: float) -> float:
    return 1.6 * math.sin(0.35 * x) * math.cos(0.45 * z) + 0.35 * math.sin(1.3 * x + 0.8 * z) \
        + 0.12 * math.cos(3.1 * x - 2.3 * z)


def normal(x: float, z: float):
    e = 1e-4
    dx = (height(x + e, z) - height(x - e, z)) / (2 * e)
    dz = (height(x, z + e) - height(x, z - e)) / (2 * e)
    n = (-dx, 1.0, -dz)
    length = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
    return n[0] / length, n[1] / length, n[2] / length


def main() -> None:
    n = int(sys.argv[1])
    prefix = sys.argv[2]
    verts, norms = [], []
    for i in range(n + 1):
        z = -10 + 20 * i / n
        for j in range(n + 1):
            x = -10 + 20 * j / n
            verts.append(f"{x:.5f} {height(x, z):.5f} {z:.5f}")
            norms.append("%.5f %.5f %.5f" % normal(x, z))
    faces = []
    for i in range(n):
        for j in range(n):
            a = i * (n + 1) + j
            b, c = a + 1, a + n + 1
            faces.append((a, c, b))
            faces.append((b, c, c + 1))
    with open(f"{prefix}.obj", "w") as f:
        f.write("# height field for bench/race.sh\n")
        f.write("".join(f"v {v}\n" for v in verts))
        f.write("".join(f"vn {v}\n" for v in norms))
        f.write("".join(f"f {a+1}//{a+1} {b+1}//{b+1} {c+1}//{c+1}\n" for a, b, c in faces))
    with open(f"{prefix}.inc", "w") as f:
        f.write("#declare Terrain = mesh2 {\n")
        f.write(f"  vertex_vectors {{ {len(verts)},\n")
        f.write(",\n".join(f"<{v.replace(' ', ',')}>" for v in verts))
        f.write("\n  }\n")
        f.write(f"  normal_vectors {{ {len(norms)},\n")
        f.write(",\n".join(f"<{v.replace(' ', ',')}>" for v in norms))
        f.write("\n  }\n")
        f.write(f"  face_indices {{ {len(faces)},\n")
        f.write(",\n".join(f"<{a},{b},{c}>" for a, b, c in faces))
        f.write("\n  }\n}\n")


if __name__ == "__main__":
    main()
