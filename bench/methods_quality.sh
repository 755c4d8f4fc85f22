#!/usr/bin/env bash
# Quality of greedy and monotone against the CDT (dc) on the lab's distributions, under the bench
# lock. Usage: bench/methods_quality.sh [build-dir] [N] [SEEDS]
set -euo pipefail
build=${1:-build}
exec flock /work/coord/bench.lock "$build/bench/methods_quality" "${2:-5000}" "${3:-3}"
