#!/usr/bin/python3
"""Crash safety of `dtm build` (issue 17.4), checked by killing the real process.

An OUTDIR holding the products of an OLD build (fewer points) is rebuilt with the NEW inputs under
strace, which sends SIGKILL at the N-th rename / renameat / renameat2 / link of the build, for every
N until the build completes, and at a spread of its write(2) calls. After every kill OUTDIR must
hold exactly the OLD set of file digests or exactly the NEW set (plus a user file that must survive
both). The same with renameat2 refused (EINVAL) so that the documented rename pair runs: there a
kill between the two renames may leave no OUTDIR but the complete old folder under ".out.old",
which the next run renames back (checked). Then a full disk (write -> ENOSPC) and a file-size
limit (prlimit --fsize): exit 1, a clear message, OUTDIR untouched, no temporary left behind.
About 60 builds: under a minute of CPU.

Usage: build_kill_check.py DTM SAMPLE_DIR [--faults-only]   (exit 0 pass, 1 fail, 77 skip: ptrace not allowed)
"""
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

DTM = sys.argv[1]
SAMPLE = Path(sys.argv[2])
ENV = dict(os.environ, OGR_CURRENT_DATE="2000-01-01T00:00:00Z",  # GeoPackage timestamps
           SOURCE_DATE_EPOCH="946684800")  # cairo's PDF creation date (map.pdf)
USER_FILE = "notes-of-the-user.txt"
failures = []


def build_command(points, out):
    return [DTM, "build", str(points), "--breaklines", str(SAMPLE / "breaklines.shp"),
            "--boundary", str(SAMPLE / "boundary.shp"), "--holes", str(SAMPLE / "building.shp"),
            "--crs", "EPSG:5514", "--skip-bad-lines", "-q", "-o", str(out)]


def digest(folder):
    """File name -> sha256; report.json without its timings (they differ from run to run)."""
    result = {}
    for path in sorted(folder.rglob("*")):
        if not path.is_file():
            continue
        data = path.read_bytes()
        if path.suffix == ".pdf":  # cairo stamps the time (it ignores SOURCE_DATE_EPOCH here)
            data = re.sub(rb"/CreationDate \(D:[0-9Z+\-']*\)", b"", data)
        if path.name == "report.json":
            try:
                report = json.loads(data)
            except ValueError:
                result[path.name] = "partial report.json"
                continue
            report.pop("timings_seconds", None)
            data = json.dumps(report, sort_keys=True).encode()
        result[str(path.relative_to(folder))] = hashlib.sha256(data).hexdigest()
    return result


def run(command, **kw):
    return subprocess.run(command, env=ENV, capture_output=True, text=True, **kw)


def state(out, old, new):
    if out.is_dir():
        d = digest(out)
        if d == old:
            return "old"
        if d == new:
            return "new"
        mixed = sorted(k for k in set(d) | set(new) if d.get(k) != old.get(k) and d.get(k) != new.get(k))
        return "MIXED " + ",".join(mixed)
    backup = out.parent / ("." + out.name + ".old")
    if backup.is_dir() and digest(backup) == old:
        return "no-outdir+old-backup"
    return "LOST"


def reset(out, reference):
    shutil.rmtree(out.parent)
    out.parent.mkdir()
    shutil.copytree(reference, out)


def kill_runs(work, old_ref, new_ref, new_points, syscall, numbers, extra=()):
    """Kill the build at the N-th call of `syscall` for N in numbers (stop at the first complete run)."""
    out = work / "out"
    tally = {}
    for n in numbers:
        reset(out, old_ref)
        command = ["strace", "-f", "-o", "/dev/null", *extra,
                   "-e", f"inject={syscall}:signal=KILL:when={n}"] + build_command(new_points, out)
        r = run(command)
        s = state(out, digest(old_ref), digest(new_ref))
        if s == "no-outdir+old-backup":
            # The documented recovery rule, as a reader applies it (io::recover_directory, which
            # the next run calls first; tests/unit/io/atomic_file_test.cpp checks that).
            (out.parent / ("." + out.name + ".old")).rename(out)
            s = "old (recovered)" if state(out, digest(old_ref), digest(new_ref)) == "old" else "RECOVERY FAILED"
        key = s if r.returncode != 0 else "completed:" + s
        tally[key] = tally.get(key, 0) + 1
        if s not in ("old", "new", "old (recovered)") or (r.returncode == 0 and s != "new"):
            failures.append(f"{syscall} #{n} {' '.join(extra)}: exit {r.returncode}, OUTDIR {s}")
        if r.returncode == 0:
            break
    else:
        if numbers and numbers[-1] >= 400:
            failures.append(f"{syscall}: never completed")
    print(f"kill at {syscall} {' '.join(extra)}: {tally}", flush=True)
    return tally


