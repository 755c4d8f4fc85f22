#!/usr/bin/env bash
# compare_outputs.sh: `dtm tin` of two binaries must give the same PLY bytes on every input,
# thread count and tile count (a kernel change that claims "same triangles" is checked here).
#
#   bench/compare_outputs.sh OLD_DTM NEW_DTM [--dir DIR] [--big] [--threads "1 2"] [--tiles "auto 1 7 64"]
#
# Inputs (generated once into DIR, default /tmp/dtm-compare-outputs, with NEW's make_inputs next to
# it, $BUILD/bench/make_inputs): uniform, Gaussian, clustered, 1 m lattice (exactly cocircular
# cells), breakline-heavy (N/2 segments), exact duplicates, circles of cocircular points, a
# collinear chain with a few points off it, crossing collinear lines, small sets of 3 to 1000
# points, and the river survey of ../shared/data (breaklines, boundary, hole seeds) when present.
# --big adds 4 x 10^6 and 10^7 uniform points and 2 x 10^6 with breaklines. Each input runs
# with every thread count and every tile count (auto, 1 = one tile, odd and many tiles) through
# NEW; every output is compared with `cmp` against OLD's output with one thread.
# Prints one line per input and exits 1 on the first difference.
set -euo pipefail

old="${1:?usage: compare_outputs.sh OLD_DTM NEW_DTM [--dir DIR] [--big]}"
new="${2:?usage: compare_outputs.sh OLD_DTM NEW_DTM [--dir DIR] [--big]}"
shift 2
dir=/tmp/dtm-compare-outputs
big=0
thread_counts="1 2"
tile_counts="auto 1 7 64"
while [[ $# -gt 0 ]]; do
    case "$1" in
        --dir) dir="$2"; shift 2 ;;
        --big) big=1; shift ;;
        --threads) thread_counts="$2"; shift 2 ;;
        --tiles) tile_counts="$2"; shift 2 ;;
        *) echo "compare_outputs.sh: unknown option '$1'" >&2; exit 2 ;;
    esac
done
BUILD=${BUILD:-build}
make_inputs="$BUILD/bench/make_inputs"
[[ -x "$make_inputs" ]] || { echo "compare_outputs.sh: $make_inputs missing" >&2; exit 2; }
mkdir -p "$dir"

gen() {  # kind n seed name
    [[ -s "$dir/$4/points.xyz" ]] || "$make_inputs" --kind "$1" --n "$2" --seed "$3" --out "$dir/$4" >/dev/null
}
gen uniform 1000000 1 uniform_1m
gen gaussian 1000000 2 gaussian_1m
gen clustered 1000000 3 clustered_1m
gen grid 1000000 1 grid_1m
gen grid 250000 1 grid_250k
gen breaklines 1000000 1 breaklines_1m
gen breaklines 200000 7 breaklines_200k
if [[ "$big" == 1 ]]; then
    gen uniform 4000000 4 uniform_4m
    gen uniform 10000000 5 uniform_10m
    gen breaklines 2000000 6 breaklines_2m
fi
[[ -s "$dir/small1000.xyz" ]] || python3 - "$dir" <<'PY'
import math, random, sys
d = sys.argv[1]
random.seed(5)
with open(f"{d}/dups.xyz", "w") as f:  # half-metre grid: many exact duplicates
    for i in range(300000):
        x = round(random.uniform(0, 300) * 2) / 2
        y = round(random.uniform(0, 300) * 2) / 2
        f.write(f"{x - 750000} {y - 1050000} {random.uniform(200, 300):.3f}\n")
with open(f"{d}/circles.xyz", "w") as f:  # cocircular groups; the last exactly (Pythagorean)
    for c in range(200):
        cx, cy = random.uniform(0, 1000), random.uniform(0, 1000)
        for k in range(64):
            a = 2 * math.pi * k / 64
            f.write(f"{cx + 10 * math.cos(a)} {cy + 10 * math.sin(a)} {k * 0.1}\n")
    for a, b in [(0, 65), (16, 63), (25, 60), (33, 56), (39, 52)]:
        for sx in (1, -1):
            for sy in (1, -1):
                f.write(f"{2000 + sx * a} {2000 + sy * b} 1\n{2000 + sx * b} {2000 + sy * a} 1\n")
with open(f"{d}/collinear.xyz", "w") as f:  # a collinear chain and five points off it
    for i in range(100000):
        f.write(f"{i * 0.5} {i * 0.25} 1\n")
    for i in range(5):
        f.write(f"{i * 100.0} {i * 50.0 + 1.0} 2\n")
with open(f"{d}/lines.xyz", "w") as f:  # three long collinear lines and random points
    for i in range(50000):
        f.write(f"{i} 0 1\n{i} {i} 1\n0 {i} 1\n")
    for i in range(20000):
        f.write(f"{random.uniform(0, 50000)} {random.uniform(0, 50000)} 3\n")
for n in (3, 4, 5, 7, 10, 17, 33, 100, 1000):
    with open(f"{d}/small{n}.xyz", "w") as f:
        for i in range(n):
            f.write(f"{random.uniform(0, 10)} {random.uniform(0, 10)} {random.uniform(0, 1)}\n")
PY

cases=()  # "name|input args"
for name in uniform_1m gaussian_1m clustered_1m grid_1m grid_250k uniform_4m uniform_10m; do
    [[ -s "$dir/$name/points.xyz" ]] && cases+=("$name|$dir/$name/points.xyz")
done
for name in breaklines_1m breaklines_200k breaklines_2m; do
    [[ -s "$dir/$name/points.xyz" ]] &&
        cases+=("$name|$dir/$name/points.xyz --breaklines $dir/$name/breaklines.csv")
done
for name in dups circles collinear lines small3 small4 small5 small7 small10 small17 small33 small100 small1000; do
    cases+=("$name|$dir/$name.xyz")
done
river="$(dirname "$0")/../../shared/data/points-breaklines-pputils-hurdville"
if [[ -s "$river/nodes.csv" ]]; then
    cases+=("river|$river/nodes.csv --breaklines $river/lines3d.csv --boundary $river/boundary.csv --holes $river/holes.csv")
    cases+=("river_soft|$river/nodes.csv --soft-breaklines $river/lines.csv --boundary $river/boundary.csv --holes $river/holes.csv --snap 0.001")
fi

out="$dir/out"
mkdir -p "$out"
for c in "${cases[@]}"; do
    name="${c%%|*}"
    read -r -a args <<< "${c#*|}"
    "$old" tin "${args[@]}" -o "$out/$name.ref.ply" --threads 1 -q
    runs=0
    for threads in $thread_counts; do
        for tiles in $tile_counts; do
            "$new" tin "${args[@]}" -o "$out/$name.ply" --threads "$threads" --tiles "$tiles" -q
            if ! cmp -s "$out/$name.ref.ply" "$out/$name.ply"; then
                echo "DIFFERENT: $name with --threads $threads --tiles $tiles" >&2
                exit 1
            fi
            runs=$((runs + 1))
        done
    done
    echo "same: $name ($runs runs, $(stat -c %s "$out/$name.ref.ply") bytes)"
    rm -f "$out/$name.ply"
done
echo "all outputs identical"
