#!/usr/bin/env bash
# Quick-start command 1: installs what is missing, builds dtm and runs the main job on the
# bundled sample. Outputs go to out/sample/.
# Usage: scripts/run-sample.sh [build-dir]
set -euo pipefail

repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$repo_root"
build_dir=${1:-"$repo_root/build"}

scripts/install-deps.sh
scripts/build.sh "$build_dir" --target dtm

sample=samples/quick
if [[ ! -f "$sample/points.xyz" || ! -f "$sample/breaklines.csv" ]]; then
    python3 scripts/make-quick-sample.py "$sample"
fi
mkdir -p out/sample
dtm="$build_dir/tools/dtm"

# ---- THE MAIN JOB: switch this one line to `dtm build` when it lands -------------------------
"$dtm" tin "$sample/points.xyz" --breaklines "$sample/breaklines.csv" -o out/sample/tin.ply --stats --check
# ----------------------------------------------------------------------------------------------

echo "run-sample: outputs in $repo_root/out/sample/"
ls -l out/sample/
