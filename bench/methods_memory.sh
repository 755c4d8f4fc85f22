#!/usr/bin/env bash
# The memory figures of issue 11 (docs/performance.md, "Memory of the methods"): the lab's peak
# resident-set rise per point of the eleven Delaunay and Voronoi methods at 10^5 and 10^6
# uniform points, one thread. With a second dtm binary (e.g. main's) both are measured, and
# the speed is compared by callgrind's instruction count of each method call, one thread, on
# the same 20 000 points (the load of the shared machine does not change it; times would).
# Memory does not depend on the load either. Takes the bench lock.
# Usage: bench/methods_memory.sh [build-dir] [baseline-dtm] [output-dir]
set -euo pipefail
build=${1:-build}
baseline=${2:-}
out=${3:-bench-methods-memory}
methods=dc,randomized-dag,lifting,uniform-grid,incremental-walk,topological-dc,dewall
methods+=,incremental-kirkpatrick,voronoi-incremental,voronoi-topological,voronoi-dc
mkdir -p "$out"
run() {  # run BINARY SIZES DIR
    nice -n 10 "$1" methods compare --methods "$methods" --n "$2" --dist uniform --repeat 1 \
        --threads 1 --no-historical -q -o "$3" > /dev/null
}
exec 9> /work/coord/bench.lock
flock 9
run "$build/tools/dtm" 100000,1000000 "$out/memory"
dirs=("$out/memory")
if [[ -n "$baseline" ]]; then
    run "$baseline" 100000,1000000 "$out/memory-baseline"
    dirs+=("$out/memory-baseline")
    awk 'BEGIN { srand(7); print "x,y,z"; for (i = 0; i < 20000; i++)
        printf "%.6f,%.6f,%.3f\n", 1000 * rand(), 1000 * rand(), 50 * rand() }' > "$out/points.csv"
    for m in ${methods//,/ }; do
        for which in baseline new; do
            bin=$baseline
            [[ $which == new ]] && bin=$build/tools/dtm
            nice -n 10 valgrind --tool=callgrind --callgrind-out-file=/dev/null \
                --toggle-collect='dtm::methods::run_*' "$bin" methods run "$m" "$out/points.csv" \
                -o "$out/callgrind.ply" -q --threads 1 2>&1 > /dev/null |
                sed -n 's/.*Collected : \([0-9]*\).*/\1/p' > "$out/instructions-$which-$m"
        done
    done
fi
/usr/bin/python3 - "$out" "${dirs[@]}" <<'PY'
import csv, glob, os, sys
out, dirs = sys.argv[1], sys.argv[2:]
def rows(d):
    return {(r["method"], int(r["n"])): r for r in csv.DictReader(open(os.path.join(d, "results.csv")))}
new = rows(dirs[0])
base = rows(dirs[1]) if len(dirs) > 1 else {}
def instructions(which, m):
    try:
        return int(open(os.path.join(out, f"instructions-{which}-{m}")).read())
    except (OSError, ValueError):
        return None
print("| method | N | B/pt" + (" baseline | B/pt | instructions / baseline's (20 000 points)" if base else "") + " |")
print("|---|---:|---:" + ("|---:|---:" if base else "") + "|")
for (m, n), r in new.items():
    line = f"| {m} | {n} | "
    if base:
        b = base.get((m, n))
        line += (f"{float(b['rss_bytes_per_point']):.0f}" if b else "") + " | "
    line += f"{float(r['rss_bytes_per_point']):.0f}"
    if base:
        a, b = instructions("new", m), instructions("baseline", m)
        line += " | " + (f"{a / b:.3f}" if a and b and n == 100000 else "")
    print(line + " |")
PY
