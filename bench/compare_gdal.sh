#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# dtm grid / dtm contour against gdal_grid -a linear / gdal_contour, in one run.
#
#   [REPEAT=3] bench/compare_gdal.sh [DTM_BINARY] [POINTS] [WORKDIR]
#
# Every timed command runs REPEAT times, dtm's and GDAL's taking turns; the best time of each is
# compared (the bench machine's run-to-run spread is large: see docs/performance.md).
#
# 1. Generates POINTS (default 10^6) uniform random survey points of a smooth terrain with
#    about 150 m of relief over 2000 m x 2000 m at S-JTSK (EPSG:5514) offsets.
# 2. DEM: `dtm grid` and `gdal_grid -a linear:radius=0` (all threads) on the same points and the
#    same 2000 x 2000 cells. The extent is given as the raster's outer edges to both
#    (gdal_grid's -txe/-tye are outer edges and it samples cell centres, as dtm does), so the
#    same cell centres are sampled. Prints both times, the ratio, the largest absolute difference
#    where both have a value, and the NoData footprint mismatch (bench/compare_rasters.cpp).
#    gdal_grid triangulates with qhull in floating point: at S-JTSK magnitudes (10^6 m) qhull
#    merges nearly cocircular facets and splits them arbitrarily, so a few cells differ from the
#    exact Delaunay TIN. The same comparison is therefore repeated with gdal_grid run on the same
#    points shifted to local coordinates (then re-georeferenced with gdal_translate -a_ullr):
#    there the two must agree everywhere.
# 3. Contours at 1 m (`--no-labels`: gdal_contour places no labels either): `dtm contour` on
#    the TIN (`dtm tin` PLY as input) and on the points
#    (reading + triangulation included) against `gdal_contour -i 1` on gdal_grid's 2000 x 2000
#    raster; all write a GeoPackage.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
dtm="${1:-$here/../build/tools/dtm}"
points="${2:-1000000}"
work="${3:-$(mktemp -d /tmp/dtm-compare-gdal.XXXXXX)}"
mkdir -p "$work"
xmin=-750000; xmax=-748000; ymin=-1050000; ymax=-1048000; size=2000

[[ -x "$dtm" ]] || { echo "compare_gdal: no dtm binary at $dtm" >&2; exit 2; }
command -v gdal_grid >/dev/null || { echo "compare_gdal: gdal_grid not found" >&2; exit 2; }

now() { date +%s.%N; }
elapsed() { echo "$2 - $1" | bc -l | awk '{printf "%.2f", $1}'; }
repeat="${REPEAT:-3}"
best() {  # best PREVIOUS COMMAND...: runs COMMAND once, prints the smaller of its time and PREVIOUS
    local previous=$1; shift
    local t0 t1 t
    t0=$(now); "$@" >&2; t1=$(now); t=$(elapsed "$t0" "$t1")
    if [[ -z "$previous" ]] || (( $(echo "$t < $previous" | bc -l) )); then echo "$t"; else echo "$previous"; fi
}

"$here/cpu_info.sh"
echo "== work directory: $work"
echo "== generating $points points"
python3 "$here/terrain_points.py" "$points" "$work/points.csv" "$xmin" "$ymin" "$xmax" "$ymax" \
    --local "$work/points_local.csv"
for name in points points_local; do
    cat > "$work/$name.vrt" <<VRT
<OGRVRTDataSource>
  <OGRVRTLayer name="$name">
    <SrcDataSource>$work/$name.csv</SrcDataSource>
    <SrcLayer>$name</SrcLayer>
    <GeometryType>wkbPoint25D</GeometryType>
    <GeometryField encoding="PointFromColumns" x="x" y="y" z="z"/>
  </OGRVRTLayer>
</OGRVRTDataSource>
VRT
done

compare="$work/compare_rasters"
g++ -std=c++20 -O2 -I/usr/include/gdal "$here/compare_rasters.cpp" -o "$compare" -lgdal

