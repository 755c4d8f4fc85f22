#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# dtm map on a 10^6-point site against GDAL making a georeferenced contour PDF, in one run.
#
#   bench/map_render.sh [DTM_BINARY] [POINTS] [WORKDIR]
#
# 1. Generates POINTS (default 10^6) random survey points of a hilly terrain (about 60 m of
#    relief with 70 m and 20 m undulations) over 1000 m x 700 m at S-JTSK (EPSG:5514) offsets.
# 2. dtm: `dtm map points.csv --scale 2000` (read + triangulate + contours + spot heights +
#    label placement + drawing + GDAL georeferencing: the whole job), then `dtm map tin.ply`
#    (the map from a TIN: the map's own share).
# 3. Reference: what GDAL offers for "a georeferenced contour PDF" given a DEM: `gdal_contour`
#    at the same interval on a 0.5 m DEM of the same surface (written by `dtm grid`, not timed)
#    and `gdal_translate -of PDF` of the DEM with the contours as an OGR vector layer. GDAL's PDF
#    has no label placement, spot heights, grid or furniture, and the reference does not include
#    triangulating the points, so the ratio flatters GDAL.
# 4. Checks what the issue judges: pdfinfo page = extent / scale, gdalinfo EPSG:5514 and
#    NEATLINE, every label of the report found by pdftotext.
# Take the bench lock: flock /work/coord/bench.lock bench/map_render.sh
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
dtm="${1:-$here/../build/tools/dtm}"
points="${2:-1000000}"
work="${3:-$(mktemp -d /tmp/dtm-map-render.XXXXXX)}"
mkdir -p "$work"
[[ -x "$dtm" ]] || { echo "map_render: no dtm binary at $dtm" >&2; exit 2; }
for tool in gdal_contour gdal_translate pdfinfo pdftotext gdalinfo; do
    command -v "$tool" >/dev/null || { echo "map_render: $tool not found" >&2; exit 2; }
done

# timed LABEL CMD...: runs CMD, prints wall and CPU (user + sys) seconds, sets wall_s and cpu_s.
# On a shared machine the CPU time is the figure to compare (the wall time includes waiting for
# the cores); on an idle machine wall <= CPU because dtm triangulates in parallel.
timed() {
    local label="$1"
    shift
    /usr/bin/time -f '%e %U %S' -o "$work/time.txt" "$@"
    read -r wall user sys < "$work/time.txt"
    wall_s="$wall"
    cpu_s=$(echo "$user + $sys" | bc -l | awk '{printf "%.2f", $1}')
    echo "   $label: wall $wall_s s, CPU $cpu_s s"
}
ratio() { echo "$1 / $2" | bc -l | awk '{printf "%.2f", $1}'; }

"$here/cpu_info.sh"

echo "== work directory: $work"
echo "== generating $points points"
python3 - "$points" "$work/points.csv" <<'PY'
import math, random, sys
n, path = int(sys.argv[1]), sys.argv[2]
random.seed(20261201)
x0, y0, w, h = -745000.0, -1046000.0, 1000.0, 700.0
with open(path, "w") as f:
    f.write("x,y,z\n")
    corners = [(0, 0), (w, 0), (0, h), (w, h)]
    for i in range(n):
        u, v = corners[i] if i < 4 else (random.uniform(0, w), random.uniform(0, h))
        z = (300 + 25 * math.sin(u / 180) * math.cos(v / 150) + 0.02 * u
             + 4 * math.sin(u / 37 + v / 53) + 1.5 * math.cos(u / 11 - v / 17))
        f.write(f"{x0 + u:.3f},{y0 + v:.3f},{z:.3f}\n")
PY
"$dtm" tin "$work/points.csv" --crs EPSG:5514 -o "$work/tin.ply" -q
"$dtm" grid "$work/tin.ply" --cell 0.5 -o "$work/dem.tif" -q

echo "== dtm map from the points (the whole job)"
timed "dtm map points.csv" "$dtm" map "$work/points.csv" --crs EPSG:5514 --scale 2000 \
    --interval 2.5 -o "$work/map.pdf" --report "$work/map.json" -q
whole_wall="$wall_s" whole_cpu="$cpu_s"

echo "== dtm map from the TIN (the map's own share)"
timed "dtm map tin.ply" "$dtm" map "$work/tin.ply" --crs EPSG:5514 --scale 2000 --interval 2.5 \
    -o "$work/map_tin.pdf" -q
tin_wall="$wall_s" tin_cpu="$cpu_s"

echo "== reference: gdal_contour + gdal_translate -of PDF (from the DEM)"
rm -f "$work/contours.gpkg" "$work/ref.pdf"
timed "gdal_contour" gdal_contour -q -i 2.5 -a elevation "$work/dem.tif" "$work/contours.gpkg"
ref_wall="$wall_s" ref_cpu="$cpu_s"
# the PDF driver writes 8-bit rasters: the DEM scaled to grey, the contours as a vector layer
timed "gdal_translate -of PDF" gdal_translate -q -of PDF -ot Byte -scale "$work/dem.tif" \
    "$work/ref.pdf" -co OGR_DATASOURCE="$work/contours.gpkg" -co OGR_DISPLAY_FIELD=elevation
ref_wall=$(echo "$ref_wall + $wall_s" | bc -l) ref_cpu=$(echo "$ref_cpu + $cpu_s" | bc -l)
echo "   reference total: wall $ref_wall s, CPU $ref_cpu s"
echo "== ratio reference / dtm map points.csv: wall $(ratio "$ref_wall" "$whole_wall"), CPU $(ratio "$ref_cpu" "$whole_cpu")"
echo "== ratio reference / dtm map tin.ply:    wall $(ratio "$ref_wall" "$tin_wall"), CPU $(ratio "$ref_cpu" "$tin_cpu")"

echo "== checks"
python3 - "$work" <<'PY'
import json, subprocess, sys
work = sys.argv[1]
r = json.load(open(f"{work}/map.json"))
page = r["pages"][0]
ext = page["extent"]
w_mm = (ext[2] - ext[0]) * 1000 / page["scale"]
h_mm = (ext[3] - ext[1]) * 1000 / page["scale"]
info = subprocess.run(["pdfinfo", f"{work}/map.pdf"], capture_output=True, text=True).stdout
size = [l for l in info.splitlines() if l.startswith("Page size")][0].split()
pw, ph = float(size[2]) * 25.4 / 72, float(size[4]) * 25.4 / 72
print(f"   page {pw:.2f} x {ph:.2f} mm, extent / scale {w_mm:.2f} x {h_mm:.2f} mm")
g = subprocess.run(["gdalinfo", f"{work}/map.pdf"], capture_output=True, text=True).stdout
print("   gdalinfo EPSG:5514:", 'ID["EPSG",5514]]' in g, " NEATLINE:", "NEATLINE=POLYGON" in g)
words = subprocess.run(["pdftotext", f"{work}/map.pdf", "-"], capture_output=True,
                       text=True).stdout.split()
labels = [l["text"] for l in r["labels"]["placed_labels"]]
missing = [t for t in set(labels) if words.count(t) < labels.count(t)]
print(f"   labels placed {len(labels)}, not placed {r['labels']['not_placed']},"
      f" found by pdftotext: {'all' if not missing else 'missing ' + str(missing)}")
print(f"   spot heights {r['spot_heights']['drawn']} (summits {r['spot_heights']['summits']},"
      f" pits {r['spot_heights']['pits']}, saddles {r['spot_heights']['saddles']})")
PY
