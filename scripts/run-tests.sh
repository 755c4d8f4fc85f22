#!/usr/bin/env bash
# Quick-start command 2 (and what CI runs): installs what is missing, builds everything with
# warnings as errors, and runs the test suite.
# Usage: scripts/run-tests.sh [build-dir]
#   DTM_SLOW_TESTS=1  also run the tests labelled `slow`
#   DTM_SHARED_DATA_DIR is a CMake cache option: tests needing the real data skip when it is absent.
set -euo pipefail

repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$repo_root"
build_dir=${1:-"$repo_root/build"}

scripts/install-deps.sh
scripts/build.sh "$build_dir" -DDTM_WERROR=ON

ctest_options=(--test-dir "$build_dir" --output-on-failure -j2)
if [[ "${DTM_SLOW_TESTS:-0}" != "1" ]]; then
    ctest_options+=(-LE slow)
fi
echo "run-tests: ctest ${ctest_options[*]}"
ctest "${ctest_options[@]}"

# ---- LATER STAGES: add further stages below this line ----------------------------------------
# (sanitizer build: scripts/build.sh build-asan -DDTM_SANITIZE=ON ... + ctest; fuzzers: -DDTM_FUZZ=ON)
# ----------------------------------------------------------------------------------------------

echo "run-tests: all stages passed"
