#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Accuracy of dtm's surfaces against the truth, next to scipy and gdal_grid, in one run.

    bench/compare_accuracy.py [--dtm build/tools/dtm] [--sample build/tools/dtm-sample/dtm-sample]
                              [--data ../shared/data] [--work DIR] [--seed 1] [--quick]

Cases (each prints RMSE, MAE and max error against the truth on the same check cells):
  * DEM sampling: points sampled at random cell centres of a real DEM (dem-whiteboxR 90 m,
    the Maunga Whau volcano grid 10 m), the DEM rebuilt on the same cells, compared at every
    cell that was not sampled and lies inside every method's footprint. dtm grid
    --interpolation linear|cubic|natural against scipy's LinearNDInterpolator and
    CloughTocher2DInterpolator and gdal_grid -a linear|invdist|nearest.
  * The bundled sample site (samples/sjtsk): its spot heights with and without its road
    breaklines, against the analytic terrain (tools/dtm-sample z) on a 0.5 m grid.
  * A sharp ridge crossed by a breakline along its crest: errors within 2 m of the crest.
  * Contour maps: the whitebox DEM's contours (gdal_contour -i 20, -i 50) as input with
    --z-field, with and without --contours-fix-flats: flat triangles and DEM error.
Needs /usr/bin/python3 with numpy, scipy (python3-scipy) and GDAL (python3-gdal), gdal_grid and
gdal_contour on PATH. Timings are wall times of one run each (noisy on a shared machine).
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np
from osgeo import gdal
from scipy.interpolate import CloughTocher2DInterpolator, LinearNDInterpolator

gdal.UseExceptions()
HERE = os.path.dirname(os.path.abspath(__file__))


def run(cmd, **kw):
    t0 = time.time()
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        sys.exit(f"compare_accuracy: {' '.join(cmd)} failed:\n{r.stderr}")
    return time.time() - t0, r


def read_raster(path):
    ds = gdal.Open(path)
    band = ds.GetRasterBand(1)
    a = band.ReadAsArray().astype(float)
    nd = band.GetNoDataValue()
    if nd is not None:
        a[a == nd] = np.nan
    return a, ds.GetGeoTransform()


class Grid:
    """Cell centres of a north-up raster: xmin, ymax, cell, cols, rows."""

    def __init__(self, xmin, ymax, cell, cols, rows):
        self.xmin, self.ymax, self.cell, self.cols, self.rows = xmin, ymax, cell, cols, rows

    def centres(self):
        x = self.xmin + (np.arange(self.cols) + 0.5) * self.cell
        y = self.ymax - (np.arange(self.rows) + 0.5) * self.cell
        return np.meshgrid(x, y)

    def extent(self):
        return (self.xmin, self.ymax - self.rows * self.cell, self.xmin + self.cols * self.cell,
                self.ymax)


def write_points(path, x, y, z):
    with open(path, "w") as f:
        f.write("x,y,z\n")
        for a, b, c in zip(x, y, z):
            f.write(f"{a:.4f},{b:.4f},{c:.5f}\n")
    vrt = path.replace(".csv", ".vrt")
    layer = os.path.basename(path)[:-4]
    with open(vrt, "w") as f:
        f.write(f"""<OGRVRTDataSource><OGRVRTLayer name="{layer}"><SrcDataSource>{path}</SrcDataSource>
<SrcLayer>{layer}</SrcLayer><GeometryType>wkbPoint25D</GeometryType>
<GeometryField encoding="PointFromColumns" x="x" y="y" z="z"/></OGRVRTLayer></OGRVRTDataSource>""")
    return vrt, layer


def dtm_grid(args, work, name, inputs, grid, method, extra=()):
    out = os.path.join(work, f"{name}_dtm_{method}.tif")
    e = grid.extent()
    t, _ = run([args.dtm, "grid", *inputs, "-o", out, "--cell", repr(grid.cell), "--extent",
                f"{e[0]!r},{e[1]!r},{e[2]!r},{e[3]!r}", "--interpolation", method, "-q", *extra])
    return read_raster(out)[0], t


