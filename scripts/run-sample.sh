#!/usr/bin/env bash
# Quick-start command 1: installs what is missing, builds dtm and runs the main job (`dtm build`)
# on the bundled sample samples/sjtsk. Outputs go to out/sample/ (replaced as a whole, atomically).
# Usage: scripts/run-sample.sh [build-dir]
set -euo pipefail

repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$repo_root"
build_dir=${1:-"$repo_root/build"}

scripts/install-deps.sh
scripts/build.sh "$build_dir" --target dtm

dtm="$build_dir/tools/dtm"
mkdir -p out

# ---- THE MAIN JOB: the one line to change to run another job on the sample -------------------
"$dtm" build samples/sjtsk/points.csv --breaklines samples/sjtsk/breaklines.shp --boundary samples/sjtsk/boundary.shp --holes samples/sjtsk/building.shp --crs EPSG:5514 --skip-bad-lines -o out/sample
# Smaller alternative (TIN only, on the generated fixture of scripts/make-quick-sample.py):
# "$dtm" tin samples/quick/points.xyz --breaklines samples/quick/breaklines.csv -o out/sample/tin.ply --stats --check
# ----------------------------------------------------------------------------------------------

echo "run-sample: outputs in $repo_root/out/sample/"
ls -l out/sample/
