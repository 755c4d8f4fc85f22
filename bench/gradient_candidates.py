#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Vertex-gradient candidates for the cubic, measured against scipy's Clough-Tocher.

    bench/gradient_candidates.py [--seeds 1,2,3] [--alt] [--data ../shared/data]

Draws the DEM-sampling cases of bench/compare_accuracy.py (same sampling functions and order;
--alt: 3 000 whitebox points, 800 and 3 000 volcano points) and, on scipy's own Delaunay
triangulation, evaluates the Clough-Tocher element of dtm (normal derivative linear along each
edge, corner derivatives bounded by 3 x the corner's relief: libdtm/src/algo/clough_tocher.cpp)
with several vertex-gradient estimates. Prints, per candidate, the RMSE divided by that of
scipy's CloughTocher2DInterpolator on the same check cells: mean, worst, count above 1.
Prototype only (numpy, dense per-triangle work): the triangulation is scipy's, not dtm's, so
the cocircular ties of the volcano lattice are split as qhull splits them.
"""
import argparse
import math
import os
import sys

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl
from scipy.interpolate import CloughTocher2DInterpolator

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_accuracy as ca  # noqa: E402


def edges_of(tri):
    s = tri.simplices
    e = np.vstack([s[:, [0, 1]], s[:, [1, 2]], s[:, [2, 0]]])
    e.sort(1)
    return np.unique(e, axis=0)


def solve_blocks(n, pairs, rhs):
    """pairs: list of (rows, cols, values) of a 2n x 2n system."""
    m = sp.csr_matrix((np.concatenate([p[2] for p in pairs]),
                       (np.concatenate([p[0] for p in pairs]),
                        np.concatenate([p[1] for p in pairs]))), shape=(2 * n, 2 * n))
    return spl.spsolve(m.tocsc(), rhs).reshape(n, 2)


def network(pts, z, tri, border_weight=1.0):
    """Nielson's minimum-norm network (scipy's estimate when border_weight = 1)."""
    e = edges_of(tri)
    n = len(pts)
    a, b = e[:, 0], e[:, 1]
    d = pts[b] - pts[a]
    length = np.hypot(d[:, 0], d[:, 1])
    u = d / length[:, None]
    h = z[b] - z[a]
    hull = np.sort(tri.convex_hull, 1)
    key = lambda x: x[:, 0].astype(np.int64) * 10**9 + x[:, 1]  # noqa: E731
    w = np.where(np.isin(key(e), key(hull)), border_weight, 1.0)
    pairs, rhs = [], np.zeros(2 * n)
    for i, j, c in ((a, a, 8), (b, b, 8), (a, b, 4), (b, a, 4)):
        for k in range(2):
            for m in range(2):
                pairs.append((2 * i + k, 2 * j + m, w * c / length * u[:, k] * u[:, m]))
    for k in range(2):
        np.add.at(rhs, 2 * a + k, w * 12 * h / length**2 * u[:, k])
        np.add.at(rhs, 2 * b + k, w * 12 * h / length**2 * u[:, k])
    return solve_blocks(n, pairs, rhs)


def cross(ax, ay, bx, by):
    return ax * by - ay * bx


def ordinates(v, f, d):
    """Bezier ordinates of dtm's element; v (T,3,2), f (...,T,3), d (...,T,3,2)."""
    o = v[:, 0]
    b, c = v[:, 1] - o, v[:, 2] - o
    e = f[..., None] + d / 3.0
    inner = f + (d[..., 0] + d[..., 1]) / 9.0
    gx, gy = (b[:, 0] + c[:, 0]) / 3, (b[:, 1] + c[:, 1]) / 3
    px, py = [np.zeros(len(v)), b[:, 0], c[:, 0]], [np.zeros(len(v)), b[:, 1], c[:, 1]]
    mid = []
    for k in range(3):
        i, j = (k + 1) % 3, (k + 2) % 3
        ex, ey, wx, wy = px[j] - px[i], py[j] - py[i], gx - px[i], gy - py[i]
        nx, ny = -ey, ex
        dw = cross(ex, ey, wx, wy)
        bb, cc = cross(nx, ny, wx, wy) / dw, cross(ex, ey, nx, ny) / dw
        aa = -bb - cc
        eij, eji = e[..., i, 0], e[..., j, 1]
        c20 = aa * f[..., i] + bb * eij + cc * inner[..., i]
        c02 = aa * eji + bb * f[..., j] + cc * inner[..., j]
        mid.append((0.5 * (c20 + c02) - aa * eij - bb * eji) / cc)
    mid = np.stack(mid, -1)
    q = np.stack([(inner[..., i] + mid[..., (i + 1) % 3] + mid[..., (i + 2) % 3]) / 3
                  for i in range(3)], -1)
    return f, e, inner, mid, q, q.mean(-1)