echo "== DEM ${size} x ${size} (best of $repeat runs each, dtm and GDAL taking turns)"
run_dtm_grid() {
    rm -f "$work/dtm.tif"
    "$dtm" grid "$work/points.csv" -o "$work/dtm.tif" --cell 1 --extent "$xmin,$ymin,$xmax,$ymax" -q
}
run_gdal_grid() {
    rm -f "$work/gdal.tif"
    gdal_grid --config GDAL_NUM_THREADS ALL_CPUS -q -a linear:radius=0:nodata=-9999 -ot Float32 \
        -txe "$xmin" "$xmax" -tye "$ymax" "$ymin" -outsize "$size" "$size" \
        -l points "$work/points.vrt" "$work/gdal.tif"
}
dtm_grid=""; gdal_grid_s=""
for ((rep = 1; rep <= repeat; ++rep)); do
    dtm_grid=$(best "$dtm_grid" run_dtm_grid)
    gdal_grid_s=$(best "$gdal_grid_s" run_gdal_grid)
done
echo "dtm grid:  ${dtm_grid} s"
echo "gdal_grid: ${gdal_grid_s} s"
echo "speed-up:  $(echo "$gdal_grid_s / $dtm_grid" | bc -l | awk '{printf "%.1f", $1}') x"
echo -n "dtm vs gdal_grid at S-JTSK offsets:    "
"$compare" "$work/dtm.tif" "$work/gdal.tif"
gdal_grid --config GDAL_NUM_THREADS ALL_CPUS -q -a linear:radius=0:nodata=-9999 -ot Float32 \
    -txe 0 "$((xmax - xmin))" -tye "$((ymax - ymin))" 0 -outsize "$size" "$size" \
    -l points_local "$work/points_local.vrt" "$work/gdal_local.tif"
gdal_translate -q -a_ullr "$xmin" "$ymax" "$xmax" "$ymin" "$work/gdal_local.tif" "$work/gdal_local_georef.tif"
echo -n "dtm vs gdal_grid in local coordinates: "
"$compare" "$work/dtm.tif" "$work/gdal_local_georef.tif"

echo "== contours at 1 m"
"$dtm" tin "$work/points.csv" -o "$work/tin.ply" -q >/dev/null
run_dtm_contour_tin() {
    rm -f "$work/dtm_contours_tin.gpkg"
    "$dtm" contour "$work/tin.ply" -o "$work/dtm_contours_tin.gpkg" --interval 1 --no-labels -q
}
run_dtm_contour() {
    rm -f "$work/dtm_contours.gpkg"
    "$dtm" contour "$work/points.csv" -o "$work/dtm_contours.gpkg" --interval 1 --no-labels -q
}
run_gdal_contour() {
    rm -f "$work/gdal_contours.gpkg"
    gdal_contour -q -i 1 -a elevation -3d "$work/gdal.tif" "$work/gdal_contours.gpkg"
}
dtm_contour_tin=""; dtm_contour=""; gdal_contour_s=""
for ((rep = 1; rep <= repeat; ++rep)); do
    dtm_contour_tin=$(best "$dtm_contour_tin" run_dtm_contour_tin)
    dtm_contour=$(best "$dtm_contour" run_dtm_contour)
    gdal_contour_s=$(best "$gdal_contour_s" run_gdal_contour)
done
echo "dtm contour (TIN .ply -> contours):      ${dtm_contour_tin} s"
echo "dtm contour (points -> TIN -> contours): ${dtm_contour} s"
echo "gdal_contour (2000 x 2000 raster):       ${gdal_contour_s} s"
echo "speed-up (TIN input):    $(echo "$gdal_contour_s / $dtm_contour_tin" | bc -l | awk '{printf "%.1f", $1}') x"
echo "speed-up (points input): $(echo "$gdal_contour_s / $dtm_contour" | bc -l | awk '{printf "%.1f", $1}') x"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
echo "features: dtm $(ogrinfo -so -al "$work/dtm_contours.gpkg" | awk '/Feature Count/ {print $3}')," \
     "gdal $(ogrinfo -so -al "$work/gdal_contours.gpkg" | awk '/Feature Count/ {print $3}')"
