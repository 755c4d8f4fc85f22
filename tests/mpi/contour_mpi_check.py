#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""`mpirun -np P dtm contour POINTS.csv -o contours.vrt --interval I --no-labels` against `dtm
contour -o contours.gpkg --no-labels` on one process (issue 18, R-P4): read through OGR
(ogr2ogr to GeoJSON, every coordinate printed at 17 digits: exactly), the OGR VRT over one
GeoPackage per rank is the serial layer line for line, in order and bit for bit, with its fields
and CRS; inputs: S-JTSK survey points with duplicates (smoothed lines too), a lattice whose
heights sit exactly on the levels (flat triangles, ridges on a level, the doubled pieces the
tracer drops) and explicit levels. Usage: contour_mpi_check.py DTM MPIEXEC NP"""
import os
import random
import subprocess
import tempfile

from mpi_checks import check, finish, ranks, run, write_breaklines, write_ring


def layer(path):
    """Every feature as ogr2ogr writes it to GeoJSON (its fields, and its coordinates at 17
    significant digits: exact), and the layer's CRS and fields."""
    geojson = subprocess.run(["ogr2ogr", "-f", "GeoJSON", "/vsistdout/", path,
                              "-lco", "COORDINATE_PRECISION=17", "-lco", "RFC7946=NO"],
                             capture_output=True, text=True, check=True).stdout
    features = [l for l in geojson.splitlines() if l.startswith('{ "type": "Feature"')]
    info = subprocess.run(["ogrinfo", "-so", "-al", path], capture_output=True, text=True,
                          check=True).stdout
    keep = [l for l in info.splitlines()
            if l.startswith(("Geometry", "Feature Count", "elevation", "index", "closed", '    ID["EPSG"'))]
    return features, keep


def write_survey(path):
    rng = random.Random(20261203)
    with open(path, "w") as out:
        out.write("id,x,y,z\n")
        for i in range(12000):
            x = -750000 - rng.randrange(50000) / 100.0
            y = -1050000 - rng.randrange(40000) / 100.0
            z = 250 + ((x + 750000) ** 2 + (y + 1050000) ** 2) ** 0.5 / 40.0 + rng.random()
            out.write(f"P{i},{x},{y},{z:.3f}\n")
            if i % 60 == 7:
                out.write(f"D{i},{x},{y},{z + 1:.3f}\n")


def write_lattice(path):
    with open(path, "w") as out:
        out.write("x,y,z\n")
        for j in range(50):
            for i in range(70):
                out.write(f"{i * 2},{j * 2},{100 + (i * 7 + j * 13) % 6}\n")


with tempfile.TemporaryDirectory() as tmp:
    survey, lattice = os.path.join(tmp, "survey.csv"), os.path.join(tmp, "lattice.csv")
    write_survey(survey)
    write_lattice(lattice)
    lines = os.path.join(tmp, "lines.csv")
    write_breaklines(lines, -750500, -1050400, 500, 400)
    boundary, hole = os.path.join(tmp, "boundary.csv"), os.path.join(tmp, "hole.csv")
    write_ring(boundary, -750250, -1050200, 180, 262)
    write_ring(hole, -750250, -1050180, 45, 258)
    cases = [("survey", survey, ["--crs", "EPSG:5514", "--interval", "0.5", "--duplicates", "mean"]),
             ("survey smoothed", survey, ["--crs", "EPSG:5514", "--interval", "2", "--smooth", "2"]),
             ("survey levels", survey, ["--crs", "EPSG:5514", "--levels", "251.3,255,260.25,262",
                                        "--smooth", "1", "--index-every", "2"]),
             ("survey breaklines", survey, ["--crs", "EPSG:5514", "--interval", "1", "--breaklines", lines]),
             ("survey boundary", survey, ["--crs", "EPSG:5514", "--interval", "1", "--breaklines", lines,
                                          "--boundary", boundary, "--holes", hole]),
             ("lattice", lattice, ["--interval", "1"]),
             ("lattice base", lattice, ["--interval", "0.5", "--base", "0.25"])]
    for n, (name, points, options) in enumerate(cases):
        serial_gpkg, dist_vrt = os.path.join(tmp, f"serial-{n}.gpkg"), os.path.join(tmp, f"c{n}.vrt")
        serial = run(["contour", points, "-o", serial_gpkg, "--no-labels", "-q"] + options, False)
        dist = run(["contour", points, "-o", dist_vrt, "--no-labels", "-q"] + options, True)
        check(serial.returncode == 0, f"{name}: serial dtm contour: {serial.stderr}")
        check(dist.returncode == 0, f"{name}: mpirun dtm contour: exit {dist.returncode}: {dist.stderr}")
        if serial.returncode != 0 or dist.returncode != 0:
            continue
        check(dist.stdout.count("lines of") == 1, f"{name}: summary printed once: {dist.stdout!r}")
        a, b = layer(serial_gpkg), layer(dist_vrt)
        check(len(a[0]) > 2 and a[0] == b[0], f"{name}: the lines or their fields differ from "
              "the serial layer (coordinates at 17 digits)")
        check(a[1] == b[1], f"{name}: layer description differs: {a[1]} vs {b[1]}")
        pieces = [f for f in os.listdir(tmp) if f.startswith(f"c{n}-") and f.endswith(".gpkg")]
        check(1 <= len(pieces) <= ranks, f"{name}: {len(pieces)} pieces for {ranks} ranks")

    if ranks > 1:
        labels = run(["contour", survey, "--interval", "1", "-o", os.path.join(tmp, "l.vrt")], True)
        check(labels.returncode == 2 and labels.stderr.count("give --no-labels") == 1,
              f"labels refused: exit {labels.returncode}: {labels.stderr!r}")
        cubic = run(["contour", survey, "--interval", "1", "--no-labels", "--interpolation", "cubic",
                     "-o", os.path.join(tmp, "c.vrt")], True)
        check(cubic.returncode == 2 and "do not take" in cubic.stderr, f"cubic refused: {cubic.stderr!r}")
        gpkg = run(["contour", survey, "--interval", "1", "--no-labels", "-o", os.path.join(tmp, "t.gpkg")], True)
        check(gpkg.returncode == 2 and "give -o NAME.vrt" in gpkg.stderr, f".gpkg under mpirun: {gpkg.stderr!r}")

finish("contour")
