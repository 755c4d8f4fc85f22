#!/usr/bin/env python3
"""Writes the small deterministic fixture used by scripts/run-sample.sh until the real sample
generator lands: samples/quick/points.xyz (x y z, one point a line) and samples/quick/breaklines.csv
(GDAL CSV with a `wkt` column holding LINESTRING Z).

The terrain is a hill with a sharp ridge in S-JTSK (EPSG:5514) coordinates, near
x = -745 000, y = -1 045 000, 200 m x 200 m. Usage: scripts/make-quick-sample.py [out-dir]
"""
import math
import random
import sys
from pathlib import Path

X0, Y0, SIZE = -745200.0, -1045200.0, 200.0


def height(x: float, y: float) -> float:
    u, v = (x - X0) / SIZE, (y - Y0) / SIZE
    hill = 12.0 * math.exp(-((u - 0.5) ** 2 + (v - 0.55) ** 2) * 6.0)
    ridge = 4.0 * max(0.0, 1.0 - abs(v - 0.3) * 8.0)
    return round(300.0 + hill + ridge + 2.0 * u, 3)


def main() -> None:
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent / "samples" / "quick"
    out.mkdir(parents=True, exist_ok=True)
    rng = random.Random(5514)
    lines = []
    for row in range(20):
        for col in range(20):
            x = round(X0 + (col + 0.5 + rng.uniform(-0.35, 0.35)) * SIZE / 20, 3)
            y = round(Y0 + (row + 0.5 + rng.uniform(-0.35, 0.35)) * SIZE / 20, 3)
            lines.append(f"{x:.3f} {y:.3f} {height(x, y):.3f}\n")
    (out / "points.xyz").write_text("".join(lines))

    def linestring(points):
        coords = ", ".join(f"{x:.3f} {y:.3f} {height(x, y):.3f}" for x, y in points)
        return f"LINESTRING Z ({coords})"

    ridge = [(X0 + 12.3 + i * 17.5, Y0 + 0.3 * SIZE + 0.37 * math.sin(i)) for i in range(11)]
    toe = [(X0 + 40.7 + i * 11.1, Y0 + 150.2 + 9.3 * math.sin(i * 0.6)) for i in range(11)]
    rows = ["id,kind,wkt\n",
            f'1,ridge,"{linestring(ridge)}"\n',
            f'2,toe,"{linestring(toe)}"\n']
    (out / "breaklines.csv").write_text("".join(rows))
    print(f"wrote {len(lines)} points and 2 breaklines to {out}")


if __name__ == "__main__":
    main()
