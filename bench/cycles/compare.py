"""Compares rts's and Cycles' renders of one scene block by block, with a z-test.

    python3 bench/cycles/compare.py --a rts_s0.pfm rts_s1.pfm ... --b cy_s0.pfm cy_s1.pfm ...
        [--block 8] [--png side_by_side.png]

Each engine renders the scene K times with independent seeds. Per pixel the K images give a
mean and a sample variance; a block's mean is the mean of its pixels, and its variance the sum
of its pixels' variances / K / n^2 (pixels are independent; each pixel's K renders are). For
each block and channel z = (mean_a - mean_b) / sqrt(var_a + var_b). If both engines compute
the same image, z is close to standard normal: |z| > 4 in about 6e-5 of blocks, and the
fraction beyond 2 is near 4.6%. The relative difference of the block means and of the whole
image's mean are printed too (what "within a few percent" means).
"""
import argparse
import struct
import sys
import zlib

import numpy as np


def read_pfm(path):
    with open(path, 'rb') as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype='<f4' if scale < 0 else '>f4')
    ch = 3 if kind == b'PF' else 1
    img = data.reshape(h, w, ch)[::-1]  # PFM stores the bottom row first
    return img.astype(np.float64)


def write_png(path, img):
    """img: linear RGB floats, h x w x 3; written with the sRGB curve, 8 bits."""
    x = np.clip(img, 0, 1)
    x = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)
    x = (x * 255 + 0.5).astype(np.uint8)
    h, w, _ = x.shape
    raw = b''.join(b'\x00' + x[j].tobytes() for j in range(h))

    def chunk(t, d):
        c = struct.pack('>I', len(d)) + t + d
        return c + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0))
                + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))


def stats(paths):
    imgs = np.stack([read_pfm(p) for p in paths])
    return imgs.mean(axis=0), imgs.var(axis=0, ddof=1), len(paths)


def blocks(x, b):
    h, w, c = x.shape
    return x[:h - h % b, :w - w % b].reshape(h // b, b, w // b, b, c).sum(axis=(1, 3))


def compare(a_paths, b_paths, block):
    ma, va, ka = stats(a_paths)
    mb, vb, kb = stats(b_paths)
    n = block * block
    bma, bmb = blocks(ma, block) / n, blocks(mb, block) / n
    bva, bvb = blocks(va, block) / ka / n ** 2, blocks(vb, block) / kb / n ** 2
    z = (bma - bmb) / np.sqrt(np.maximum(bva + bvb, 1e-30))
    lit = (bma + bmb) / 2 > 0.02 * max(ma.mean(), 1e-9)  # relative differences where there is light
    rel = np.abs(bma - bmb)[lit] / ((bma + bmb) / 2)[lit]
    return dict(ma=ma, mb=mb, z=z, rel=rel,
                mean_a=ma.mean(axis=(0, 1)), mean_b=mb.mean(axis=(0, 1)),
                se_a=np.sqrt(va.sum(axis=(0, 1)) / ka) / (ma.shape[0] * ma.shape[1]),
                se_b=np.sqrt(vb.sum(axis=(0, 1)) / kb) / (mb.shape[0] * mb.shape[1]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--a', nargs='+', required=True, help='rts renders (independent seeds)')
    ap.add_argument('--b', nargs='+', required=True, help='Cycles renders (independent seeds)')
    ap.add_argument('--block', type=int, default=8)
    ap.add_argument('--png', help='write rts | Cycles | 4x difference side by side')
    ap.add_argument('--name', default='')
    a = ap.parse_args()
    r = compare(a.a, a.b, a.block)
    z = r['z'].ravel()
    ratio = r['mean_a'] / r['mean_b']
    ratio_se = ratio * np.sqrt((r['se_a'] / r['mean_a']) ** 2 + (r['se_b'] / r['mean_b']) ** 2)
    print('%s: blocks %d x %d px, %d values; |z| max %.2f, mean z %+.2f, fraction |z|>2 %.3f (4.6%% expected), '
          '|z|>4 %d; block |rel. diff| median %.3f, 95th pct %.3f; image mean rts/Cycles %s +- %s'
          % (a.name, a.block, a.block, z.size, np.abs(z).max(), z.mean(), (np.abs(z) > 2).mean(),
             (np.abs(z) > 4).sum(), np.median(r['rel']), np.percentile(r['rel'], 95),
             ' '.join('%.4f' % x for x in ratio), ' '.join('%.4f' % x for x in ratio_se)))
    if a.png:
        diff = np.abs(r['ma'] - r['mb']) * 4
        sep = np.ones((r['ma'].shape[0], 2, 3))
        write_png(a.png, np.concatenate([r['ma'], sep, r['mb'], sep, diff], axis=1))
    return 0


if __name__ == '__main__':
    sys.exit(main())
