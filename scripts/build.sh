#!/usr/bin/env bash
# Configures (Release, Ninja) and builds dtm incrementally.
# Usage: scripts/build.sh [build-dir] [-DOPTION=VALUE...] [--target NAME...]
#   build-dir  defaults to build/ in the repository root
#   -D...      extra CMake cache options (kept in the cache for later runs)
#   --target   build only these targets (default: everything)
# With CI=true warnings are errors (-DDTM_WERROR=ON). DTM_BUILD_JOBS sets the job count.
set -euo pipefail

repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir="$repo_root/build"
if [[ $# -gt 0 && "$1" != -* ]]; then
    build_dir=$1
    shift
fi

cmake_options=(-G Ninja -DCMAKE_BUILD_TYPE=Release)
if [[ "${CI:-}" == "true" ]]; then
    cmake_options+=(-DDTM_WERROR=ON)
fi
targets=()
while [[ $# -gt 0 ]]; do
    case "$1" in
        -D*) cmake_options+=("$1") ;;
        --target) targets+=(--target "$2"); shift ;;
        *) echo "build.sh: unknown argument '$1'" >&2; exit 2 ;;
    esac
    shift
done

# Configuring an up-to-date tree is quick and rebuilds nothing by itself.
mkdir -p "$build_dir"
if ! cmake -S "$repo_root" -B "$build_dir" "${cmake_options[@]}" > "$build_dir/configure.log" 2>&1; then
    cat "$build_dir/configure.log" >&2
    exit 1
fi
grep -i "warning" -A3 "$build_dir/configure.log" >&2 || true
cmake --build "$build_dir" -j "${DTM_BUILD_JOBS:-$(nproc)}" "${targets[@]}"
