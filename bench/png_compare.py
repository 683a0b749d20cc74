#!/usr/bin/env python3
"""Mean absolute difference of two 8-bit PNGs, in codes of 255, over all pixels and channels,
and over the means of BLOCK x BLOCK pixel blocks (for scenes whose noise patterns differ in
detail but not on average). Pure Python (zlib), so the benchmark needs no imaging package.

    png_compare.py A.png B.png [BLOCK]   ->   "MAD BLOCK_MAD"   (or "size A != size B")
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or interlace != 0 or ctype not in (0, 2, 4, 6):
                raise ValueError(f"{path}: only 8-bit non-interlaced grey/RGB(A) PNGs are read")
            channels = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev, at = [], bytearray(stride), 0
    for _ in range(height):
        ftype, line = raw[at], bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if ftype == 1:
                line[i] = (line[i] + a) & 255
            elif ftype == 2:
                line[i] = (line[i] + b) & 255
            elif ftype == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    rgb = []
    for line in rows:
        for x in range(width):
            px = line[x * channels:(x + 1) * channels]
            rgb.append((px[0], px[0], px[0]) if channels < 3 else (px[0], px[1], px[2]))
    return width, height, rgb


def main():
    a_w, a_h, a = read_png(sys.argv[1])
    b_w, b_h, b = read_png(sys.argv[2])
    block = int(sys.argv[3]) if len(sys.argv) > 3 else 40
    if (a_w, a_h) != (b_w, b_h):
        print(f"size {a_w}x{a_h} != {b_w}x{b_h}")
        return 1
    mad = sum(abs(p[c] - q[c]) for p, q in zip(a, b) for c in range(3)) / (3 * len(a))
    sums = {}
    for i, (p, q) in enumerate(zip(a, b)):
        key = ((i % a_w) // block, (i // a_w) // block)
        s = sums.setdefault(key, [0, 0, 0, 0, 0, 0, 0])
        for c in range(3):
            s[c] += p[c]
            s[3 + c] += q[c]
        s[6] += 1
    block_mad = sum(abs(s[c] - s[3 + c]) / s[6] for s in sums.values() for c in range(3)) / (3 * len(sums))
    print(f"{mad:.3f} {block_mad:.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
