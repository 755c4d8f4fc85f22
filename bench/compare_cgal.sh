#!/usr/bin/env bash
# compare_cgal.sh: time dtm's triangulation against CGAL's on the same inputs, in the same run.
#
#   BUILD=build-bench bench/compare_cgal.sh [--n N] [--out DIR] [--kinds "uniform ..."] [--repeat R]
#                                           [--threads "1 2"]
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
# and the speed-up of the largest count over one thread.
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
        -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
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

for kind in $kinds; do
    dir="$out/$kind"
    echo "== $kind: generating $n points in $dir" >&2
    "$make_inputs" --kind "$kind" --n "$n" --out "$dir"
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
            printf '{"kind":"%s","threads":%s,"dtm":%s}\n' "$kind" "$threads" "$dtm_json" \
                >> "$results"
        done
        echo "== $kind: cgal_reference (run $rep/$repeat)" >&2
        cgal_json="$("$cgal" --kind "$kind" "${cgal_files[@]}" | grep '^{' | tail -n 1)"
        printf '{"kind":"%s","cgal":%s}\n' "$kind" "$cgal_json" >> "$results"
    done
done

python3 - "$results" "$n" "$repeat" <<'PY'
import json, sys
dtm = {}   # (kind, threads) -> [json, seconds], fastest run
cgal = {}  # kind -> [json, seconds], fastest run
kinds = []
for line in open(sys.argv[1]):
    if not line.strip():
        continue
    r = json.loads(line)
    if r["kind"] not in kinds:
        kinds.append(r["kind"])
    if "dtm" in r:
        sec = r["dtm"]["seconds"]
        t = sec["triangulate"] + sec["constrain"]
        key = (r["kind"], r["threads"])
        if key not in dtm or t < dtm[key][1]:
            dtm[key] = [r["dtm"], t]
    else:
        t = r["cgal"]["seconds"]
        if r["kind"] not in cgal or t < cgal[r["kind"]][1]:
            cgal[r["kind"]] = [r["cgal"], t]
threads = sorted({t for (_, t) in dtm})
print(f"n = {sys.argv[2]} points, best of {sys.argv[3]}; times exclude reading and writing; "
      f"CGAL on one thread")
cols = "".join(f" {'dtm ' + str(t) + 't s':>10}" for t in threads)
cols += f" {'cgal s':>9}" + "".join(f" {'cgal/' + str(t) + 't':>9}" for t in threads)
if len(threads) > 1:
    cols += f" {str(threads[-1]) + 't vs 1t':>9}"
head = f"{'kind':<12} {'vertices':>9} {'triangles':>10} {'same':>5}" + cols
print(head)
print("-" * len(head))
for kind in kinds:
    c, t_cgal = cgal[kind]
    d0 = dtm[(kind, threads[0])][0]
    same = all(dtm[(kind, t)][0]["triangles"] == c["faces"] and
               dtm[(kind, t)][0]["vertices"] == c["vertices"] for t in threads)
    line = f"{kind:<12} {d0['vertices']:>9} {d0['triangles']:>10} {'yes' if same else 'NO':>5}"
    line += "".join(f" {dtm[(kind, t)][1]:>10.3f}" for t in threads)
    line += f" {t_cgal:>9.3f}"
    line += "".join(f" {t_cgal / dtm[(kind, t)][1]:>9.2f}" for t in threads)
    if len(threads) > 1:
        line += f" {dtm[(kind, threads[0])][1] / dtm[(kind, threads[-1])][1]:>9.2f}"
    print(line)
PY
echo "raw results: $results" >&2