def count_calls(work, old_ref, new_points, syscall):
    out = work / "out"
    reset(out, old_ref)
    log = work.parent / "count.log"
    run(["strace", "-f", "-o", str(log), "-e", f"trace={syscall}"] + build_command(new_points, out))
    return sum(1 for line in log.read_text().splitlines() if f" {syscall}(" in line or line.startswith(syscall + "("))


def fault_runs(work, old_ref, new_points, label, prefix):
    out = work / "out"
    reset(out, old_ref)
    r = run(prefix + build_command(new_points, out))
    leftovers = [p.name for p in out.parent.iterdir() if p.name != "out"]
    ok = r.returncode == 1 and digest(out) == digest(old_ref) and not leftovers
    print(f"{label}: exit {r.returncode}, OUTDIR {'untouched' if digest(out) == digest(old_ref) else 'CHANGED'}, "
          f"left behind {leftovers}, message: {r.stderr.strip()[-200:]}", flush=True)
    if not ok or not r.stderr.strip().splitlines()[-1:] or not r.stderr.strip().splitlines()[-1].startswith("dtm: "):
        failures.append(f"{label}: exit {r.returncode}, stderr {r.stderr.strip()[:300]}")


def main():
    if shutil.which("strace") is None:
        print("strace is not installed (scripts/install-deps.sh installs it)")
        return 1
    probe = subprocess.run(["strace", "-o", "/dev/null", "true"], capture_output=True, text=True)
    if probe.returncode != 0:
        print("SKIP: ptrace is not allowed here: " + probe.stderr.strip())
        return 77
    with tempfile.TemporaryDirectory(prefix="dtm-kill-") as tmp:
        tmp = Path(tmp)
        lines = (SAMPLE / "points.csv").read_text().splitlines(keepends=True)
        old_points = tmp / "old.csv"
        old_points.write_text("".join(lines[:-400]))
        new_points = SAMPLE / "points.csv"
        old_ref, new_ref = tmp / "ref" / "old", tmp / "ref" / "new"
        for points, ref in ((old_points, old_ref), (new_points, new_ref)):
            r = run(build_command(points, ref))
            if r.returncode != 0:
                print("reference build failed: " + r.stderr)
                return 1
            (ref / USER_FILE).write_text("kept across builds\n")
        if digest(old_ref) == digest(new_ref) or any(digest(old_ref)[k] == v for k, v in digest(new_ref).items() if k != USER_FILE and k != "dtm.qgs"):
            print("the old and the new products must differ file by file")
            return 1
        again = tmp / "ref" / "again"
        shutil.copytree(new_ref, again)
        if run(build_command(new_points, again)).returncode != 0 or digest(again) != digest(new_ref):
            print("two builds of the same inputs differ: the digests cannot tell old from new")
            return 1
        work = tmp / "work"
        work.mkdir()
        (work / "out").mkdir()
        total = 0
        kills = "--faults-only" not in sys.argv
        for syscall in ("rename", "renameat", "renameat2", "linkat", "link") if kills else ():
            total += sum(kill_runs(work, old_ref, new_ref, new_points, syscall, range(1, 401)).values())
        writes = count_calls(work, old_ref, new_points, "write")
        picks = [] if not kills else sorted(set([1 + i * max(1, writes // 12) for i in range(12)] + list(range(max(1, writes - 6), writes + 2))))
        total += sum(kill_runs(work, old_ref, new_ref, new_points, "write", picks).values())
        print(f"write calls in a build: {writes}", flush=True)
        refuse = ["-e", "inject=renameat2:error=EINVAL"]
        for syscall in ("rename", "renameat") if kills else ():
            total += sum(kill_runs(work, old_ref, new_ref, new_points, syscall, range(1, 401), refuse).values())
        print(f"kills and runs: {total}", flush=True)
        # A later run cleans what the kills left behind.
        r = run(build_command(new_points, work / "out"))
        leftovers = [p.name for p in work.iterdir() if p.name != "out"]
        if r.returncode != 0 or leftovers:
            failures.append(f"clean run after the kills: exit {r.returncode}, left behind {leftovers}")
        # A full disk: one write(2) fails with ENOSPC (a later one would also fail the message).
        for n in sorted(set([1 + i * max(1, writes // 6) for i in range(6)] + list(range(max(1, writes - 28), writes + 1, 4)))):
            fault_runs(work, old_ref, new_points, f"full disk at write #{n}",
                       ["strace", "-f", "-o", "/dev/null", "-e", f"inject=write:error=ENOSPC:when={n}"])
        # File-size limits that stop the first product (tin.ply) and a later one (tin.2dm).
        for limit in (1000, 190000):
            fault_runs(work, old_ref, new_points, f"prlimit --fsize={limit}", ["prlimit", f"--fsize={limit}"])
    for failure in failures:
        print("FAIL: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
