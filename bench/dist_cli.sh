#!/usr/bin/env bash
# `mpirun -np P dtm tin|grid|contour` against the same subcommand on one process, in one run,
# on the same S-JTSK point list (bench/make_inputs, N points, default 10^6; for `tin` also with
# make_inputs' N/2 breakline segments): wall times (best of
# RUNS), the ratio distributed / serial, and the outputs compared (PLY bytes; DEM cells through
# gdal_translate -of ENVI; contour features through ogr2ogr).
# Usage: BUILD=build bench/dist_cli.sh [N] [CELL]
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD:-$repo/build}
n=${1:-1000000}
cell=${2:-1}
runs=${RUNS:-2}
dtm=$build/tools/dtm
command -v mpirun >/dev/null || { echo "dist_cli.sh: mpirun not found (install openmpi-bin)"; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
    OMPI_MCA_btl=self,vader OMPI_MCA_oob_tcp_if_include=lo
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/bench/make_inputs" --kind uniform --n "$n" --out "$work" >/dev/null
pts=$work/points.xyz
"$repo/bench/cpu_info.sh" || true

best() {  # best wall time in seconds of RUNS runs of "$@"
    local b="" t
    for _ in $(seq "$runs"); do
        local s e
        s=$(date +%s.%N)
        "$@" >/dev/null 2>&1
        e=$(date +%s.%N)
        t=$(echo "$e - $s" | bc)
        if [[ -z "$b" ]] || (( $(echo "$t < $b" | bc) )); then b=$t; fi
    done
    printf '%.2f' "$b"
}
cells() { gdal_translate -q -of ENVI "$1" "$2" && md5sum < "$2" | cut -d' ' -f1; }

echo "points: $n; cell: $cell m; best of $runs runs"
echo
echo "| job | dtm (one process) | mpirun -np 2 | ratio | mpirun -np 4 | ratio | same output |"
echo "|---|---|---|---|---|---|---|"
serial=$(best "$dtm" tin "$pts" --crs EPSG:5514 -o "$work/s.ply")
d2=$(best mpirun -np 2 "$dtm" tin "$pts" --crs EPSG:5514 -o "$work/d2.ply")
d4=$(best mpirun -np 4 "$dtm" tin "$pts" --crs EPSG:5514 -o "$work/d4.ply")
same=no
cmp -s "$work/s.ply" "$work/d2.ply" && cmp -s "$work/s.ply" "$work/d4.ply" && same="yes (PLY bytes)"
echo "| tin | ${serial} s | ${d2} s | $(echo "scale=2; $d2 / $serial" | bc)x | ${d4} s | $(echo "scale=2; $d4 / $serial" | bc)x | $same |"
"$build/bench/make_inputs" --kind breaklines --n "$n" --out "$work/bl" >/dev/null
bpts=$work/bl/points.xyz
blines=$work/bl/breaklines.csv
serial=$(best "$dtm" tin "$bpts" --breaklines "$blines" --crs EPSG:5514 -o "$work/bs.ply")
d2=$(best mpirun -np 2 "$dtm" tin "$bpts" --breaklines "$blines" --crs EPSG:5514 -o "$work/bd2.ply")
d4=$(best mpirun -np 4 "$dtm" tin "$bpts" --breaklines "$blines" --crs EPSG:5514 -o "$work/bd4.ply")
same=no
cmp -s "$work/bs.ply" "$work/bd2.ply" && cmp -s "$work/bs.ply" "$work/bd4.ply" && same="yes (PLY bytes)"
echo "| tin, N/2 breakline segments | ${serial} s | ${d2} s | $(echo "scale=2; $d2 / $serial" | bc)x | ${d4} s | $(echo "scale=2; $d4 / $serial" | bc)x | $same |"
serial=$(best "$dtm" grid "$pts" --crs EPSG:5514 --cell "$cell" -o "$work/s.tif")
d2=$(best mpirun -np 2 "$dtm" grid "$pts" --crs EPSG:5514 --cell "$cell" -o "$work/d2.vrt")
d4=$(best mpirun -np 4 "$dtm" grid "$pts" --crs EPSG:5514 --cell "$cell" -o "$work/d4.vrt")
same=no
s=$(cells "$work/s.tif" "$work/s.raw")
[[ "$s" == "$(cells "$work/d2.vrt" "$work/d2.raw")" && "$s" == "$(cells "$work/d4.vrt" "$work/d4.raw")" ]] \
    && same="yes (cells)"
echo "| grid | ${serial} s | ${d2} s | $(echo "scale=2; $d2 / $serial" | bc)x | ${d4} s | $(echo "scale=2; $d4 / $serial" | bc)x | $same |"
serial=$(best "$dtm" contour "$pts" --crs EPSG:5514 --interval 1 --no-labels -o "$work/s.gpkg")
d2=$(best mpirun -np 2 "$dtm" contour "$pts" --crs EPSG:5514 --interval 1 --no-labels -o "$work/c2.vrt")
d4=$(best mpirun -np 4 "$dtm" contour "$pts" --crs EPSG:5514 --interval 1 --no-labels -o "$work/c4.vrt")
same=no
lines() { ogr2ogr -f CSV /vsistdout/ "$1" -lco GEOMETRY=AS_WKT | md5sum | cut -d' ' -f1; }
s=$(lines "$work/s.gpkg")
[[ "$s" == "$(lines "$work/c2.vrt")" && "$s" == "$(lines "$work/c4.vrt")" ]] && same="yes (features)"
echo "| contour, interval 1 m | ${serial} s | ${d2} s | $(echo "scale=2; $d2 / $serial" | bc)x | ${d4} s | $(echo "scale=2; $d4 / $serial" | bc)x | $same |"
echo
echo "job start alone: mpirun -np 2 dtm --version $(best mpirun -np 2 "$dtm" --version) s"
