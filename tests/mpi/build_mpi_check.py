#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""`mpirun -np P dtm build POINTS.csv -o OUT` against `dtm build` on one process (issue 18,
R-E3 and R-P5): tin.ply byte for byte, dem.vrt the serial dem.tif cell for cell (GDAL XYZ),
hillshade.vrt the serial hillshade.tif cell for cell,
contours.vrt the serial contour layer line for line (OGR CSV), report.json's TIN, extent, z
range, areas (exact sums), DEM grid and contour figures equal, surface.pvtp naming one VTK piece
per rank whose triangles add up to the TIN's, dtm.qgs opening in the real QGIS (PyQGIS) with
every layer valid in EPSG:5514; survey points with duplicates, with hard breaklines, a boundary
and a hole; a bad line exits 2 once and leaves no folder; refusals. Usage:
build_mpi_check.py DTM MPIEXEC NP"""
import json
import os
import re
import subprocess
import tempfile

from mpi_checks import check, finish, ranks, run, write_breaklines, write_ring

QGIS_OPEN = r"""
import sys
from qgis.core import QgsApplication, QgsProject
app = QgsApplication([], False)
app.initQgis()
project = QgsProject.instance()
if not project.read(sys.argv[1]):
    print("cannot read"); sys.exit(1)
layers = list(project.mapLayers().values())
bad = [l.name() for l in layers if not l.isValid() or l.crs().authid() != "EPSG:5514"]
names = sorted(l.source().split("|")[0].rsplit("/", 1)[-1] for l in layers)
print(" ".join(names), "bad:", bad)
sys.exit(1 if bad or len(layers) < 2 else 0)
"""


def has_qgis():
    return subprocess.run(["/usr/bin/python3", "-c", "import qgis.core"],
                          capture_output=True).returncode == 0 if os.path.exists("/usr/bin/python3") else False


def text(command):
    return subprocess.run(command, capture_output=True, text=True, check=True).stdout


def write_survey(path):
    import random
    rng = random.Random(20261204)
    with open(path, "w") as out:
        out.write("id,x,y,z\n")
        for i in range(9000):
            x = -750000 - rng.randrange(50000) / 100.0
            y = -1050000 - rng.randrange(40000) / 100.0
            z = 250 + ((x + 750000) ** 2 + (y + 1050000) ** 2) ** 0.5 / 40.0 + rng.random()
            out.write(f"P{i},{x},{y},{z:.3f}\n")
            if i % 50 == 3:
                out.write(f"D{i},{x},{y},{z + 1:.3f}\n")


def same_report(name, a, b):
    for key in ("tin", "extent", "z_range", "area", "crs"):
        check(a[key] == b[key], f"{name}: report {key}: {a[key]} vs {b[key]}")
    for key in ("cell", "cell_rule", "cols", "rows", "xmin", "ymax"):
        check(a["dem"][key] == b["dem"][key], f"{name}: report dem.{key}")
    for key in ("interval", "interval_rule", "levels", "lines", "index_every"):
        check(a["contours"][key] == b["contours"][key], f"{name}: report contours.{key}")


with tempfile.TemporaryDirectory() as tmp:
    survey = os.path.join(tmp, "survey.csv")
    write_survey(survey)
    lines, boundary, hole = (os.path.join(tmp, f) for f in ("lines.csv", "boundary.csv", "hole.csv"))
    write_breaklines(lines, -750500, -1050400, 500, 400)
    write_ring(boundary, -750250, -1050200, 180, 262)
    write_ring(hole, -750250, -1050180, 45, 258)
    cases = [("survey", ["--crs", "EPSG:5514", "--duplicates", "mean"]),
             ("breaklines", ["--crs", "EPSG:5514", "--breaklines", lines, "--boundary", boundary,
                             "--holes", hole, "--cell", "2", "--interval", "1"])]
    qgis = has_qgis()
    for n, (name, options) in enumerate(cases):
        serial_dir, dist_dir = os.path.join(tmp, f"serial{n}"), os.path.join(tmp, f"dist{n}")
        serial = run(["build", survey, "-o", serial_dir, "-q"] + options, False)
        dist = run(["build", survey, "-o", dist_dir] + options, True)
        check(serial.returncode == 0, f"{name}: serial dtm build: {serial.stderr}")
        check(dist.returncode == 0, f"{name}: mpirun dtm build: exit {dist.returncode}: {dist.stderr}")
        if serial.returncode != 0 or dist.returncode != 0:
            continue
        with open(os.path.join(serial_dir, "tin.ply"), "rb") as a, open(os.path.join(dist_dir, "tin.ply"), "rb") as b:
            check(a.read() == b.read(), f"{name}: tin.ply differs")
        if ranks == 1:  # mpirun -np 1 runs the serial build
            check(os.path.exists(os.path.join(dist_dir, "dem.tif")), f"{name}: -np 1 is the serial build")
            continue
        check(dist.stdout.count("products and report.json") == 1, f"{name}: summary once: {dist.stdout!r}")
        dem_a = text(["gdal_translate", "-q", "-of", "XYZ", os.path.join(serial_dir, "dem.tif"), "/vsistdout/"])
        dem_b = text(["gdal_translate", "-q", "-of", "XYZ", os.path.join(dist_dir, "dem.vrt"), "/vsistdout/"])
        check(dem_a.count("\n") > 1000 and dem_a == dem_b, f"{name}: dem.vrt differs from dem.tif")
        hs_a = text(["gdal_translate", "-q", "-of", "XYZ", os.path.join(serial_dir, "hillshade.tif"), "/vsistdout/"])
        hs_b = text(["gdal_translate", "-q", "-of", "XYZ", os.path.join(dist_dir, "hillshade.vrt"), "/vsistdout/"])
        check(hs_a.count("\n") > 1000 and hs_a == hs_b, f"{name}: hillshade.vrt differs from hillshade.tif")
        layer = lambda path: text(["ogr2ogr", "-f", "GeoJSON", "/vsistdout/", path, "contours",
                                   "-lco", "COORDINATE_PRECISION=17", "-lco", "RFC7946=NO"])
        features = lambda t: [l for l in t.splitlines() if l.startswith('{ "type": "Feature"')]
        ca = features(layer(os.path.join(serial_dir, "contours.gpkg")))
        cb = features(layer(os.path.join(dist_dir, "contours.vrt")))
        check(len(ca) > 5 and ca == cb, f"{name}: contours.vrt differs ({len(ca)} vs {len(cb)} lines)")
        with open(os.path.join(serial_dir, "report.json")) as a, open(os.path.join(dist_dir, "report.json")) as b:
            ra, rb = json.load(a), json.load(b)
        same_report(name, ra, rb)
        check(rb["distributed"]["ranks"] == ranks, f"{name}: report ranks {rb['distributed']}")
        check(rb["points"]["total_accounted"] == ra["points"]["total_accounted"], f"{name}: points accounted")
        for f in rb["outputs"]:
            check(os.path.exists(os.path.join(dist_dir, f)), f"{name}: listed output {f} missing")
        with open(os.path.join(dist_dir, "surface.pvtp")) as f:
            pieces = re.findall(r'Source="([^"]+)"', f.read())
        check(1 <= len(pieces) <= ranks, f"{name}: {len(pieces)} VTK pieces")
        polys = 0
        for piece in pieces:
            with open(os.path.join(dist_dir, piece), "rb") as f:
                head = f.read(4000).decode("latin-1")
            polys += sum(int(v) for v in re.findall(r'NumberOfPolys="(\d+)"', head))
        check(polys == ra["tin"]["triangles"], f"{name}: VTK pieces hold {polys} triangles")
        if qgis:
            opened = subprocess.run(["/usr/bin/python3", "-c", QGIS_OPEN, os.path.join(dist_dir, "dtm.qgs")],
                                    capture_output=True, text=True, env={**os.environ, "QT_QPA_PLATFORM": "offscreen"})
            check(opened.returncode == 0 and "contours.vrt" in opened.stdout and "dem.vrt" in opened.stdout
                  and "hillshade.vrt" in opened.stdout,
                  f"{name}: QGIS opens dtm.qgs: {opened.stdout} {opened.stderr[-500:]}")
        else:
            print("note: no PyQGIS at /usr/bin/python3: dtm.qgs not opened in QGIS")

    if ranks > 1:
        bad = os.path.join(tmp, "bad.csv")
        with open(survey) as f, open(bad, "w") as out:
            rows = f.read().splitlines()
            rows.insert(len(rows) - 5, "B1,-750100,oops,250")
            out.write("\n".join(rows) + "\n")
        out_dir = os.path.join(tmp, "bad_out")
        r = run(["build", bad, "--crs", "EPSG:5514", "-o", out_dir, "-q"], True)
        check(r.returncode == 2 and r.stderr.count("bad.csv") == 1, f"bad line: exit {r.returncode}: {r.stderr!r}")
        check(not os.path.exists(out_dir), "bad line: no output folder")
        for extra in (["--base", survey], ["--map-scale", "1000"], ["--interpolation", "cubic"]):
            r = run(["build", survey, "-o", os.path.join(tmp, "refused"), "-q"] + extra, True)
            check(r.returncode == 2 and "does not take" in r.stderr, f"{extra} refused: {r.stderr!r}")
        check(not os.path.exists(os.path.join(tmp, "refused")), "refusals leave no folder")

finish("build")
