#!/usr/bin/env python3
"""Inputs for timing the breakline pre-pass (docs/performance.md, "Crossing breaklines").

crossing_lines.py DIR [N]
writes into DIR, at S-JTSK offsets on a 2 km square (seed 1):
  pts.xyz    N survey points (default 10^6), a tilted plane;
  free.csv   20 000 polylines of 9 short segments along rows that never touch (180 000 segments);
  cross.csv  3 000 random straight polylines of 14 segments of about 28 m (about 29 000 crossings).
Time with, for example:
  dtm tin DIR/pts.xyz --breaklines DIR/cross.csv --crs EPSG:5514 -o t.ply --stats
"""
import os
import random
import sys

E, N = -750000.0, -1050000.0


def wkt(points):
    return '"LINESTRING Z (' + ", ".join(f"{E + x:.3f} {N + y:.3f} {z:.3f}" for x, y, z in points) + ')"'


def main(argv):
    out = argv[1]
    n = int(argv[2]) if len(argv) > 2 else 1_000_000
    os.makedirs(out, exist_ok=True)
    random.seed(1)
    with open(os.path.join(out, "pts.xyz"), "w") as f:
        for _ in range(n):
            x, y = random.uniform(0, 2000), random.uniform(0, 2000)
            f.write(f"{E + x:.3f} {N + y:.3f} {300 + 0.01 * x + 0.02 * y:.3f}\n")
    with open(os.path.join(out, "free.csv"), "w") as f:
        f.write("id,kind,wkt\n")
        k = 0
        for r in range(400):
            y = 2.5 + 5 * r
            for c in range(50):
                x0 = c * 40 + 1
                z = 300 + 0.01 * x0 + 0.02 * y
                k += 1
                f.write(f"{k},l,{wkt([(x0 + i * 3.7, y + 0.3 * ((i % 3) - 1), z) for i in range(10)])}\n")
    with open(os.path.join(out, "cross.csv"), "w") as f:
        f.write("id,kind,wkt\n")
        for k in range(3000):
            x, y = random.uniform(0, 2000), random.uniform(0, 2000)
            dx, dy = random.uniform(-20, 20), random.uniform(-20, 20)
            points = []
            for _ in range(15):
                points.append((min(max(x, 0), 2000), min(max(y, 0), 2000), 300 + random.uniform(0, 1)))
                x += dx
                y += dy
            f.write(f"{k + 1},l,{wkt(points)}\n")


if __name__ == "__main__":
    main(sys.argv)
