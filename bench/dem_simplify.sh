#!/usr/bin/env bash
# DEM thinning (`--dem-max-error`, algo/dem_reduce) against the delatin npm package (mapbox's port
# of Fogleman's hmm: sequential Garland-Heckbert greedy insertion with Delaunay flips), on the
# same height field in one run: vertices kept, max and RMS error reached, wall time, and the
# ratio of the vertex counts. delatin is a bench-only oracle, installed into build/bench-node.
#
#   bench/dem_simplify.sh [DTM_BINARY] [SIZE] [ERRORS...]
#   defaults: build/tools/dtm/dtm, 512 (a SIZE x SIZE grid of 2 m cells, bench/terrain_points.py's
#   terrain), errors 0.05 0.2 1
# Timings: run it under `flock /work/coord/bench.lock` on a shared machine.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dtm=${1:-$here/../build/tools/dtm/dtm}
size=${2:-512}
shift $(($# > 2 ? 2 : $#))
errors=${*:-0.05 0.2 1}
node_dir=${DTM_BENCH_NODE:-$here/../build/bench-node}
if [ ! -f "$node_dir/node_modules/delatin/package.json" ]; then
    mkdir -p "$node_dir"
    npm install --prefix "$node_dir" --no-audit --no-fund --silent delatin@0.2.0 >&2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# the height field: an ESRI ASCII grid for dtm, the same numbers as JSON for delatin
python3 - "$size" "$work" "$here" <<'EOF'
import json, sys
sys.path.insert(0, sys.argv[3])
from terrain_points import height
n, work = int(sys.argv[1]), sys.argv[2]
cell = 2.0
rows = []
for j in range(n):            # row 0 is the north edge in the grid file
    v = (n - 1 - j) * cell + cell / 2
    rows.append([round(height(i * cell + cell / 2, v), 3) for i in range(n)])
with open(f"{work}/dem.asc", "w") as f:
    f.write(f"ncols {n}\nnrows {n}\nxllcorner -750000\nyllcorner -1050000\ncellsize {cell}\n")
    f.write("NODATA_value -9999\n")
    for r in rows:
        f.write(" ".join(f"{z:.3f}" for z in r) + "\n")
with open(f"{work}/dem.json", "w") as f:
    json.dump([z for r in rows for z in r], f)
EOF

cat > "$work/delatin.mjs" <<'EOF'
import fs from 'fs';
const [, , dir, file, n, ...errors] = process.argv;
const { default: Delatin } = await import(dir + '/node_modules/delatin/index.js');
const data = JSON.parse(fs.readFileSync(file, 'utf8'));
for (const e of errors) {
    const start = process.hrtime.bigint();
    const tin = new Delatin(data, Number(n), Number(n));
    tin.run(Number(e));
    const s = Number(process.hrtime.bigint() - start) / 1e9;
    console.log(`${e} ${tin.coords.length / 2} ${tin.getMaxError()} ${tin.getRMSD()} ${s}`);
}
EOF
node "$work/delatin.mjs" "$node_dir" "$work/dem.json" "$size" $errors > "$work/delatin.txt"

echo "DEM ${size} x ${size} cells ($((size * size)) points), bench/terrain_points.py terrain, 2 m cells"
printf '%-8s %12s %12s %8s %12s %12s %12s %12s %9s %9s\n' max_error dtm_vertices \
    delatin_vert ratio dtm_max delatin_max dtm_rms delatin_rms dtm_s delatin_s
for e in $errors; do
    start=$(date +%s.%N)
    "$dtm" tin "$work/dem.asc" --dem-max-error "$e" -o "$work/tin.ply" 2> "$work/dtm.err"
    end=$(date +%s.%N)
    line=$(grep 'DEM:' "$work/dtm.err" | tail -1)
    vertices=$(sed -E 's/.*; ([0-9]+) vertices.*/\1/' <<< "$line")
    max=$(sed -E 's/.*max error ([^,]+),.*/\1/' <<< "$line")
    rms=$(sed -E 's/.*RMS ([^ ]+) over.*/\1/' <<< "$line")
    read -r _ dv dmax drms ds < <(grep "^$e " "$work/delatin.txt")
    awk -v e="$e" -v v="$vertices" -v dv="$dv" -v m="$max" -v dm="$dmax" -v r="$rms" \
        -v dr="$drms" -v t="$(echo "$end - $start" | bc)" -v dt="$ds" 'BEGIN {
        printf "%-8s %12d %12d %8.3f %12.4g %12.4g %12.4g %12.4g %9.2f %9.2f\n",
               e, v, dv, v / dv, m, dm, r, dr, t, dt }'
done
echo "ratio = dtm vertices / delatin vertices (both within max_error at every cell)"