def gdal_grid(work, name, vrt, layer, grid, algorithm):
    out = os.path.join(work, f"{name}_gdal_{algorithm.split(':')[0]}.tif")
    e = grid.extent()
    t, _ = run(["gdal_grid", "--config", "GDAL_NUM_THREADS", "ALL_CPUS", "-q", "-a",
                algorithm + ":nodata=-9999", "-ot", "Float64", "-txe", repr(e[0]), repr(e[2]),
                "-tye", repr(e[3]), repr(e[1]), "-outsize", str(grid.cols), str(grid.rows),
                "-l", layer, vrt, out])
    return read_raster(out)[0], t


def scipy_grid(x, y, z, grid, kind):
    X, Y = grid.centres()
    t0 = time.time()
    pts = np.column_stack([x, y])
    f = (LinearNDInterpolator(pts, z) if kind == "linear"
         else CloughTocher2DInterpolator(pts, z))
    return f(X, Y), time.time() - t0


def report(title, results, truth, check):
    """results: list of (label, values on the grid, seconds); check: mask of cells to use."""
    mask = check.copy()
    for _, v, _ in results:
        mask &= np.isfinite(v)
    print(f"\n### {title}\n")
    print(f"{int(mask.sum())} check cells\n")
    print("| method | RMSE | MAE | max | time s |")
    print("|---|---|---|---|---|")
    rows = {}
    for label, v, t in results:
        e = v[mask] - truth[mask]
        rmse, mae, mx = math.sqrt(np.mean(e * e)), np.mean(np.abs(e)), np.max(np.abs(e))
        rows[label] = rmse
        print(f"| {label} | {rmse:.4f} | {mae:.4f} | {mx:.3f} | {t:.2f} |")
    return rows


def sampling_case(args, work, name, grid, truth, count, rng, gdal_methods=True):
    valid = np.argwhere(np.isfinite(truth))
    pick = valid[rng.choice(len(valid), size=count, replace=False)]
    X, Y = grid.centres()
    x, y, z = X[pick[:, 0], pick[:, 1]], Y[pick[:, 0], pick[:, 1]], truth[pick[:, 0], pick[:, 1]]
    check = np.isfinite(truth)
    check[pick[:, 0], pick[:, 1]] = False
    csv = os.path.join(work, f"{name}.csv")
    vrt, layer = write_points(csv, x, y, z)
    results = []
    for m in ("linear", "cubic", "natural"):
        v, t = dtm_grid(args, work, name, [csv], grid, m)
        results.append((f"dtm {m}", v, t))
    for kind in ("linear", "cubic"):
        v, t = scipy_grid(x, y, z, grid, kind)
        label = "scipy LinearNDInterpolator" if kind == "linear" else "scipy CloughTocher2DInterpolator"
        results.append((label, v, t))
    if gdal_methods:
        for alg in ("linear:radius=0", "invdist", "nearest"):
            v, t = gdal_grid(work, name, vrt, layer, grid, alg)
            results.append((f"gdal_grid {alg.split(':')[0]}", v, t))
    return report(f"{name}: {count} points sampled from {grid.cols} x {grid.rows} cells of "
                  f"{grid.cell:g}", results, truth, check)


def whitebox(args):
    a, gt = read_raster(os.path.join(args.data, "dem-whiteboxR", "DEM.tif"))
    a[a < -1e4] = np.nan
    return Grid(gt[0], gt[3], gt[1], a.shape[1], a.shape[0]), a


def volcano(args):
    m = np.loadtxt(os.path.join(args.data, "points-r-davis-topo-volcano", "volcano.csv"),
                   delimiter=",", skiprows=1)[:, 1:]
    # rows are one way across the crater, columns the other: 10 m cells, row 0 to the north
    return Grid(0.0, m.shape[0] * 10.0, 10.0, m.shape[1], m.shape[0]), m


