#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Test oracle: scipy's Clough-Tocher interpolation of the points in a CSV file.

usage: scipy_clough_tocher.py POINTS.csv QUERIES.csv OUT_GRADIENTS.csv OUT_VALUES.csv
POINTS.csv: x,y,z per line (no header); QUERIES.csv: x,y per line.
Writes the estimated vertex gradients (scipy's minimum-norm network, converged tightly) in the
order of the points, and the CloughTocher2DInterpolator and LinearNDInterpolator values at the
queries (nan outside the hull).
"""
import sys

import numpy as np
from scipy.interpolate import CloughTocher2DInterpolator, LinearNDInterpolator

points = np.loadtxt(sys.argv[1], delimiter=",", ndmin=2)
queries = np.loadtxt(sys.argv[2], delimiter=",", ndmin=2)
ct = CloughTocher2DInterpolator(points[:, :2], points[:, 2], tol=1e-13, maxiter=100000)
np.savetxt(sys.argv[3], ct.grad.reshape(-1, 2), delimiter=",", fmt="%.17g")
lin = LinearNDInterpolator(ct.tri, points[:, 2])
np.savetxt(sys.argv[4], np.column_stack([ct(queries), lin(queries)]), delimiter=",", fmt="%.17g")
