# SPDX-License-Identifier: MIT
"""What the MPI checks share: the command line (DTM MPIEXEC NP), running dtm with or without
mpirun, and collecting failures. Imported by the *_mpi_check.py scripts beside it."""
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


def finish(job):
    print(job, "on", ranks, "MPI ranks:",
          "all checks passed" if not failures else f"{len(failures)} failed")
    sys.exit(1 if failures else 0)
