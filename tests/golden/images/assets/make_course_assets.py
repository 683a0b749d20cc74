#!/usr/bin/env python3
"""Regenerates the course-feature test assets (Python's standard library and Debian's libstb
through ctypes, for the BMP and JPEG encoders):

- tile4.png / tile4.bmp / tile4.jpg: 16x16, four 8x8 quadrants: top-left red, top-right green,
  bottom-left blue, bottom-right white (the same picture in three formats).
- cube/pos{x,y,z}.png, neg{x,y,z}.png: 16x16 cube-map faces in solid colors (+x red, -x cyan,
  +y green, -y magenta, +z blue, -z yellow), each with a white 4x4 marker in its top-left corner.
- cube_mit/{right,left,up,down,front,back}.bmp: the same faces under MIT 6.837's names, as BMP.
- bands.png: 64x32 latitude-longitude map: four longitude bands (u in quarters: red, green,
  blue, yellow), the top 8 rows white and the bottom 8 rows dark grey.
- tilt.png: 32x32 linear normal map: left half tilted towards -u, right half towards +u.
- bumps.png: 32x32 height map, 0.5 + 0.5 sin(2 pi x / 16) sin(2 pi y / 16): a grid of bumps.
"""
import ctypes, math, os, struct, zlib

here = os.path.dirname(os.path.abspath(__file__))
stb = ctypes.CDLL("libstb.so")


def png(path, w, h, pixels):
    raw = b"".join(b"\0" + bytes(c for p in pixels[y * w:(y + 1) * w] for c in p) for y in range(h))
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def stb_write(kind, path, w, h, pixels):
    data = bytes(c for p in pixels for c in p)
    buf = ctypes.create_string_buffer(data, len(data))
    if kind == "bmp":
        ok = stb.stbi_write_bmp(path.encode(), w, h, 3, buf)
    else:
        ok = stb.stbi_write_jpg(path.encode(), w, h, 3, buf, 100)
    assert ok, path


def tile4():
    px = []
    for y in range(16):
        for x in range(16):
            px.append([(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255)][(y >= 8) * 2 + (x >= 8)])
    return px


def face(color):
    return [(255, 255, 255) if x < 4 and y < 4 else color for y in range(16) for x in range(16)]


FACES = [(255, 0, 0), (0, 255, 255), (0, 255, 0), (255, 0, 255), (0, 0, 255), (255, 255, 0)]

if __name__ == "__main__":
    png(os.path.join(here, "tile4.png"), 16, 16, tile4())
    stb_write("bmp", os.path.join(here, "tile4.bmp"), 16, 16, tile4())
    stb_write("jpg", os.path.join(here, "tile4.jpg"), 16, 16, tile4())
    os.makedirs(os.path.join(here, "cube"), exist_ok=True)
    os.makedirs(os.path.join(here, "cube_mit"), exist_ok=True)
    for name, mit, color in zip(["posx", "negx", "posy", "negy", "posz", "negz"],
                                ["right", "left", "up", "down", "front", "back"], FACES):
        png(os.path.join(here, "cube", name + ".png"), 16, 16, face(color))
        stb_write("bmp", os.path.join(here, "cube_mit", mit + ".bmp"), 16, 16, face(color))
    bands = []
    for y in range(32):
        for x in range(64):
            if y < 8:
                bands.append((255, 255, 255))
            elif y >= 24:
                bands.append((40, 40, 40))
            else:
                bands.append([(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 0)][x // 16])
    png(os.path.join(here, "bands.png"), 64, 32, bands)
    s = 0.5 ** 0.5
    tilt = []
    for y in range(32):
        for x in range(32):
            nx = -s if x < 16 else s
            tilt.append((round((nx + 1) / 2 * 255), 128, round((s + 1) / 2 * 255)))
    png(os.path.join(here, "tilt.png"), 32, 32, tilt)
    bumps = []
    for y in range(32):
        for x in range(32):
            v = round(255 * (0.5 + 0.5 * math.sin(2 * math.pi * x / 16) * math.sin(2 * math.pi * y / 16)))
            bumps.append((v, v, v))
    png(os.path.join(here, "bumps.png"), 32, 32, bumps)
