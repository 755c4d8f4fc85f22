# Independent check of `dtm check`: heights by barycentric interpolation in numpy over the
# triangles of a 2DM mesh (brute force, every triangle), residuals and their statistics with
# numpy (std with ddof=1, numpy.percentile's default linear method), compared with dtm's
# residuals CSV and statistics JSON. Usage: check_stats_oracle.py MESH POINTS_CSV RESIDUALS STATS
import csv, json, sys
import numpy as np

mesh, points_csv, residuals_csv, stats_json = sys.argv[1:5]
nodes, faces = {}, []
for line in open(mesh):
    w = line.split()
    if w and w[0] == 'ND':
        nodes[int(w[1])] = (float(w[2]), float(w[3]), float(w[4]))
    elif w and w[0] == 'E3T':
        faces.append((int(w[2]), int(w[3]), int(w[4])))
tri = np.array([[nodes[i] for i in f] for f in faces])  # (n, 3, 3)
a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]

ids, pts = [], []
with open(points_csv) as f:
    for row in csv.DictReader(f):
        ids.append(row['id'])
        pts.append((float(row['x']), float(row['y']), float(row['z'])))

def height(x, y):
    # relative to corner a for precision at S-JTSK offsets
    bx, by = b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]
    cx, cy = c[:, 0] - a[:, 0], c[:, 1] - a[:, 1]
    px, py = x - a[:, 0], y - a[:, 1]
    d = bx * cy - by * cx
    l1 = (px * cy - py * cx) / d
    l2 = (bx * py - by * px) / d
    inside = (l1 >= -1e-12) & (l2 >= -1e-12) & (l1 + l2 <= 1 + 1e-12)
    k = np.flatnonzero(inside)
    if len(k) == 0:
        return None
    k = k[0]
    return a[k, 2] + l1[k] * (b[k, 2] - a[k, 2]) + l2[k] * (c[k, 2] - a[k, 2])

res, outside = [], []
for i, (x, y, z) in zip(ids, pts):
    h = height(x, y)
    if h is None:
        outside.append(i)
    else:
        res.append(z - h)
r = np.array(res)
stats = json.load(open(stats_json))
expect = {
    'mean': r.mean(), 'std_dev': r.std(ddof=1), 'rmse': np.sqrt((r ** 2).mean()),
    'mean_abs': np.abs(r).mean(), 'min': r.min(), 'max': r.max(), 'max_abs': np.abs(r).max(),
    'nssda_95': 1.96 * np.sqrt((r ** 2).mean()),
}
pct = {'p50': 50, 'p68.27': 68.27, 'p90': 90, 'p95': 95, 'p99': 99}
bad = 0
for k, v in expect.items():
    if abs(stats[k] - v) > 1e-9:
        print('MISMATCH', k, stats[k], v); bad += 1
for k, q in pct.items():
    v = np.percentile(np.abs(r), q)
    if abs(stats['abs_percentiles'][k] - v) > 1e-9:
        print('MISMATCH', k, stats['abs_percentiles'][k], v); bad += 1
if stats['inside'] != len(r) or sorted(stats['outside_ids']) != sorted(outside):
    print('MISMATCH counts', stats['inside'], len(r), stats['outside_ids'], outside); bad += 1
listed = [row['id'] for row in csv.DictReader(open(residuals_csv))]
if listed != ids:
    print('MISMATCH: residuals.csv does not list every point in order'); bad += 1
print('points', len(ids), 'inside', len(r), 'outside', outside, 'rmse', expect['rmse'], 'bad', bad)
sys.exit(1 if bad else 0)
