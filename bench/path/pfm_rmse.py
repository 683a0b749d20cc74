#!/usr/bin/env python3
"""pfm_rmse.py IMAGE.pfm REF1.pfm [REF2.pfm ...]: RMSE (linear, over pixels and channels) of a
render against the mean of independent reference renders, their own noise taken out
(E|img - ref|^2 = MSE_true + var(ref), var(ref) from the references' spread / their number).
Standard library only (bench/cycles/rmse.py does the same with numpy)."""
import array, math, sys

def read_pfm(path):
    with open(path, 'rb') as f:
        kind = f.readline().strip()
        assert kind in (b'PF', b'Pf'), path + ': not a PFM'
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = array.array('f')
        data.frombytes(f.read())
    if (scale < 0) != (sys.byteorder == 'little'):
        data.byteswap()
    assert len(data) == w * h * (3 if kind == b'PF' else 1), path + ': truncated'
    return data

img = read_pfm(sys.argv[1])
refs = [read_pfm(p) for p in sys.argv[2:]]
n = len(refs)
se = 0.0
for i in range(len(img)):
    vals = [r[i] for r in refs]
    mean = sum(vals) / n
    var = sum((v - mean) ** 2 for v in vals) / (n - 1) / n if n > 1 else 0.0
    se += (img[i] - mean) ** 2 - var
print('%.5f' % math.sqrt(max(se / len(img), 0.0)))
