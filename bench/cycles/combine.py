"""Combines K renders of one scene (PFM) into their mean and the variance of that mean:

    python3 bench/cycles/combine.py OUT_PREFIX a.pfm b.pfm ...   ->  OUT_PREFIX.pfm, OUT_PREFIX_var.pfm

Each pixel's variance of the mean is the sample variance over the K renders divided by K.
"""
import struct
import sys

import numpy as np

from compare import read_pfm


def write_pfm(path, img):
    h, w, _ = img.shape
    with open(path, 'wb') as f:
        f.write(b'PF\n%d %d\n-1.0\n' % (w, h))
        f.write(np.ascontiguousarray(img[::-1], dtype='<f4').tobytes())  # bottom row first


def main():
    prefix, paths = sys.argv[1], sys.argv[2:]
    imgs = np.stack([read_pfm(p) for p in paths])
    write_pfm(prefix + '.pfm', imgs.mean(0))
    write_pfm(prefix + '_var.pfm', imgs.var(0, ddof=1) / len(paths))
    print('%s: %d renders, image mean %s' % (prefix, len(paths), imgs.mean((0, 1, 2))))


if __name__ == '__main__':
    main()
