# SPDX-License-Identifier: MIT
"""What the MPI checks share: the command line (DTM MPIEXEC NP), running dtm with or without
mpirun, and collecting failures. Imported by the *_mpi_check.py scripts beside it."""
import math
import subprocess
import sys

dtm, mpiexec, ranks = sys.argv[1], sys.argv[2], int(sys.argv[3])
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr)


def run(args, mpi):
    command = ([mpiexec, "-np", str(ranks)] if mpi else []) + [dtm] + args
    return subprocess.run(command, capture_output=True, text=True, timeout=240)


def write_breaklines(path, x0, y0, w, h, through=()):
    """Hard 3-D breaklines (shapeid,x,y,z) over [x0, x0 + w] x [y0, y0 + h]: one along the middle
    (the first seam), lines across every rank crossing it and each other, a diagonal longer than
    any rank's region, short hooks, and a line through the given survey points (x, y, z)."""
    z = lambda x, y: 260 + (x - x0) / w * 20 + (y - y0) / h * 10
    lines = [[(x0 + w * 0.5, y0 + h * (0.02 + 0.96 * k / 40)) for k in range(41)],
             [(x0 + w * (0.01 + 0.98 * k / 60), y0 + h * (0.3 + 0.01 * (k % 3))) for k in range(61)],
             [(x0 + w * (0.01 + 0.98 * k / 60), y0 + h * (0.71 - 0.01 * (k % 2))) for k in range(61)],
             [(x0 + w * 0.03, y0 + h * 0.03), (x0 + w * 0.97, y0 + h * 0.97)],
             [(x0 + w * 0.25, y0 + h * 0.05), (x0 + w * 0.27, y0 + h * 0.95)]]
    for k in range(12):
        x, y = x0 + w * (0.05 + 0.075 * k), y0 + h * (0.1 + 0.06 * k)
        lines.append([(x, y), (x + w * 0.01, y + h * 0.004), (x + w * 0.02, y - h * 0.003)])
    with open(path, "w") as out:
        out.write("shapeid,x,y,z\n")
        for i, line in enumerate(lines):
            for x, y in line:
                out.write(f"{i + 1},{x:.3f},{y:.3f},{z(x, y):.3f}\n")
        for x, y, zz in through:
            out.write(f"{len(lines) + 1},{x},{y},{zz}\n")


def write_ring(path, cx, cy, r, z):
    """A closed 3-D ring (shapeid,x,y,z) of radius about r around (cx, cy) at height z: as a
    boundary it is cut by every seam; as a hole it straddles the first ones."""
    with open(path, "w") as out:
        out.write("shapeid,x,y,z\n")
        for k in range(37):
            a = 2 * math.pi * (k % 36) / 36
            rr = r * (1 + 0.08 * math.sin(5 * (k % 36)))
            out.write(f"1,{cx + rr * math.cos(a):.3f},{cy + rr * math.sin(a):.3f},{z}\n")


def finish(job):
    print(job, "on", ranks, "MPI ranks:",
          "all checks passed" if not failures else f"{len(failures)} failed")
    sys.exit(1 if failures else 0)
