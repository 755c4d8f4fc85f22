#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Ctrl-C and crashes under mpirun (issue 18: cancellation and atomic outputs as on one
machine): SIGINT to `mpirun -np P dtm tin|build`, and one rank of `dtm tin` killed (SIGKILL), at
several moments of the run. Whenever it lands, the output holds either the previous run's
complete file (or folder) or the complete new one, never a mix or a partial file, and an
interrupted run exits non-zero. Usage: interrupt_mpi_check.py DTM MPIEXEC NP"""
import json
import os
import random
import signal
import subprocess
import tempfile
import time

from mpi_checks import check, dtm, finish, mpiexec, ranks


def write_points(path, n, seed):
    rng = random.Random(seed)
    with open(path, "w") as out:
        out.write("x,y,z\n")
        for _ in range(n):
            out.write(f"{-750000 - rng.random() * 3000:.3f},{-1050000 - rng.random() * 3000:.3f},"
                      f"{250 + rng.random() * 40:.3f}\n")


def folder_state(path):
    """The names and bytes of every file in a folder (hidden staging folders next to it apart)."""
    state = {}
    for name in sorted(os.listdir(path)):
        full = os.path.join(path, name)
        if os.path.isfile(full):
            with open(full, "rb") as f:
                state[name] = f.read()
    return state


def rank_processes(job):
    """The dtm processes mpirun started (its children running dtm)."""
    found = subprocess.run(["pgrep", "-P", str(job.pid)], capture_output=True, text=True)
    pids = []
    for pid in found.stdout.split():
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                if os.path.basename(f.read().split(b"\0")[0]) == b"dtm":
                    pids.append(int(pid))
        except OSError:
            pass
    return pids


def interrupted(args, delay, kill_rank=False):
    """Runs mpirun dtm ARGS and after DELAY seconds (if still running) sends SIGINT to mpirun, or
    with KILL_RANK kills one rank at once (SIGKILL: a crash), which ends the job."""
    job = subprocess.Popen([mpiexec, "-np", str(ranks), dtm] + args,
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    time.sleep(delay)
    sent = job.poll() is None
    if sent and kill_rank:
        victims = rank_processes(job)
        sent = bool(victims)
        for pid in victims[-1:]:
            os.kill(pid, signal.SIGKILL)
    elif sent:
        job.send_signal(signal.SIGINT)
    try:
        _, err = job.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        job.kill()
        _, err = job.communicate()
        check(False, f"mpirun did not end after SIGINT ({args})")
    return sent, job.returncode, err


with tempfile.TemporaryDirectory() as tmp:
    old_points, new_points = os.path.join(tmp, "old.csv"), os.path.join(tmp, "new.csv")
    write_points(old_points, 2000, 1)
    write_points(new_points, 800000, 2)
    # The builds take a quarter of the points: a build does more per point than a TIN, and the
    # interrupts below still land in its middle.
    build_points = os.path.join(tmp, "build.csv")
    write_points(build_points, 200000, 3)
    for name, points in (("old", old_points), ("new", new_points)):
        done = subprocess.run([dtm, "tin", points, "--crs", "EPSG:5514", "-o",
                               os.path.join(tmp, f"{name}.ply"), "-q"], capture_output=True)
        check(done.returncode == 0, f"serial dtm tin {name}: {done.stderr}")
    with open(os.path.join(tmp, "old.ply"), "rb") as f:
        old_ply = f.read()
    with open(os.path.join(tmp, "new.ply"), "rb") as f:
        new_ply = f.read()
    out = os.path.join(tmp, "out.ply")
    # SIGINT to mpirun (it ends the ranks itself, so where its ending lands varies), then a rank
    # killed outright at several moments, which must land before the commit at least once.
    stopped = {False: 0, True: 0}
    for kill_rank, delay in ((False, 0.3), (False, 1.4), (True, 0.5), (True, 0.9), (True, 1.3),
                             (True, 1.8)):
        how = "a rank killed" if kill_rank else "SIGINT"
        with open(out, "wb") as f:
            f.write(old_ply)
        sent, code, err = interrupted(["tin", new_points, "--crs", "EPSG:5514", "-o", out, "-q"],
                                      delay, kill_rank)
        with open(out, "rb") as f:
            now = f.read()
        check(now in (old_ply, new_ply), f"tin, {how} after {delay} s: tin.ply is neither the old "
              f"nor the new file ({len(now)} bytes)")
        if sent and now == old_ply:
            stopped[kill_rank] += 1
            check(code != 0, f"tin, {how} after {delay} s: an interrupted run exited 0")
    print(f"tin: SIGINT stopped {stopped[False]} of 2 runs, a killed rank {stopped[True]} of 4 "
          "before the commit (the old file kept)")
    check(stopped[True] > 0, "tin: no rank was killed before the run ended (the input is too small)")

    # dtm build: the folder holds the old products or the new ones, whole (the report's
    # timings aside, a complete new build equals an uninterrupted one).
    def build(points, folder):
        return subprocess.run([mpiexec, "-np", str(ranks), dtm, "build", points, "--crs",
                               "EPSG:5514", "-o", folder, "-q"], capture_output=True, text=True)

    def complete_new(state, new):
        """The folder holds the whole new build: its files, the same TIN, DEM and contour VRTs
        and the same report of the points."""
        if set(state) != set(new) or "report.json" not in state:
            return False
        if any(state[n] != new[n] for n in ("tin.ply", "dem.vrt", "contours.vrt") if n in new):
            return False
        return json.loads(state["report.json"])["points"] == json.loads(new["report.json"])["points"]

    folder, reference = os.path.join(tmp, "site"), os.path.join(tmp, "reference")
    first, ref = build(old_points, folder), build(build_points, reference)
    check(first.returncode == 0 and ref.returncode == 0,
          f"mpirun dtm build: {first.stderr} {ref.stderr}")
    if first.returncode == 0 and ref.returncode == 0:
        new_state = folder_state(reference)
        kept = 0
        for delay in (0.6, 1.2, 2.0):
            before = folder_state(folder)
            sent, code, err = interrupted(["build", build_points, "--crs", "EPSG:5514", "-o", folder,
                                           "-q"], delay)
            state = folder_state(folder)
            untouched = state == before
            check(untouched or complete_new(state, new_state),
                  f"build, SIGINT after {delay} s: neither the old nor the new products: {sorted(state)}")
            if sent and untouched and not complete_new(before, new_state):
                kept += 1
                check(code != 0, f"build, SIGINT after {delay} s: an interrupted run exited 0")
        print(f"build: SIGINT stopped {kept} of 3 runs before the switch (the old products kept)")

finish("interrupt")