def at_barycentric(o, l, k):
    f, e, inner, mid, q, s = o
    i, j = (k + 1) % 3, (k + 2) % 3
    u, v, w = l[i] - l[k], l[j] - l[k], 3 * l[k]
    uu, vv, ww = u * u, v * v, w * w
    return (u * uu * f[..., i] + v * vv * f[..., j] + w * ww * s
            + 3 * (uu * (v * e[..., i, 0] + w * inner[..., i])
                   + vv * (u * e[..., j, 1] + w * inner[..., j])
                   + ww * (u * q[..., i] + v * q[..., j])) + 6 * u * v * w * mid[..., k])


def ct_energy(pts, z, tri):
    """Gradients minimising the thin-plate energy of the piecewise Clough-Tocher surface."""
    s = tri.simplices
    v = pts[s]
    t = len(s)
    n = len(pts)
    bf, bd = np.zeros((9, t, 3)), np.zeros((9, t, 3, 2))
    for a in range(3):
        bf[a, :, a] = 1
        for k in range(2):
            bd[3 + 2 * a + k, :, a, k] = 1
    o = ordinates(v, bf, bd)
    org = v[:, 0]
    b, c = v[:, 1] - org, v[:, 2] - org
    det = cross(b[:, 0], b[:, 1], c[:, 0], c[:, 1])
    a1, a2 = np.column_stack([c[:, 1], -c[:, 0]]) / det[:, None], \
        np.column_stack([-b[:, 1], b[:, 0]]) / det[:, None]
    h = 1e-3 * np.sqrt(np.abs(det))
    energy = np.zeros((t, 9, 9))
    for k in range(3):  # the exact rule for quadratics on each sub-triangle
        for qp in ((2 / 3, 1 / 6, 1 / 6), (1 / 6, 2 / 3, 1 / 6), (1 / 6, 1 / 6, 2 / 3)):
            lam = np.full(3, qp[2] / 3)
            lam[(k + 1) % 3] += qp[0]
            lam[(k + 2) % 3] += qp[1]
            p = lam[1] * b + lam[2] * c

            def val(dx, dy):
                x, y = p[:, 0] + dx * h, p[:, 1] + dy * h
                l1, l2 = a1[:, 0] * x + a1[:, 1] * y, a2[:, 0] * x + a2[:, 1] * y
                return at_barycentric(o, (1 - l1 - l2, l1, l2), k)

            c0 = val(0, 0)
            parts = ((val(1, 0) - 2 * c0 + val(-1, 0)) / h**2, 1), \
                ((val(0, 1) - 2 * c0 + val(0, -1)) / h**2, 1), \
                ((val(1, 1) - val(1, -1) - val(-1, 1) + val(-1, -1)) / (4 * h**2), 2)
            for arr, cf in parts:
                r = arr.T
                energy += cf * (np.abs(det) / 18)[:, None, None] * r[:, :, None] * r[:, None, :]
    pm = np.zeros((t, 6, 6))
    for a in range(3):
        for k in range(2):
            ev = v[:, (a + 1 + k) % 3] - v[:, a]
            pm[:, 2 * a + k, 2 * a], pm[:, 2 * a + k, 2 * a + 1] = ev[:, 0], ev[:, 1]
    kdd = np.einsum('tdi,tde,tej->tij', pm, energy[:, 3:, 3:], pm)
    kdf = np.einsum('tdi,tde,te->ti', pm, energy[:, 3:, :3], z[s])
    gi = (2 * s[:, :, None] + np.arange(2)).reshape(t, 6)
    rhs = np.zeros(2 * n)
    np.add.at(rhs, gi.ravel(), -kdf.ravel())
    return solve_blocks(n, [(np.repeat(gi, 6, 1).ravel(), np.tile(gi, (1, 6)).ravel(),
                             kdd.ravel())], rhs)


def local_quadratic(pts, z, tri):
    """Weighted least-squares quadratic through each vertex over its 2-ring."""
    e = edges_of(tri)
    n = len(pts)
    adj = sp.coo_matrix((np.ones(len(e)), (e[:, 0], e[:, 1])), shape=(n, n))
    adj = (adj + adj.T).tocsr()
    ring = ((adj + sp.identity(n)) @ adj).tocsr()
    g = np.zeros((n, 2))
    for i in range(n):
        nb = ring.indices[ring.indptr[i]:ring.indptr[i + 1]]
        nb = nb[nb != i]
        dx, dz = pts[nb] - pts[i], z[nb] - z[i]
        r2 = (dx**2).sum(1)
        s = math.sqrt(np.median(r2))
        x, y = dx[:, 0] / s, dx[:, 1] / s
        m = np.column_stack([x, y, x * x, x * y, y * y])
        w = np.sqrt(s * s / r2)
        cf = np.linalg.lstsq(m * w[:, None], dz * w, rcond=None)[0]
        g[i] = cf[:2] / s
    return g