def sample_site(args, work):
    samples = os.path.join(HERE, "..", "samples", "sjtsk")
    grid = Grid(-750300.0, -1050020.0, 0.5, 500, 360)
    X, Y = grid.centres()
    pairs = os.path.join(work, "site_pairs.txt")
    np.savetxt(pairs, np.column_stack([X.ravel(), Y.ravel()]), fmt="%.3f")
    with open(pairs) as f:
        out = subprocess.run([args.sample, "z", "-"], stdin=f, capture_output=True, text=True,
                             check=True).stdout
    truth = np.full(X.size, np.nan)
    for i, line in enumerate(out.splitlines()):
        if "off the surveyed surface" not in line:
            truth[i] = float(line.split()[2])
    truth = truth.reshape(X.shape)
    points = os.path.join(samples, "points.csv")
    common = ["--skip-bad-lines", "--crs", "EPSG:5514", "--boundary",
              os.path.join(samples, "boundary.shp"), "--holes",
              os.path.join(samples, "building.shp")]
    brk = ["--breaklines", os.path.join(samples, "breaklines.shp")]
    results = []
    for m in ("linear", "cubic", "natural"):
        v, t = dtm_grid(args, work, "site_brk", [points], grid, m, common + brk)
        results.append((f"dtm {m}, breaklines", v, t))
    for m in ("linear", "cubic"):
        v, t = dtm_grid(args, work, "site_pts", [points], grid, m, common)
        results.append((f"dtm {m}, points only", v, t))
    xyz = np.genfromtxt(points, delimiter=",", skip_header=1, usecols=(1, 2, 3),
                        invalid_raise=False)
    xyz = xyz[np.all(np.isfinite(xyz), axis=1)]
    xyz = np.unique(xyz, axis=0)
    _, keep = np.unique(xyz[:, :2], axis=0, return_index=True)
    xyz = xyz[keep]
    for kind in ("linear", "cubic"):
        v, t = scipy_grid(xyz[:, 0], xyz[:, 1], xyz[:, 2], grid, kind)
        results.append((f"scipy {'Linear' if kind == 'linear' else 'CloughTocher'}, points only",
                        v, t))
    return report("sample site (samples/sjtsk, 2,982 spot heights, 8 road breaklines) against "
                  "its analytic terrain, 0.5 m cells", results, truth, np.isfinite(truth))


def ridge_case(args, work, rng):
    """A sharp ridge: z = 100 + 0.3 x' - 0.8 |y'| + smooth terms, crest along a slanted line."""
    def truth_at(x, y):
        d = y - (50.0 + 0.15 * (x - 50.0))  # offset from the crest line
        return 100.0 - 0.8 * np.abs(d) + 0.02 * x + 2.0 * np.sin(x / 13.0) * np.cos(y / 17.0)

    n = 1500
    x, y = rng.uniform(0, 100, n), rng.uniform(0, 100, n)
    x = np.concatenate([x, [0, 100, 0, 100]])
    y = np.concatenate([y, [0, 0, 100, 100]])
    csv = os.path.join(work, "ridge.csv")
    write_points(csv, x, y, truth_at(x, y))
    crest_x = np.arange(0.0, 100.01, 4.0)
    crest_y = 50.0 + 0.15 * (crest_x - 50.0)
    brk = os.path.join(work, "ridge_crest.csv")
    with open(brk, "w") as f:
        f.write("shapeid,x,y,z\n")
        for a, b in zip(crest_x, crest_y):
            f.write(f"1,{a:.4f},{b:.4f},{float(truth_at(a, b)):.5f}\n")
    grid = Grid(0.0, 100.0, 0.25, 400, 400)
    X, Y = grid.centres()
    truth = truth_at(X, Y)
    near = np.abs(Y - (50.0 + 0.15 * (X - 50.0))) <= 2.0
    near &= (X > 5) & (X < 95)
    results = []
    for m in ("linear", "cubic", "natural"):
        v, t = dtm_grid(args, work, "ridge_brk", [csv], grid, m, ["--breaklines", brk])
        results.append((f"dtm {m}, crest breakline", v, t))
    for m in ("linear", "cubic"):
        v, t = dtm_grid(args, work, "ridge_pts", [csv], grid, m)
        results.append((f"dtm {m}, no breakline", v, t))
    v, t = scipy_grid(x, y, truth_at(x, y), grid, "cubic")
    results.append(("scipy CloughTocher, no breakline", v, t))
    return report("sharp ridge with its crest as a breakline (1,500 points, 100 x 100 m): cells "
                  "within 2 m of the crest", results, truth, near)


