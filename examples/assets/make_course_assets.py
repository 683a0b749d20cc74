#!/usr/bin/env python3
"""Regenerates the assets of examples/course_surfaces.rts (Python's standard library and
Debian's libstb through ctypes for the JPEG encoder):

- sky.png: 256x128 latitude-longitude sky: a blue gradient above the horizon with a sun at
  azimuth +z+x, elevation 30 degrees, and a brown-green ground below.
- bricks.jpg: 64x64 brick pattern (JPEG).
- bricks_height.png: its height map (mortar low, bricks high), linear.
"""
import ctypes, math, os, struct, zlib

here = os.path.dirname(os.path.abspath(__file__))


def png(path, w, h, pixels):
    raw = b"".join(b"\0" + bytes(c for p in pixels[y * w:(y + 1) * w] for c in p) for y in range(h))
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def clamp(x):
    return max(0, min(255, round(x)))


def sky(w=256, h=128):
    sun = (math.cos(math.radians(30)) * math.sin(math.radians(35)), math.sin(math.radians(30)),
           math.cos(math.radians(30)) * math.cos(math.radians(35)))
    px = []
    for y in range(h):
        lat = math.pi * (0.5 - (y + 0.5) / h)
        for x in range(w):
            lon = 2 * math.pi * ((x + 0.5) / w - 0.5)
            d = (math.cos(lat) * math.sin(lon), math.sin(lat), math.cos(lat) * math.cos(lon))
            if lat >= 0:
                t = lat / (math.pi / 2)
                c = [90 + 100 * (1 - t), 140 + 80 * (1 - t), 230]
                glow = max(0.0, sum(a * b for a, b in zip(d, sun))) ** 200
                c = [ci + 255 * glow * 2 for ci in c]
            else:
                t = min(1.0, -lat / 0.3)
                c = [110 - 40 * t, 100 - 20 * t, 70 - 20 * t]
            px.append(tuple(clamp(ci) for ci in c))
    return px


def bricks(n=64):
    color, height = [], []
    for y in range(n):
        row = y // 16
        for x in range(n):
            xo = (x + (8 if row % 2 else 0)) % 32
            mortar = y % 16 < 2 or xo < 2
            v = 0 if mortar else 255
            height.append((v, v, v))
            shade = ((x * 7 + y * 13) % 17) * 2
            color.append((200, 200, 190) if mortar else (160 + shade, 60 + shade // 2, 40))
    return color, height


if __name__ == "__main__":
    png(os.path.join(here, "sky.png"), 256, 128, sky())
    color, height = bricks()
    png(os.path.join(here, "bricks_height.png"), 64, 64, height)
    data = bytes(c for p in color for c in p)
    buf = ctypes.create_string_buffer(data, len(data))
    assert ctypes.CDLL("libstb.so").stbi_write_jpg(os.path.join(here, "bricks.jpg").encode(), 64, 64, 3, buf, 95)