def evaluate(pts, z, tri, g, xs, ys):
    """dtm's element with gradients g on scipy's triangulation, at the cells xs, ys."""
    s = tri.simplices
    v = pts[s]
    edges = edges_of(tri)
    rise = np.abs(z[edges[:, 1]] - z[edges[:, 0]])
    relief = np.zeros(len(pts))
    np.maximum.at(relief, edges[:, 0], rise)
    np.maximum.at(relief, edges[:, 1], rise)
    d = np.zeros((len(s), 3, 2))
    for a in range(3):
        for k in range(2):
            j = (a + 1 + k) % 3
            limit = 3 * np.maximum(np.abs(z[s[:, j]] - z[s[:, a]]), relief[s[:, a]])
            d[:, a, k] = np.clip((g[s[:, a]] * (v[:, j] - v[:, a])).sum(1), -limit, limit)
    o = tuple(x[0] for x in ordinates(v, z[s][None], d[None]))
    xi = np.column_stack([xs.ravel(), ys.ravel()])
    simplex = tri.find_simplex(xi)
    out = np.full(len(xi), np.nan)
    ok = simplex >= 0
    t = simplex[ok]
    tr = tri.transform[t]
    l12 = np.einsum('nij,nj->ni', tr[:, :2], xi[ok] - tr[:, 2])
    lam = np.column_stack([l12, 1 - l12.sum(1)])
    low = np.argmin(lam, 1)
    res = np.zeros(len(t))
    for k in range(3):
        m = low == k
        res[m] = at_barycentric(tuple(x[t[m]] for x in o), (lam[m, 0], lam[m, 1], lam[m, 2]), k)
    out[ok] = res
    return out.reshape(xs.shape)


CANDIDATES = {
    "network (scipy's estimate)": lambda p, z, t, g: g,
    "network, border edges x 1/2": lambda p, z, t, g: network(p, z, t, 0.5),
    "network, border edges x 0.3": lambda p, z, t, g: network(p, z, t, 0.3),
    "0.9 network + 0.1 CT energy": lambda p, z, t, g: 0.9 * g + 0.1 * ct_energy(p, z, t),
    "CT energy": lambda p, z, t, g: ct_energy(p, z, t),
    "2-ring quadratic": lambda p, z, t, g: local_quadratic(p, z, t),
}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seeds", default="1,2,3,4,5")
    ap.add_argument("--alt", action="store_true")
    ap.add_argument("--data", default=os.path.join(ca.HERE, "..", "..", "shared", "data"))
    args = ap.parse_args()
    ratios = {k: [] for k in CANDIDATES}
    for seed in (int(s) for s in args.seeds.split(",")):
        rng = np.random.default_rng(seed)
        dems = ((ca.whitebox(args), (3000,) if args.alt else (2000, 7025, 15000)),
                (ca.volcano(args), (800, 3000) if args.alt else (500, 1500)))
        for (grid, truth), counts in dems:
            for count in counts:
                valid = np.argwhere(np.isfinite(truth))
                pick = valid[rng.choice(len(valid), size=count, replace=False)]
                xs, ys = grid.centres()
                pts = np.column_stack([xs[pick[:, 0], pick[:, 1]], ys[pick[:, 0], pick[:, 1]]])
                z = truth[pick[:, 0], pick[:, 1]]
                check = np.isfinite(truth)
                check[pick[:, 0], pick[:, 1]] = False
                ip = CloughTocher2DInterpolator(pts, z)
                base = ip(xs, ys)
                m = check & np.isfinite(base)
                r0 = math.sqrt(np.mean((base[m] - truth[m])**2))
                for name, fn in CANDIDATES.items():
                    v = evaluate(pts, z, ip.tri, fn(pts, z, ip.tri, ip.grad[:, 0, :]), xs, ys)
                    ratios[name].append(math.sqrt(np.mean((v[m] - truth[m])**2)) / r0)
    print("| gradients (dtm's element, scipy's TIN) | mean | worst | above scipy |")
    print("|---|---|---|---|")
    for name, r in ratios.items():
        r = np.array(r)
        print(f"| {name} | {r.mean():.4f} | {r.max():.4f} | {(r > 1).sum()} of {len(r)} |")


if __name__ == "__main__":
    main()
