#!/usr/bin/env bash
# DEM error of `dtm tin --optimize CRITERION` against truth, under the bench lock: the bundled
# sample (analytic truth), the whiteboxR DEM (10 % and 3 % of its cells as points, 3 seeds) and
# R's volcano grid (25 %, 3 seeds). Markdown tables to stdout (docs/performance.md).
# Usage: bench/optimize_dem.sh [build-dir]
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
data=${DTM_SHARED_DATA_DIR:-$root/../shared/data}
run() { flock /work/coord/bench.lock "$build/bench/optimize_dem" "$@"; }
run sample "$root/samples/sjtsk" 0.5
run raster "$data/dem-whiteboxR/DEM.tif" 0.10 3
run raster "$data/dem-whiteboxR/DEM.tif" 0.03 3
run table "$data/points-r-davis-topo-volcano/volcano.csv" 10 0.25 3
