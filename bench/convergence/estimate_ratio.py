"""Error estimate against the true error: for each render (a .pfm with its --stats-json), the
estimated RMSE it printed over the RMSE measured against a reference made of independent
renders (the reference's own noise taken out, as bench/cycles/rmse.py).

    python3 bench/convergence/estimate_ratio.py --ref REF1.pfm REF2.pfm ... --runs A.pfm B.pfm ...

Each run's JSON is its .pfm with .json. Prints one line per run and, per group of runs sharing
the name up to the last '.', the ratio of the root-mean estimated MSE to the root-mean measured
MSE (the figure that should be 1) and the spread of the single-run ratios.
"""
import argparse
import collections
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', 'cycles'))
from compare import read_pfm  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument('--ref', nargs='+', required=True)
ap.add_argument('--runs', nargs='+', required=True)
a = ap.parse_args()
refs = np.stack([read_pfm(p) for p in a.ref])
ref = refs.mean(axis=0)
ref_var = (refs.var(axis=0, ddof=1) / len(refs)).mean() if len(refs) > 1 else 0.0
groups = collections.defaultdict(list)
for run in a.runs:
    img = read_pfm(run)
    err = json.load(open(run[:-4] + '.json'))['error']
    mse = max(((img - ref) ** 2).mean() - ref_var, 0.0)
    est = err['rmse']
    spp = json.load(open(run[:-4] + '.json')).get('sampling', {}).get('mean_spp', 0)
    print('%s: measured %.5f estimated %.5f ratio %.3f  mean spp %s' % (run, np.sqrt(mse), est, est / np.sqrt(mse), spp))
    groups[run.rsplit('.', 2)[0]].append((mse, est * est))
for g, v in groups.items():
    m = np.array(v)
    r = np.sqrt(m[:, 1] / m[:, 0])
    print('%s: %d runs, sqrt(mean est MSE / mean measured MSE) %.3f; single runs %.3f..%.3f'
          % (g, len(v), np.sqrt(m[:, 1].mean() / m[:, 0].mean()), r.min(), r.max()))
