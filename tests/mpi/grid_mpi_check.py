#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""`mpirun -np P dtm grid POINTS.csv -o dem.vrt --cell C` against `dtm grid -o dem.tif` on one
process (issue 18, R-P3): the VRT over one GeoTIFF per rank has the serial DEM's cells bit for
bit (both read by GDAL's gdal_translate as raw Float32), its geotransform and CRS; inputs: S-JTSK
survey points with duplicates and a cocircular lattice whose vertices and edges fall on cell
centres and whose rows the rank blocks cut; gdaldem's hillshade, slope and aspect of the tiled DEM equal
the serial ones cell for cell. Usage: grid_mpi_check.py DTM MPIEXEC NP"""
import os
import random
import subprocess
import tempfile

from mpi_checks import check, dtm, finish, ranks, run, write_breaklines, write_ring


def raw(path):
    """The raster's cells as GDAL reads them (ENVI: raw Float32), and its gdalinfo."""
    out = path + ".bin"
    subprocess.run(["gdal_translate", "-q", "-of", "ENVI", path, out], check=True)
    with open(out, "rb") as f:
        cells = f.read()
    info = subprocess.run(["gdalinfo", path], capture_output=True, text=True, check=True).stdout
    keep = [l for l in info.splitlines() if l.startswith(("Size is", "Origin", "Pixel Size", "    ID[", "NoData"))]
    return cells, keep


def write_survey(path):
    rng = random.Random(20261202)
    with open(path, "w") as out:
        out.write("id,x,y,z\n")
        for i in range(15000):
            x = -750000 - rng.randrange(60000) / 100.0
            y = -1050000 - rng.randrange(40000) / 100.0
            out.write(f"P{i},{x},{y},{250 + (i % 1000) / 10.0}\n")
            if i % 50 == 7:
                out.write(f"D{i},{x},{y},{300 + i % 7}\n")


def write_lattice(path):
    with open(path, "w") as out:
        out.write("x,y,z\n")
        for j in range(60):
            for i in range(80):
                out.write(f"{i * 2 + 0.5},{j * 2 + 0.5},{100 + (i * 7 + j * 13) % 17 / 3.0}\n")


with tempfile.TemporaryDirectory() as tmp:
    survey, lattice = os.path.join(tmp, "survey.csv"), os.path.join(tmp, "lattice.csv")
    write_survey(survey)
    write_lattice(lattice)
    lines = os.path.join(tmp, "lines.csv")
    write_breaklines(lines, -750600, -1050400, 600, 400)
    boundary, hole = os.path.join(tmp, "boundary.csv"), os.path.join(tmp, "hole.csv")
    write_ring(boundary, -750300, -1050200, 190, 290)
    write_ring(hole, -750300, -1050180, 50, 280)
    cases = [("survey", survey, ["--crs", "EPSG:5514", "--cell", "0.7"]),
             ("survey extent", survey, ["--crs", "EPSG:5514", "--cell", "2",
                                        "--extent", "-750700,-1050450,-750100,-1050050"]),
             ("lattice", lattice, ["--cell", "0.25", "--duplicates", "mean"]),
             ("survey breaklines", survey, ["--crs", "EPSG:5514", "--cell", "1.3", "--breaklines", lines]),
             ("survey boundary", survey, ["--crs", "EPSG:5514", "--cell", "1.1", "--breaklines", lines,
                                          "--boundary", boundary, "--holes", hole])]
    for name, points, options in cases:
        serial_tif, dist_vrt = os.path.join(tmp, "serial.tif"), os.path.join(tmp, f"dem-{len(name)}.vrt")
        serial = run(["grid", points, "-o", serial_tif, "-q"] + options, False)
        dist = run(["grid", points, "-o", dist_vrt, "-q"] + options, True)
        check(serial.returncode == 0, f"{name}: serial dtm grid: {serial.stderr}")
        check(dist.returncode == 0, f"{name}: mpirun dtm grid: exit {dist.returncode}: {dist.stderr}")
        if serial.returncode != 0 or dist.returncode != 0:
            continue
        check(dist.stdout.count("cells with data") == 1, f"{name}: summary printed once: {dist.stdout!r}")
        a, b = raw(serial_tif), raw(dist_vrt)
        check(len(a[0]) > 0 and a[0] == b[0], f"{name}: the DEM cells differ from the serial DEM")
        check(a[1] == b[1], f"{name}: georeference differs: {a[1]} vs {b[1]}")
        tiles = [f for f in os.listdir(tmp) if f.startswith(f"dem-{len(name)}-") and f.endswith(".tif")]
        check(len(tiles) == ranks, f"{name}: {len(tiles)} tiles for {ranks} ranks")

    # gdaldem's hillshade, slope and aspect of the tiled DEM: one GeoTIFF per rank from its rows
    # and one more on each side, the serial derivative's cells (NoData holes and edges included).
    name, points, options = cases[-1]
    derived = [("hillshade", "--hillshade"), ("slope", "--slope"), ("aspect", "--aspect")]
    serial = run(["grid", points, "-o", os.path.join(tmp, "s.tif"), "-q"] + options +
                 [a for k, o in derived for a in (o, os.path.join(tmp, f"s-{k}.tif"))], False)
    dist = run(["grid", points, "-o", os.path.join(tmp, "d.vrt"), "-q"] + options +
               [a for k, o in derived for a in (o, os.path.join(tmp, f"d-{k}.vrt"))], True)
    check(serial.returncode == 0 and dist.returncode == 0,
          f"derivatives: exit {serial.returncode} / {dist.returncode}: {serial.stderr} {dist.stderr}")
    if serial.returncode == 0 and dist.returncode == 0:
        for k, _ in derived:
            a, b = raw(os.path.join(tmp, f"s-{k}.tif")), raw(os.path.join(tmp, f"d-{k}.vrt"))
            check(len(a[0]) > 0 and a[0] == b[0], f"{k}: the cells differ from the serial {k}")
            check(a[1] == b[1], f"{k}: georeference or NoData differs: {a[1]} vs {b[1]}")
            tiles = [f for f in os.listdir(tmp) if f.startswith(f"d-{k}-") and f.endswith(".tif")]
            check(len(tiles) == ranks, f"{k}: {len(tiles)} tiles for {ranks} ranks")
    if ranks > 1:
        bad = run(["grid", survey, "--cell", "1", "-o", os.path.join(tmp, "e.vrt"),
                   "--slope", os.path.join(tmp, "e.tif")], True)
        check(bad.returncode == 2 and "give --slope NAME.vrt" in bad.stderr,
              f"--slope .tif under mpirun: exit {bad.returncode}: {bad.stderr!r}")
        check(not os.path.exists(os.path.join(tmp, "e.vrt")), "refused run wrote the DEM")

    if ranks > 1:
        refused = run(["grid", survey, "--cell", "1", "--interpolation", "cubic",
                       "-o", os.path.join(tmp, "c.vrt")], True)
        check(refused.returncode == 2 and refused.stderr.count("does not take") == 1,
              f"cubic refused: exit {refused.returncode}: {refused.stderr!r}")
        tif = run(["grid", survey, "--cell", "1", "-o", os.path.join(tmp, "t.tif")], True)
        check(tif.returncode == 2 and "give -o NAME.vrt" in tif.stderr, f".tif under mpirun: {tif.stderr!r}")

finish("grid")
