#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Test oracle: scipy's Clough-Tocher interpolation of the points in a CSV file.

usage: scipy_clough_tocher.py POINTS.csv QUERIES.csv OUT_GRADIENTS.csv OUT_VALUES.csv
POINTS.csv: x,y,z per line (no header); QUERIES.csv: x,y per line.
Writes per point (in the order of the points) the vertex gradients of scipy's minimum-norm
network (converged tightly) and those of the same network with its border (convex hull) edges
weighted 1/2, dtm's estimate (solved directly on scipy's triangulation); and the
CloughTocher2DInterpolator and LinearNDInterpolator values at the queries (nan outside the hull).
"""
import sys

import numpy as np
import scipy.sparse
import scipy.sparse.linalg
from scipy.interpolate import CloughTocher2DInterpolator, LinearNDInterpolator


def border_weighted_network(xy, z, tri, border_weight=0.5):
    """Nielson's network, minimised exactly: sum over edges of w (4/L)(ma^2 + ma mb + mb^2)
    - w (12/L^2) h (ma + mb), ma = ga.d/L; w = border_weight on the hull, else 1."""
    s = tri.simplices
    e = np.sort(np.vstack([s[:, [0, 1]], s[:, [1, 2]], s[:, [2, 0]]]), 1)
    e = np.unique(e, axis=0)
    hull = np.sort(tri.convex_hull, 1)
    on_hull = {(int(a), int(b)) for a, b in hull}
    w = np.array([border_weight if (int(a), int(b)) in on_hull else 1.0 for a, b in e])
    a, b = e[:, 0], e[:, 1]
    d = xy[b] - xy[a]
    length = np.hypot(d[:, 0], d[:, 1])
    u = d / length[:, None]
    h = z[b] - z[a]
    rows, cols, vals = [], [], []
    rhs = np.zeros(2 * len(xy))
    for i, j, c in ((a, a, 8.0), (b, b, 8.0), (a, b, 4.0), (b, a, 4.0)):
        for k in range(2):
            for m in range(2):
                rows.append(2 * i + k)
                cols.append(2 * j + m)
                vals.append(w * c / length * u[:, k] * u[:, m])
    for k in range(2):
        np.add.at(rhs, 2 * a + k, w * 12.0 * h / length**2 * u[:, k])
        np.add.at(rhs, 2 * b + k, w * 12.0 * h / length**2 * u[:, k])
    m = scipy.sparse.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                                shape=(2 * len(xy), 2 * len(xy)))
    return scipy.sparse.linalg.spsolve(m.tocsc(), rhs).reshape(-1, 2)


points = np.loadtxt(sys.argv[1], delimiter=",", ndmin=2)
queries = np.loadtxt(sys.argv[2], delimiter=",", ndmin=2)
ct = CloughTocher2DInterpolator(points[:, :2], points[:, 2], tol=1e-13, maxiter=100000)
weighted = border_weighted_network(points[:, :2], points[:, 2], ct.tri)
np.savetxt(sys.argv[3], np.column_stack([ct.grad.reshape(-1, 2), weighted]), delimiter=",",
           fmt="%.17g")
lin = LinearNDInterpolator(ct.tri, points[:, 2])
np.savetxt(sys.argv[4], np.column_stack([ct(queries), lin(queries)]), delimiter=",", fmt="%.17g")
