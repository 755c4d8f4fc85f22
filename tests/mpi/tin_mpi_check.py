#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""`mpirun -np P dtm tin POINTS.csv -o tin.ply` against `dtm tin` on one process (issue 18):
the same PLY bytes (also with hard breaklines crossing the seams and each other, and a 2-D breakline
through survey points in every rank's part of the file, soft 2-D lines, a 2-D boundary off the
points; points transformed by `--target-crs` or, in degrees, projected to their UTM zone), the
tiled TIN
(`-o tin.json`) put together by `dtm tin` and `dtm grid` as the same TIN, a GeoPackage read by
feature ranges (also filtered by `--where`), the serial reader's
message and exit code 2 for a bad line in the last
rank's byte range (printed once), a clear refusal of what the distributed run does not take yet,
and `--stats` naming the ranks. Usage: tin_mpi_check.py DTM MPIEXEC NP"""
import json
import math
import os
import random
import subprocess
import tempfile

from mpi_checks import check, dtm, finish, ranks, run, write_breaklines, write_ring


def write_points(path, n, bad_line=None):
    rng = random.Random(20261202)
    with open(path, "w") as out:
        out.write("# survey in S-JTSK\nid,x,y,z\n")
        for i in range(n):
            x = -750000 - rng.randrange(200000) / 100.0
            y = -1050000 - rng.randrange(200000) / 100.0
            if i % 50 == 7:  # an exact duplicate of the previous point, another height
                out.write(f"D{i},{last[0]},{last[1]},{300 + i % 7}\n")
            out.write(f"P{i},{x},{y},{250 + (i % 1000) / 10.0}\n")
            last = (x, y)
            if i % 333 == 0:
                out.write("\n# a comment\n")
        if bad_line:
            out.write("P-bad,-750000.25,no-number,251\n")


def same_ply(tmp, label, points, args):
    """`dtm tin POINTS ARGS` on one process and under mpirun: both succeed, same PLY bytes."""
    serial_ply, dist_ply = os.path.join(tmp, "serial-x.ply"), os.path.join(tmp, "dist-x.ply")
    serial = run(["tin", points, "-o", serial_ply] + args, False)
    dist = run(["tin", points, "-o", dist_ply] + args, True)
    check(serial.returncode == 0 and dist.returncode == 0,
          f"{label}: exit {serial.returncode} / {dist.returncode}: {serial.stderr} {dist.stderr}")
    if serial.returncode == 0 and dist.returncode == 0:
        with open(serial_ply, "rb") as a, open(dist_ply, "rb") as b:
            check(a.read() == b.read(), f"{label}: the PLY differs from the serial one")


with tempfile.TemporaryDirectory() as tmp:
    points = os.path.join(tmp, "points.csv")
    write_points(points, 20000)
    for rule in ("first", "mean"):
        serial = run([ "tin", points, "-o", os.path.join(tmp, "serial.ply"), "--crs", "EPSG:5514",
                      "--duplicates", rule, "-q"], False)
        dist = run(["tin", points, "-o", os.path.join(tmp, "dist.ply"), "--crs", "EPSG:5514",
                    "--duplicates", rule, "-q"], True)
        check(serial.returncode == 0, f"serial dtm tin: {serial.stderr}")
        check(dist.returncode == 0, f"mpirun dtm tin ({rule}): exit {dist.returncode}: {dist.stderr}")
        if serial.returncode == 0 and dist.returncode == 0:
            with open(os.path.join(tmp, "serial.ply"), "rb") as a, open(os.path.join(tmp, "dist.ply"), "rb") as b:
                check(a.read() == b.read(), f"the PLY differs from the serial one ({rule})")

    lines = os.path.join(tmp, "lines.csv")
    with open(points) as f:  # a line through survey points: its vertices merge with them
        rows = [r.split(",") for r in f.read().splitlines()[2:40] if r.startswith("P")]
    write_breaklines(lines, -752000, -1052000, 2000, 2000, [(r[1], r[2], r[3]) for r in rows[:8]])
    serial = run(["tin", points, "--breaklines", lines, "-o", os.path.join(tmp, "serial-b.ply"),
                  "--crs", "EPSG:5514", "--stats"], False)
    dist = run(["tin", points, "--breaklines", lines, "-o", os.path.join(tmp, "dist-b.ply"),
                "--crs", "EPSG:5514", "--stats"], True)
    check(serial.returncode == 0 and dist.returncode == 0,
          f"breaklines: exit {serial.returncode} / {dist.returncode}: {serial.stderr} {dist.stderr}")
    if serial.returncode == 0 and dist.returncode == 0:
        with open(os.path.join(tmp, "serial-b.ply"), "rb") as a, open(os.path.join(tmp, "dist-b.ply"), "rb") as b:
            serial_bytes = a.read()
            check(b"element edge 0" not in serial_bytes, "breaklines: the serial PLY has constrained edges")
            check(serial_bytes == b.read(), "breaklines: the PLY differs from the serial one")
        a, b = json.loads(serial.stdout), json.loads(dist.stdout)
        for key in ("points_in", "duplicates_merged", "vertices", "triangles", "constrained_edges"):
            check(a[key] == b[key], f"breaklines --stats {key}: {a[key]} serial, {b[key]} distributed")

    # A 2-D breakline (no z column) through survey points in every rank's part of the file: its
    # vertices take the first such point's z, which the mean rule then averages in.
    lines2d = os.path.join(tmp, "lines2d.csv")
    with open(points) as f:
        rows = [r.split(",") for r in f.read().splitlines() if r.startswith("P")]
    with open(lines2d, "w") as out:
        out.write("shapeid,x,y\n")
        for k in range(9):
            r = rows[k * (len(rows) - 1) // 8]
            out.write(f"1,{r[1]},{r[2]}\n")
    two_d = ["--breaklines", lines2d, "--crs", "EPSG:5514", "--duplicates", "mean", "-q"]
    same_ply(tmp, "2-D breakline", points, two_d)
    # A 2-D boundary off the survey points, partly beyond their hull: heights from a first
    # surface of the points and the breakline (nearest vertex beyond the hull).
    ring2d = os.path.join(tmp, "ring2d.csv")
    with open(ring2d, "w") as out:
        out.write("shapeid,x,y\n")
        for k in range(31):
            a = 2 * math.pi * (k % 30) / 30
            r = 1050 * (1 + 0.08 * math.sin(3 * (k % 30)))
            out.write(f"1,{-751000 + r * math.cos(a):.4f},{-1051000 + r * math.sin(a):.4f}\n")
    # Soft 2-D lines across the seams and the hard line: heights from a first surface.
    soft2d = os.path.join(tmp, "soft2d.csv")
    with open(soft2d, "w") as out:
        out.write("shapeid,x,y\n1,-751990.5,-1051000.25\n1,-750010.5,-1050990.75\n"
                  "2,-751003.5,-1051990.5\n2,-750997.25,-1050010.5\n")
    soft = ["--soft-breaklines", soft2d]
    same_ply(tmp, "soft breaklines", points, two_d + soft)
    same_ply(tmp, "2-D boundary", points, two_d + ["--boundary", ring2d])

    # --target-crs: every rank transforms its points one by one as the serial load does (GDAL/
    # PROJ): GNSS latitude/longitude into S-JTSK, the S-JTSK survey into UTM with a breakline in
    # S-JTSK (its file is transformed by every rank).
    geo = os.path.join(tmp, "geo.csv")
    rng = random.Random(20261207)
    with open(geo, "w") as out:
        out.write("lon,lat,h\n")
        for i in range(6000):
            out.write(f"{14.40 + rng.random() * 0.02:.8f},{50.05 + rng.random() * 0.015:.8f},"
                      f"{200 + rng.random() * 5:.3f}\n")
    same_ply(tmp, "WGS 84 to S-JTSK", geo, ["--crs", "EPSG:4326", "--target-crs", "EPSG:5514"])
    same_ply(tmp, "S-JTSK to UTM", points, ["--crs", "EPSG:5514", "--target-crs", "EPSG:32633",
                                             "--breaklines", lines])
    # Without --target-crs, geographic points go to the UTM zone of their box's centre (exact
    # over the ranks), projected by GeographicLib, a breakline in degrees too; from S-JTSK's own
    # geographic CRS through WGS 84 first.
    geo_lines = os.path.join(tmp, "geo-lines.csv")
    with open(geo_lines, "w") as out:
        out.write("shapeid,x,y,z\n1,14.4012,50.0511,201\n1,14.4187,50.0633,203\n"
                  "2,14.4013,50.0639,202\n2,14.4191,50.0507,204\n")
    same_ply(tmp, "WGS 84 to its UTM zone", geo, ["--crs", "EPSG:4326", "--breaklines", geo_lines])
    geo_xy = os.path.join(tmp, "geo-xy.csv")  # x, y columns: the CRS is --crs's alone
    with open(geo, "r") as f, open(geo_xy, "w") as out:
        out.write("x,y,z\n" + "".join(f.readlines()[1:]))
    same_ply(tmp, "S-JTSK degrees to UTM", geo_xy, ["--crs", "EPSG:4156"])
    same_ply(tmp, "lat/lon columns are WGS 84 whatever --crs", geo, ["--crs", "EPSG:4156"])

    boundary, hole = os.path.join(tmp, "boundary.csv"), os.path.join(tmp, "hole.csv")
    write_ring(boundary, -751000, -1051000, 880, 262)
    write_ring(hole, -751000, -1050900, 240, 258)
    domain = ["--breaklines", lines, "--boundary", boundary, "--holes", hole, "--crs", "EPSG:5514"]
    serial = run(["tin", points, "-o", os.path.join(tmp, "serial-d.ply"), "--stats"] + domain, False)
    dist = run(["tin", points, "-o", os.path.join(tmp, "dist-d.ply"), "--stats"] + domain, True)
    check(serial.returncode == 0 and dist.returncode == 0,
          f"boundary and hole: exit {serial.returncode} / {dist.returncode}: {serial.stderr} {dist.stderr}")
    if serial.returncode == 0 and dist.returncode == 0:
        with open(os.path.join(tmp, "serial-d.ply"), "rb") as a, open(os.path.join(tmp, "dist-d.ply"), "rb") as b:
            check(a.read() == b.read(), "boundary and hole: the PLY differs from the serial one")
        a, b = json.loads(serial.stdout), json.loads(dist.stdout)
        check(a["removed_triangles"] > 1000 and a["removed_triangles"] == b["removed_triangles"],
              f"boundary and hole: removed {a['removed_triangles']} serial, {b['removed_triangles']} distributed")
    # The tiled TIN (R-P2): one PLY per rank and a manifest, read back by any subcommand as the
    # same TIN: `dtm tin` rewrites it as the serial PLY's bytes, `dtm grid` gives the same cells.
    tiled = run(["tin", points, "-o", os.path.join(tmp, "dist-d.json"), "-q"] + domain, True)
    check(tiled.returncode == 0, f"tiled TIN: exit {tiled.returncode}: {tiled.stderr}")
    if tiled.returncode == 0:
        with open(os.path.join(tmp, "dist-d.json")) as f:
            manifest = json.load(f)
        check(manifest["format"] == "dtm-tin-tiles" and len(manifest["tiles"]) == ranks,
              f"tiled TIN: {len(manifest['tiles'])} tiles on {ranks} ranks")
        back = run(["tin", os.path.join(tmp, "dist-d.json"), "-o", os.path.join(tmp, "back-d.ply"), "-q"], False)
        check(back.returncode == 0, f"dtm tin reading the tiled TIN: {back.stderr}")
        if back.returncode == 0:
            with open(os.path.join(tmp, "serial-d.ply"), "rb") as a, open(os.path.join(tmp, "back-d.ply"), "rb") as b:
                check(a.read() == b.read(), "tiled TIN: put together it differs from the serial PLY")
        grids = [run(["grid", source, "--cell", "10", "-o", os.path.join(tmp, name), "-q"], False)
                 for source, name in ((os.path.join(tmp, "dist-d.json"), "tiles.tif"),
                                      (os.path.join(tmp, "serial-d.ply"), "serial-d.tif"))]
        check(all(g.returncode == 0 for g in grids), f"dtm grid of the tiled TIN: {[g.stderr for g in grids]}")
        if all(g.returncode == 0 for g in grids):
            with open(os.path.join(tmp, "tiles.tif"), "rb") as a, open(os.path.join(tmp, "serial-d.tif"), "rb") as b:
                check(a.read() == b.read(), "dtm grid: the tiled TIN's DEM differs from the PLY's")

    serial = run(["tin", points, "-o", os.path.join(tmp, "serial-m.ply"), "--max-edge", "25", "-q"], False)
    dist = run(["tin", points, "-o", os.path.join(tmp, "dist-m.ply"), "--max-edge", "25", "-q"], True)
    check(serial.returncode == 0 and dist.returncode == 0,
          f"--max-edge: exit {serial.returncode} / {dist.returncode}: {serial.stderr} {dist.stderr}")
    if serial.returncode == 0 and dist.returncode == 0:
        with open(os.path.join(tmp, "serial-m.ply"), "rb") as a, open(os.path.join(tmp, "dist-m.ply"), "rb") as b:
            check(a.read() == b.read(), "--max-edge: the PLY differs from the serial one")

    # The real river survey of ../shared/data (157 3-D breaklines, 16 hole seeds), when present.
    river = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "shared", "data",
                         "points-breaklines-pputils-hurdville")
    if os.path.isdir(river):
        real = [os.path.join(river, "nodes.csv"), "--breaklines", os.path.join(river, "lines3d.csv"),
                "--holes", os.path.join(river, "holes.csv")]
        serial = run(["tin"] + real + ["-o", os.path.join(tmp, "serial-r.ply"), "-q"], False)
        dist = run(["tin"] + real + ["-o", os.path.join(tmp, "dist-r.ply"), "-q"], True)
        check(serial.returncode == 0 and dist.returncode == 0,
              f"river survey: exit {serial.returncode} / {dist.returncode}: {serial.stderr} {dist.stderr}")
        if serial.returncode == 0 and dist.returncode == 0:
            with open(os.path.join(tmp, "serial-r.ply"), "rb") as a, open(os.path.join(tmp, "dist-r.ply"), "rb") as b:
                check(a.read() == b.read(), "river survey: the PLY differs from the serial one")
    else:
        print("river survey: ../shared/data absent, skipped")

    # An OGR point source read by feature ranges (R-D2): a GeoPackage made by ogr2ogr, with a
    # `where` filter too; the same PLY bytes as `dtm tin` on one process.
    plain = os.path.join(tmp, "plain.csv")
    with open(points) as f, open(plain, "w") as out:
        out.write("id,x,y,z\n")
        out.writelines(r for r in f.read().splitlines(True)[2:] if r[:1] in "PD")
    gpkg = os.path.join(tmp, "survey.gpkg")
    made = subprocess.run(["ogr2ogr", "-f", "GPKG", gpkg, plain, "-a_srs", "EPSG:5514",
                           "-oo", "X_POSSIBLE_NAMES=x", "-oo", "Y_POSSIBLE_NAMES=y",
                           "-oo", "Z_POSSIBLE_NAMES=z", "-nln", "survey"], capture_output=True, text=True)
    check(made.returncode == 0, f"ogr2ogr: {made.stderr}")
    if made.returncode == 0:
        for extra, tag in (([], "all"), (["--where", "z > 280"], "where")):
            serial = run(["tin", gpkg, "-o", os.path.join(tmp, f"serial-{tag}.ply"), "-q"] + extra, False)
            dist = run(["tin", gpkg, "-o", os.path.join(tmp, f"dist-{tag}.ply"), "-q"] + extra, True)
            check(serial.returncode == 0 and dist.returncode == 0,
                  f"GeoPackage ({tag}): exit {serial.returncode} / {dist.returncode}: {serial.stderr} {dist.stderr}")
            if serial.returncode == 0 and dist.returncode == 0:
                with open(os.path.join(tmp, f"serial-{tag}.ply"), "rb") as a, \
                        open(os.path.join(tmp, f"dist-{tag}.ply"), "rb") as b:
                    serial_bytes = a.read()
                    check(b"EPSG" in serial_bytes[:4000], f"GeoPackage ({tag}): no CRS in the PLY")
                    check(serial_bytes == b.read(), f"GeoPackage ({tag}): the PLY differs from the serial one")

    stats = run(["tin", points, "-o", os.path.join(tmp, "stats.ply"), "--stats"], True)
    check(stats.returncode == 0, f"--stats: {stats.stderr}")
    if stats.returncode == 0:
        lines = [l for l in stats.stdout.splitlines() if l.strip()]
        check(len(lines) == 1, f"--stats printed once: {stats.stdout!r}")
        report = json.loads(lines[0])
        check(report.get("ranks") == ranks and report.get("points_in") == 20400, f"--stats: {report}")

    bad_lines = os.path.join(tmp, "bad-lines.csv")  # a breakline file with a bad row
    with open(bad_lines, "w") as out:
        out.write("shapeid,x,y,z\n1,-751000,-1051000,250\n1,-750990,oops,251\n")
    serial = run(["tin", points, "--breaklines", bad_lines, "-o", os.path.join(tmp, "x.ply"), "-q"], False)
    dist = run(["tin", points, "--breaklines", bad_lines, "-o", os.path.join(tmp, "y.ply"), "-q"], True)
    message = serial.stderr.strip().splitlines()[-1] if serial.stderr.strip() else ""
    check(serial.returncode == 2 and dist.returncode == 2 and dist.stderr.count(message) == 1,
          f"bad breakline row: exit {serial.returncode} / {dist.returncode}, {message!r} in {dist.stderr!r}")

    bad = os.path.join(tmp, "bad.csv")
    write_points(bad, 20000, bad_line=True)
    serial = run(["tin", bad, "-o", os.path.join(tmp, "x.ply"), "-q"], False)
    dist = run(["tin", bad, "-o", os.path.join(tmp, "y.ply"), "-q"], True)
    check(serial.returncode == 2 and dist.returncode == 2,
          f"bad line: exit {serial.returncode} / {dist.returncode}")
    message = serial.stderr.strip().splitlines()[-1] if serial.stderr.strip() else ""
    check(message.startswith("dtm: ") and dist.stderr.count(message) == 1,
          f"bad line reported once with the serial message {message!r}: {dist.stderr!r}")
    check(not os.path.exists(os.path.join(tmp, "y.ply")), "no output after a bad line")

    if ranks > 1:  # -np 1 is the single-process run, which takes everything
        refused = run(["tin", points, "--flat-areas", points, "-o", os.path.join(tmp, "z.ply")], True)
        check(refused.returncode == 2 and refused.stderr.count("does not take") == 1,
              f"flat areas refused: exit {refused.returncode}: {refused.stderr!r}")
        other = run(["info", points], True)
        check(other.returncode == 2 and "only `dtm tin`, `dtm grid`, `dtm contour` and `dtm build`" in other.stderr,
              f"dtm info under mpirun: {other.stderr!r}")

finish("tin")
