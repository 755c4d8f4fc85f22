#!/usr/bin/env python3
"""The benchmarks' smooth terrain at S-JTSK offsets (bench/compare_gdal.sh, bench/compare_cubic.sh).

terrain_points.py N OUT.csv XMIN YMIN XMAX YMAX [--local OUT_LOCAL.csv]
writes N survey points (the four corners, so that every tool covers the whole extent, then
uniform random points, seed 20261124, coordinates rounded to mm) as x,y,z; with --local also the
same points in coordinates relative to (XMIN, YMIN). height() is the terrain itself, also used
as the truth a DEM is compared with.
"""
import math
import random
import sys


def height(u, v, sin=math.sin, cos=math.cos):
    """Terrain height at (u, v) metres from the extent's corner (numpy: pass np.sin, np.cos)."""
    return (300.0 + 40.0 * sin(u / 300.0) * cos(v / 250.0) + 0.03 * u
            + 6.0 * sin(u / 37.0 + v / 53.0) + 2.0 * cos(u / 11.0 - v / 17.0))


def main(argv):
    n, path = int(argv[1]), argv[2]
    x0, y0, x1, y1 = map(float, argv[3:7])
    local = argv[8] if len(argv) > 8 and argv[7] == "--local" else None
    random.seed(20261124)
    pts = [(x0, y0), (x1, y0), (x0, y1), (x1, y1)]
    pts += [(random.uniform(x0, x1), random.uniform(y0, y1)) for _ in range(n - 4)]
    with open(path, "w") as f, (open(local, "w") if local else open("/dev/null", "w")) as g:
        f.write("x,y,z\n")
        g.write("x,y,z\n")
        for x, y in pts:
            x, y = round(x, 3), round(y, 3)
            u, v = x - x0, y - y0
            z = height(u, v)
            f.write(f"{x:.3f},{y:.3f},{z:.3f}\n")
            g.write(f"{u:.3f},{v:.3f},{z:.3f}\n")


if __name__ == "__main__":
    main(sys.argv)
