#!/usr/bin/env python3
"""Prints the 8-bit R G B codes of pixel (X, Y) (0, 0 = top left) of a PNG file.

Usage: png_pixel.py FILE X Y
       png_pixel.py --check FILE X Y R G B [X Y R G B ...]   (R G B linear values in 0..1)
Reads 8-bit gray, RGB and RGBA images with any of PNG's row filters (what rts writes); no
dependency beyond the standard library, so the course tests can check closed-form pixels.
"""
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise SystemExit(f"{path}: not a PNG file")
    pos, idat = 8, b""
    while pos < len(data):
        length = int.from_bytes(data[pos:pos + 4], "big")
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width = int.from_bytes(body[0:4], "big")
            height = int.from_bytes(body[4:8], "big")
            depth, color_type, interlace = body[8], body[9], body[12]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    if depth != 8 or interlace != 0 or color_type not in (0, 2, 6):
        raise SystemExit(f"{path}: only 8-bit, non-interlaced gray/RGB/RGBA PNGs are read here")
    channels = {0: 1, 2: 3, 6: 4}[color_type]
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind = raw[start]
        row = bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = row[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                row[i] = (row[i] + pred) & 255
        rows.append(row)
        prev = row
    return width, height, channels, rows


def pixel(image, path, x, y):
    width, height, channels, rows = image
    if not (0 <= x < width and 0 <= y < height):
        raise SystemExit(f"{path}: pixel ({x}, {y}) outside {width}x{height}")
    px = rows[y][x * channels:(x + 1) * channels]
    return [px[0]] * 3 if channels == 1 else list(px[:3])


def main():
    if sys.argv[1] != "--check":
        path, x, y = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
        print(*pixel(read_png(path), path, x, y))
        return
    # --check FILE X Y R G B [X Y R G B ...]: each code within 1 of round(255 · value), the
    # values linear in 0..1 (clamped). Prints one line per pixel; exits 1 if any is off.
    path, args = sys.argv[2], sys.argv[3:]
    image, failed = read_png(path), False
    for i in range(0, len(args), 5):
        x, y = int(args[i]), int(args[i + 1])
        want = [min(255, max(0, round(255 * float(v)))) for v in args[i + 2:i + 5]]
        got = pixel(image, path, x, y)
        ok = all(abs(a - b) <= 1 for a, b in zip(got, want))
        failed |= not ok
        print(f"{'ok' if ok else 'FAIL'}: pixel ({x}, {y}) of {path}: {' '.join(map(str, got))}, expected "
              f"{' '.join(map(str, want))}")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
