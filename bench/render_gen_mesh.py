#!/usr/bin/env python3
"""Writes the same triangle mesh (a bumpy sphere with smooth normals) as an OBJ file for rts
and as a POV-Ray mesh2 include, for bench/render.sh's mesh race.

    render_gen_mesh.py N OUT_DIR     # 2*N*N triangles: OUT_DIR/bench_mesh.obj, OUT_DIR/bench_mesh.inc
"""
import math
import sys


def main() -> None:
    n = int(sys.argv[1])
    out = sys.argv[2]
    verts, norms = [], []
    for i in range(n + 1):
        th = math.pi * i / n
        for j in range(n + 1):
            ph = 2 * math.pi * j / n
            r = 1 + 0.05 * math.sin(12 * th) * math.sin(12 * ph)
            d = (math.sin(th) * math.cos(ph), math.cos(th), math.sin(th) * math.sin(ph))
            verts.append((r * d[0], r * d[1], r * d[2]))
            norms.append(d)
    faces = []
    for i in range(n):
        for j in range(n):
            a = i * (n + 1) + j
            b, c = a + 1, a + n + 1
            faces += [(a, c, b), (b, c, c + 1)]
    with open(f"{out}/bench_mesh.obj", "w") as f:
        f.writelines(f"v {x:.6f} {y:.6f} {z:.6f}\n" for x, y, z in verts)
        f.writelines(f"vn {x:.6f} {y:.6f} {z:.6f}\n" for x, y, z in norms)
        f.writelines(f"f {a+1}//{a+1} {b+1}//{b+1} {c+1}//{c+1}\n" for a, b, c in faces)
    with open(f"{out}/bench_mesh.inc", "w") as f:
        f.write("#declare BenchMesh = mesh2 {\n")
        f.write(f"  vertex_vectors {{ {len(verts)},\n")
        f.write(",\n".join(f"<{x:.6f},{y:.6f},{z:.6f}>" for x, y, z in verts))
        f.write("\n  }\n")
        f.write(f"  normal_vectors {{ {len(norms)},\n")
        f.write(",\n".join(f"<{x:.6f},{y:.6f},{z:.6f}>" for x, y, z in norms))
        f.write("\n  }\n")
        f.write(f"  face_indices {{ {len(faces)},\n")
        f.write(",\n".join(f"<{a},{b},{c}>" for a, b, c in faces))
        f.write("\n  }\n}\n")


if __name__ == "__main__":
    main()
