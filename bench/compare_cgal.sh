#!/usr/bin/env bash
# compare_cgal.sh: time dtm's triangulation against CGAL's on the same inputs, in the same run.
#
#   BUILD=build-bench bench/compare_cgal.sh [--n "N ..."] [--out DIR] [--kinds "uniform ..."]
#                                           [--repeat R] [--threads "1 2"]
#
# Builds nothing: expects $BUILD (default: build-bench, else ./build) to hold tools/dtm/dtm,
# bench/make_inputs and bench/cgal_reference (cmake --build $BUILD --target dtm make_inputs
# cgal_reference). For each kind it generates N points (plus ~N/2 breakline segments for
# "breaklines"), runs
#   dtm tin points.xyz [--breaklines breaklines.csv] -o out.ply --threads 1 --stats
# and cgal_reference on the same files, and prints both triangulation times and the ratio
# cgal/dtm (> 1 means dtm is faster). dtm's time is seconds.triangulate + seconds.constrain
# (reading and writing excluded); CGAL's is its insert calls (Delaunay_triangulation_2, or
# Constrained_Delaunay_triangulation_2 with Exact_predicates_tag for breaklines), one thread.
# Default kinds: uniform gaussian clustered breaklines; "grid" (1 m integer lattice, exactly
# cocircular cells) can be added with --kinds. --repeat R runs both engines R times,
# alternating, and reports the fastest run of each (useful on a shared, noisy machine).
# --threads "1 2" (default "1") runs dtm with each thread count in the same run (CGAL has no
# parallel 2-D triangulation: it always runs on one thread) and prints cgal/dtm for each count
# and the speed-up of the largest count over one thread. --n takes several sizes ("1000000
# 2000000 4000000 10000000"): all are measured in the same run, and a last table gives, per kind
# and engine, how the time grows per doubling of the size between consecutive sizes
# ((t2 / t1) ^ (1 / log2(n2 / n1))). The first line names the CPU and its caches (cpu_info.sh).
#
# The issue 17 run (Delaunay and CDT, four sizes, one and two threads):
#   BUILD=build bench/compare_cgal.sh --n "1000000 2000000 4000000 10000000" \
#       --kinds "uniform breaklines" --threads "1 2" --repeat 2
set -euo pipefail

n=1000000
out=""
kinds="uniform gaussian clustered breaklines"
repeat=1
thread_counts="1"
while [[ $# -gt 0 ]]; do
    case "$1" in
        --n) n="$2"; shift 2 ;;
        --out) out="$2"; shift 2 ;;
        --kinds) kinds="$2"; shift 2 ;;
        --repeat) repeat="$2"; shift 2 ;;
        --threads) thread_counts="$2"; shift 2 ;;
        -h|--help) sed -n '2,30p' "$0"; exit 0 ;;
        *) echo "compare_cgal.sh: unknown option '$1'" >&2; exit 2 ;;
    esac
done

if [[ -z "${BUILD:-}" ]]; then
    if [[ -d build-bench ]]; then BUILD=build-bench; else BUILD=build; fi
fi
dtm="$BUILD/tools/dtm"
make_inputs="$BUILD/bench/make_inputs"
cgal="$BUILD/bench/cgal_reference"
for exe in "$dtm" "$make_inputs" "$cgal"; do
    if [[ ! -f "$exe" || ! -x "$exe" ]]; then
        echo "compare_cgal.sh: $exe not found; build it first:" >&2
        echo "  cmake --build $BUILD --target dtm make_inputs cgal_reference" >&2
        exit 2
    fi
done
if [[ -z "$out" ]]; then
    out="$(mktemp -d -t dtm-compare-cgal.XXXXXX)"
fi
mkdir -p "$out"
results="$out/results.jsonl"
: > "$results"
cpu="$("$(dirname "$0")/cpu_info.sh")"

