#!/usr/bin/env python3
"""Which child is seen, rts against POV-Ray: classifies each pixel of two renders of flat
colours (every child emits one of a small palette, the background is black) by the nearest
palette colour and prints the fraction of pixels where both images agree.

    agreement.py rts.pfm pov.ppm     (PFM: rts's float output; PPM: POV-Ray's +FP)
    agreement.py --lit rts.pfm pov.ppm
        the diffuse-lit pass (both linear): over the pixels where both show the same child,
        the mean brightness of each and the mean absolute difference per pixel, which a
        normal pointing the wrong way would make large
"""
import struct
import sys

PALETTE = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (0, 1, 1), (1, 0, 1), (1, 1, 1)]


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = f.read()
    endian = "<" if scale < 0 else ">"
    n = 3 if kind == b"PF" else 1
    vals = struct.unpack(endian + "f" * (w * h * n), data[: 4 * w * h * n])
    rows = [vals[y * w * n:(y + 1) * w * n] for y in range(h)]
    rows.reverse()  # PFM stores the bottom row first
    return w, h, [tuple(r[x * n:(x + 1) * n]) for r in rows for x in range(w)]


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos)
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    pos += 1
    w, h, maxval = int(fields[1]), int(fields[2]), int(fields[3])
    size = 2 if maxval > 255 else 1
    px = []
    for i in range(w * h):
        c = []
        for k in range(3):
            o = pos + (i * 3 + k) * size
            v = int.from_bytes(data[o:o + size], "big")
            c.append(v / maxval)
        px.append(tuple(c))
    return w, h, px


def label(c):
    return min(range(len(PALETTE)), key=lambda i: sum((a - b) ** 2 for a, b in zip(c, PALETTE[i])))


def lit_label(c):
    # Lit children are shades of one palette colour: classify by the colour's direction.
    m = max(c)
    return 0 if m < 0.02 else label(tuple(x / m for x in c))


def main():
    lit = sys.argv[1] == "--lit"
    args = sys.argv[2:] if lit else sys.argv[1:]
    w1, h1, a = read_pfm(args[0])
    w2, h2, b = read_ppm(args[1])
    if (w1, h1) != (w2, h2):
        sys.exit(f"sizes differ: {w1}x{h1} vs {w2}x{h2}")
    if lit:
        pairs = [(max(p), max(q)) for p, q in zip(a, b) if lit_label(p) == lit_label(q) != 0]
        n = max(len(pairs), 1)
        mean_a, mean_b = sum(p for p, _ in pairs) / n, sum(q for _, q in pairs) / n
        mad = sum(abs(p - q) for p, q in pairs) / n
        print(f"{mean_a:.4f} {mean_b:.4f} {mad:.4f} {len(pairs)}")
        return
    agree = sum(label(p) == label(q) for p, q in zip(a, b))
    print(f"{agree / len(a):.5f} {len(a) - agree}")


main()
