#!/usr/bin/env bash
# The speed and memory figures of issue 11 (docs/performance.md, "Methods of the literature"):
# every registry method on uniform points at 10^3 ... 10^6, three runs each, one thread,
# quadratic methods capped at an estimated 10 s. Takes the bench lock.
# Usage: bench/methods_compare.sh [build-dir] [output-dir]
set -euo pipefail
build=${1:-build}
out=${2:-bench-methods}
exec flock /work/coord/bench.lock "$build/tools/dtm" methods compare \
    --n 1000,10000,100000,1000000 --dist uniform --repeat 3 --threads 1 --cap-seconds 10 \
    --no-historical -o "$out"
