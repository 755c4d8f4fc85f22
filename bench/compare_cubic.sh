#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Speed of the smooth surfaces: `dtm grid --interpolation cubic` (and natural) against the linear
# DEM, same points, same 2000 x 2000 cells, in one run.
#
#   bench/compare_cubic.sh [DTM_BINARY] [POINTS] [WORKDIR] [--natural]
#
# Generates POINTS (default 10^6) uniform random points of a smooth terrain over 2000 m x 2000 m
# at S-JTSK offsets (the input of bench/compare_gdal.sh), then times, best of three runs each,
# the whole `dtm grid` command (read CSV, triangulate, [estimate gradients,] rasterise, write a
# DEFLATE GeoTIFF) for linear and cubic, and prints the ratio. The cubic DEM is also compared
# with the true terrain at the cell centres (RMSE against the linear DEM's). With --natural the
# natural-neighbour DEM is timed as well. Take the bench lock: flock /work/coord/bench.lock ...
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
dtm="${1:-$here/../build/tools/dtm}"
points="${2:-1000000}"
work="${3:-$(mktemp -d /tmp/dtm-compare-cubic.XXXXXX)}"
natural="${4:-}"
mkdir -p "$work"
xmin=-750000; xmax=-748000; ymin=-1050000; ymax=-1048000
python=/usr/bin/python3
[[ -x "$dtm" ]] || { echo "compare_cubic: no dtm binary at $dtm" >&2; exit 2; }

echo "== work directory: $work"
echo "== generating $points points"
"$python" "$here/terrain_points.py" "$points" "$work/points.csv" "$xmin" "$ymin" "$xmax" "$ymax"

best_time() {  # best wall time of three runs of the command
    local best=""
    for _ in 1 2 3; do
        local t0 t1
        t0=$(date +%s.%N)
        "$@"
        t1=$(date +%s.%N)
        local t
        t=$(echo "$t1 - $t0" | bc -l)
        if [[ -z "$best" ]] || (( $(echo "$t < $best" | bc -l) )); then best=$t; fi
    done
    printf "%.3f" "$best"
}

grid() { "$dtm" grid "$work/points.csv" -o "$work/$1.tif" --cell 1 --extent "$xmin,$ymin,$xmax,$ymax" \
         --interpolation "$1" -q >/dev/null; }
echo "== DEM 2000 x 2000, best of 3"
linear=$(best_time grid linear)
cubic=$(best_time grid cubic)
echo "dtm grid --interpolation linear: ${linear} s"
echo "dtm grid --interpolation cubic:  ${cubic} s"
echo "cubic / linear: $(echo "$cubic / $linear" | bc -l | awk '{printf "%.2f", $1}')"
if [[ "$natural" == "--natural" ]]; then
    nat=$(best_time grid natural)
    echo "dtm grid --interpolation natural: ${nat} s ($(echo "$nat / $linear" | bc -l | awk '{printf "%.2f", $1}') x linear)"
fi
"$python" - "$work" "$xmin" "$ymin" "$here" <<'PY'
import math, os, sys
import numpy as np
from osgeo import gdal
work, x0, y0 = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
ds = gdal.Open(f"{work}/linear.tif"); gt = ds.GetGeoTransform()
cols, rows = ds.RasterXSize, ds.RasterYSize
u = gt[0] + (np.arange(cols) + 0.5) * gt[1] - x0
v = gt[3] + (np.arange(rows) + 0.5) * gt[5] - y0
U, V = np.meshgrid(u, v)
sys.path.insert(0, sys.argv[4])
from terrain_points import height
truth = height(U, V, np.sin, np.cos)
for name in ("linear", "cubic", "natural"):
    if not os.path.exists(f"{work}/{name}.tif"):  # natural only with --natural
        continue
    a = gdal.Open(f"{work}/{name}.tif").ReadAsArray().astype(float)
    ok = a != -9999
    e = a[ok] - truth[ok]
    print(f"{name:8s} RMSE against the terrain {math.sqrt(np.mean(e * e)):.4f} m, max {np.max(np.abs(e)):.4f} m")
PY
"$here/cpu_info.sh"
