#!/usr/bin/env python3
"""png_rmse.py IMAGE.png REFERENCE.png: RMSE over pixels and channels of two linear 16-bit
RGB PNGs (as POV-Ray writes with +FN16 File_Gamma=1.0). Standard library only."""
import struct, sys, zlib

def read_png16(path):
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', path + ': not a PNG'
    pos, idat, w = 8, b'', 0
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            w, h, depth, ctype = struct.unpack('>IIBB', body[:10])
            assert depth == 16 and ctype in (2, 6), path + ': need 16-bit RGB(A)'
            chans = 3 if ctype == 2 else 4
        elif kind == b'IDAT':
            idat += body
        pos += 12 + n
    raw, bpp, stride = zlib.decompress(idat), 2 * chans, 2 * chans * w
    prev, out, i = bytearray(stride), [], 0
    for _ in range(h):
        f, line = raw[i], bytearray(raw[i + 1:i + 1 + stride]); i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b, c = prev[x], prev[x - bpp] if x >= bpp else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        for x in range(w):
            for ch in range(3):
                k = x * bpp + 2 * ch
                out.append((line[k] << 8 | line[k + 1]) / 65535.0)
        prev = line
    return w, h, out

w1, h1, a = read_png16(sys.argv[1])
w2, h2, b = read_png16(sys.argv[2])
assert (w1, h1) == (w2, h2), 'sizes differ'
print((sum((x - y) ** 2 for x, y in zip(a, b)) / len(a)) ** 0.5)
