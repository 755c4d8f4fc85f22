#!/usr/bin/env bash
# compare_cgal.sh: time dtm's triangulation against CGAL's on the same inputs, in the same run.
#
#   BUILD=build-bench bench/compare_cgal.sh [--n N] [--out DIR] [--kinds "uniform ..."] [--repeat R]
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
set -euo pipefail

n=1000000
out=""
kinds="uniform gaussian clustered breaklines"
repeat=1
while [[ $# -gt 0 ]]; do
    case "$1" in
        --n) n="$2"; shift 2 ;;
        --out) out="$2"; shift 2 ;;
        --kinds) kinds="$2"; shift 2 ;;
        --repeat) repeat="$2"; shift 2 ;;
        -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
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
        echo "== $kind: dtm tin (run $rep/$repeat)" >&2
        dtm_json="$("$dtm" tin "$dir/points.xyz" "${extra[@]}" -o "$dir/out.ply" --threads 1 \
                    --stats | grep '^{' | tail -n 1)"
        echo "== $kind: cgal_reference (run $rep/$repeat)" >&2
        cgal_json="$("$cgal" --kind "$kind" "${cgal_files[@]}" | grep '^{' | tail -n 1)"
        printf '{"kind":"%s","dtm":%s,"cgal":%s}\n' "$kind" "$dtm_json" "$cgal_json" >> "$results"
    done
done

python3 - "$results" "$n" "$repeat" <<'PY'
import json, sys
best = {}  # kind -> [dtm json, dtm seconds, cgal json, cgal seconds], fastest run of each
for line in open(sys.argv[1]):
    if not line.strip():
        continue
    r = json.loads(line)
    sec = r["dtm"]["seconds"]
    t_dtm = sec["triangulate"] + sec["constrain"]
    t_cgal = r["cgal"]["seconds"]
    b = best.setdefault(r["kind"], [r["dtm"], t_dtm, r["cgal"], t_cgal])
    if t_dtm < b[1]:
        b[0], b[1] = r["dtm"], t_dtm
    if t_cgal < b[3]:
        b[2], b[3] = r["cgal"], t_cgal
print(f"n = {sys.argv[2]} points, one thread, best of {sys.argv[3]}; times exclude reading and writing")
head = (f"{'kind':<12} {'dtm vertices':>12} {'cgal vertices':>13} {'dtm triangles':>13} "
        f"{'cgal faces':>10} {'dtm s':>9} {'cgal s':>9} {'cgal/dtm':>9}")
print(head)
print("-" * len(head))
for kind, (d, t_dtm, c, t_cgal) in best.items():
    ratio = t_cgal / t_dtm if t_dtm > 0 else float("inf")
    print(f"{kind:<12} {d['vertices']:>12} {c['vertices']:>13} {d['triangles']:>13} "
          f"{c['faces']:>10} {t_dtm:>9.3f} {t_cgal:>9.3f} {ratio:>9.2f}")
PY
echo "raw results: $results" >&2
