#!/usr/bin/env bash
# The test design of the pseudo-triangulation thesis (001 chapter 4) on this machine, under the
# bench lock: uniform, gauss, cluster, arc; N = 1000 ... 75000 (arc to 30000); 3 sets x 3 runs;
# MinLength, MaxMinAngle, MinMaxAngle with incremental / post-processing swap and fast /
# brute-force flip; the angle tables on 10000 points. Writes the markdown tables to stdout.
# Usage: bench/pseudo_thesis.sh [build-dir] [pseudo_thesis options, e.g. --sets 1 --runs 1]
set -euo pipefail
build=${1:-build}
shift || true
exec flock /work/coord/bench.lock "$build/bench/pseudo_thesis" "$@"