def contour_case(args, work, interval):
    dem = os.path.join(args.data, "dem-whiteboxR", "DEM.tif")
    grid, truth = whitebox(args)
    shp = os.path.join(work, f"contours{interval}.shp")
    for ext in (".shp", ".shx", ".dbf", ".prj"):
        if os.path.exists(shp[:-4] + ext):
            os.remove(shp[:-4] + ext)
    run(["gdal_contour", "-q", "-a", "ELEV", "-i", str(interval), dem, shp])
    results = []
    flats = {}
    for fix in ("--no-contours-fix-flats", "--contours-fix-flats"):
        for m in ("linear", "cubic"):
            out = os.path.join(work, f"contours{interval}{fix}_{m}.tif")
            e = grid.extent()
            t, r = run([args.dtm, "grid", shp, "--z-field", "ELEV", fix, "-o", out, "--cell",
                        repr(grid.cell), "--extent", f"{e[0]!r},{e[1]!r},{e[2]!r},{e[3]!r}",
                        "--interpolation", m])
            line = re.search(r"contour flats: (.*?);", r.stderr)
            if line:
                flats[fix] = line.group(1)
            label = f"dtm {m}, {'flats removed' if fix == '--contours-fix-flats' else 'as given'}"
            results.append((label, read_raster(out)[0], t))
    rows = report(f"whitebox DEM contours every {interval} m (gdal_contour) as input, "
                  f"--z-field ELEV: DEM against the DEM", results, truth, np.isfinite(truth))
    for fix, text in flats.items():
        print(f"\nflat triangles ({fix}): {text}")
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--dtm", default=os.path.join(HERE, "..", "build", "tools", "dtm"))
    p.add_argument("--sample", default=os.path.join(HERE, "..", "build", "tools", "dtm-sample",
                                                    "dtm-sample"))
    p.add_argument("--data", default=os.path.join(HERE, "..", "..", "shared", "data"))
    p.add_argument("--work", default=None)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--quick", action="store_true", help="one size per DEM, no contours")
    args = p.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="dtm-accuracy.")
    os.makedirs(work, exist_ok=True)
    rng = np.random.default_rng(args.seed)
    print(f"# dtm surface accuracy (seed {args.seed}, work {work})")
    summary = []
    grid, truth = whitebox(args)
    for count in ((7025,) if args.quick else (2000, 7025, 15000)):
        rows = sampling_case(args, work, f"whitebox{count}", grid, truth, count, rng)
        summary.append((f"whitebox {count}", rows))
    grid, truth = volcano(args)
    for count in ((800,) if args.quick else (500, 1500)):
        rows = sampling_case(args, work, f"volcano{count}", grid, truth, count, rng)
        summary.append((f"volcano {count}", rows))
    summary.append(("sample site", sample_site(args, work)))
    summary.append(("ridge", ridge_case(args, work, rng)))
    if not args.quick:
        for interval in (20, 50):
            summary.append((f"contours {interval}", contour_case(args, work, interval)))
    print("\n### cubic against scipy's Clough-Tocher and dtm linear (RMSE ratios)\n")
    for name, rows in summary:
        cubic = rows.get("dtm cubic")
        if cubic is None:
            continue
        ct = rows.get("scipy CloughTocher2DInterpolator")
        lin = rows.get("dtm linear")
        print(f"- {name}: dtm cubic / scipy CT = {cubic / ct:.4f}, dtm cubic / dtm linear = "
              f"{cubic / lin:.4f}")
    cpu = subprocess.run([os.path.join(HERE, "cpu_info.sh")], capture_output=True, text=True)
    print(f"\n{cpu.stdout.strip() or f'load average {os.getloadavg()[0]:.1f}'}")


if __name__ == "__main__":
    main()