for size in $n; do
for kind in $kinds; do
    dir="$out/$kind-$size"
    echo "== $kind: generating $size points in $dir" >&2
    [[ -s "$dir/points.xyz" ]] || "$make_inputs" --kind "$kind" --n "$size" --out "$dir"
    extra=()
    if [[ -f "$dir/breaklines.csv" ]]; then
        extra=(--breaklines "$dir/breaklines.csv")
        cgal_files=("$dir/points.xyz" "$dir/breaklines.csv")
    else
        cgal_files=("$dir/points.xyz")
    fi
    for ((rep = 1; rep <= repeat; ++rep)); do
        for threads in $thread_counts; do
            echo "== $kind: dtm tin --threads $threads (run $rep/$repeat)" >&2
            dtm_json="$("$dtm" tin "$dir/points.xyz" "${extra[@]}" -o "$dir/out.ply" \
                        --threads "$threads" --stats --quiet | grep '^{' | tail -n 1)"
            printf '{"kind":"%s","n":%s,"threads":%s,"dtm":%s}\n' "$kind" "$size" "$threads" \
                "$dtm_json" >> "$results"
        done
        echo "== $kind: cgal_reference (run $rep/$repeat)" >&2
        cgal_json="$("$cgal" --kind "$kind" "${cgal_files[@]}" | grep '^{' | tail -n 1)"
        printf '{"kind":"%s","n":%s,"cgal":%s}\n' "$kind" "$size" "$cgal_json" >> "$results"
    done
    rm -f "$dir/out.ply"
done
done

python3 - "$results" "$repeat" "$cpu" <<'PY'
import json, math, sys
dtm = {}   # (kind, n, threads) -> [json, seconds], fastest run
cgal = {}  # (kind, n) -> [json, seconds], fastest run
kinds, sizes = [], []
for line in open(sys.argv[1]):
    if not line.strip():
        continue
    r = json.loads(line)
    if r["kind"] not in kinds:
        kinds.append(r["kind"])
    if r["n"] not in sizes:
        sizes.append(r["n"])
    if "dtm" in r:
        sec = r["dtm"]["seconds"]
        t = sec["triangulate"] + sec["constrain"]
        key = (r["kind"], r["n"], r["threads"])
        if key not in dtm or t < dtm[key][1]:
            dtm[key] = [r["dtm"], t]
    else:
        t = r["cgal"]["seconds"]
        key = (r["kind"], r["n"])
        if key not in cgal or t < cgal[key][1]:
            cgal[key] = [r["cgal"], t]
threads = sorted({t for (_, _, t) in dtm})
print(sys.argv[3])
print(f"best of {sys.argv[2]}; times exclude reading and writing; CGAL on one thread")
cols = "".join(f" {'dtm ' + str(t) + 't s':>10}" for t in threads)
cols += f" {'cgal s':>9}" + "".join(f" {'cgal/' + str(t) + 't':>9}" for t in threads)
if len(threads) > 1:
    cols += f" {str(threads[-1]) + 't vs 1t':>9}"
head = f"{'kind':<12} {'points':>9} {'vertices':>9} {'triangles':>10} {'same':>5}" + cols
print(head)
print("-" * len(head))
for kind in kinds:
    for n in sizes:
        if (kind, n) not in cgal:
            continue
        c, t_cgal = cgal[(kind, n)]
        d0 = dtm[(kind, n, threads[0])][0]
        same = all(dtm[(kind, n, t)][0]["triangles"] == c["faces"] and
                   dtm[(kind, n, t)][0]["vertices"] == c["vertices"] for t in threads)
        line = (f"{kind:<12} {n:>9} {d0['vertices']:>9} {d0['triangles']:>10} "
                f"{'yes' if same else 'NO':>5}")
        line += "".join(f" {dtm[(kind, n, t)][1]:>10.3f}" for t in threads)
        line += f" {t_cgal:>9.3f}"
        line += "".join(f" {t_cgal / dtm[(kind, n, t)][1]:>9.2f}" for t in threads)
        if len(threads) > 1:
            line += f" {dtm[(kind, n, threads[0])][1] / dtm[(kind, n, threads[-1])][1]:>9.2f}"
        print(line)
if len(sizes) > 1:
    print()
    print("time growth per doubling of the size, (t2 / t1) ^ (1 / log2(n2 / n1)):")
    for kind in kinds:
        ns = [n for n in sorted(sizes) if (kind, n) in cgal]
        for a, b in zip(ns, ns[1:]):
            e = 1.0 / math.log2(b / a)
            parts = [f"dtm {t}t {(dtm[(kind, b, t)][1] / dtm[(kind, a, t)][1]) ** e:.2f}"
                     for t in threads]
            parts.append(f"cgal {(cgal[(kind, b)][1] / cgal[(kind, a)][1]) ** e:.2f}")
            print(f"  {kind:<12} {a:>9} -> {b:>9}: " + ", ".join(parts))
PY
echo "raw results: $results" >&2
