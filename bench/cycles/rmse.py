"""RMSE of one render against a reference made of many independent renders' mean.

    python3 bench/cycles/rmse.py IMAGE.pfm REF1.pfm REF2.pfm ...

The reference's own noise is taken out: E|img - ref|^2 = MSE_true + var(ref), and var(ref) is
estimated per pixel from the spread of the reference renders / their number. Prints the RMSE
over all pixels and channels, linear values.
"""
import sys

import numpy as np

from compare import read_pfm

img = read_pfm(sys.argv[1])
refs = np.stack([read_pfm(p) for p in sys.argv[2:]])
ref = refs.mean(axis=0)
ref_var = refs.var(axis=0, ddof=1) / len(refs)
mse = ((img - ref) ** 2).mean() - ref_var.mean()
print('%.5f' % np.sqrt(max(mse, 0.0)))
