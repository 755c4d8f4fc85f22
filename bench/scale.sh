#!/usr/bin/env bash
# scale.sh: peak memory and time of `dtm tin` on N uniform points (S-JTSK offsets).
#
#   BUILD=build bench/scale.sh [--n N] [--threads T] [--out DIR] [--keep]
#
# Generates the points with bench/make_inputs, runs `dtm tin points.xyz -o tin.ply --stats` under
# /usr/bin/time -v, and prints N, the phases from --stats, the peak resident memory and bytes per
# input point. Needs: cmake --build $BUILD --target dtm make_inputs; /usr/bin/time (Debian: time).
set -euo pipefail

n=20000000
threads=0
out=""
keep=0
while [[ $# -gt 0 ]]; do
    case "$1" in
        --n) n="$2"; shift 2 ;;
        --threads) threads="$2"; shift 2 ;;
        --out) out="$2"; shift 2 ;;
        --keep) keep=1; shift ;;
        -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
        *) echo "scale.sh: unknown option '$1'" >&2; exit 2 ;;
    esac
done
BUILD=${BUILD:-build}
[[ -x /usr/bin/time ]] || { echo "scale.sh: /usr/bin/time missing (apt-get install time)" >&2; exit 1; }
if [[ -z "$out" ]]; then out=$(mktemp -d); fi
mkdir -p "$out"
if [[ ! -s "$out/points.xyz" ]]; then
    "$BUILD/bench/make_inputs" --kind uniform --n "$n" --out "$out" >/dev/null
fi
bytes=$(stat -c %s "$out/points.xyz")
/usr/bin/time -v "$BUILD/tools/dtm" tin "$out/points.xyz" -o "$out/tin.ply" --threads "$threads" \
    --stats 2>"$out/time.txt" >"$out/stats.json"
rss_kb=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$out/time.txt")
wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$out/time.txt")
"$(dirname "$0")/cpu_info.sh"
python3 - "$n" "$bytes" "$rss_kb" "$wall" "$out/stats.json" <<'PY'
import json, sys
n, size, rss_kb, wall, stats = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), sys.argv[4], sys.argv[5]
s = json.load(open(stats))
sec = s["seconds"]
print(f"points {n:,}  input {size/1e6:.0f} MB  triangles {s['triangles']:,}")
print("seconds: " + ", ".join(f"{k} {v:.2f}" for k, v in sec.items()) + f"  (wall {wall})")
print(f"peak RSS {rss_kb/1024:.0f} MiB = {rss_kb*1024/n:.0f} bytes per input point")
PY
if [[ "$keep" != 1 ]]; then rm -f "$out/points.xyz" "$out/tin.ply"; fi
