#!/usr/bin/env bash
# Quick-start command 2 (and what CI runs): installs what is missing, builds everything with
# warnings as errors, and runs the test suite.
# Usage: scripts/run-tests.sh [build-dir]
#   DTM_SLOW_TESTS=1  also run the tests labelled `slow`
#   DTM_HARDENING=1   also run the fuzzers and the sanitizer test build (always on when CI=true)
#   DTM_SHARED_DATA_DIR is a CMake cache option: tests needing the real data skip when it is absent.
set -euo pipefail

repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$repo_root"
build_dir=${1:-"$repo_root/build"}

scripts/install-deps.sh
# Source rules: no flags in library strings, no triangulator in io, clang-format clean.
scripts/check-sources.sh
# The tests and the CLI compile as unity batches (about 3.5 minutes less on 2 cores).
scripts/build.sh "$build_dir" -DDTM_WERROR=ON -DDTM_UNITY_TESTS=ON

ctest_options=(--test-dir "$build_dir" --output-on-failure -j2)
if [[ "${DTM_SLOW_TESTS:-0}" != "1" ]]; then
    ctest_options+=(-LE slow)
fi
echo "run-tests: ctest ${ctest_options[*]}"
ctest "${ctest_options[@]}"

# ---- Hardening: libFuzzer targets for the text and HPGL parsers (bounded time) and the whole test
# suite under AddressSanitizer + UndefinedBehaviorSanitizer, in their own build directories.
# On in CI (CI=true) or with DTM_HARDENING=1; DTM_HARDENING=0 skips it. About 28 minutes on
# 2 cores from scratch (fuzz build and runs 8, sanitizer build 12, its ctest 8).
if [[ "${DTM_HARDENING:-${CI:-0}}" == "1" || "${DTM_HARDENING:-${CI:-0}}" == "true" ]]; then
    echo "run-tests: hardening (fuzzers ${FUZZ_SECONDS:-30} s each, sanitizer test build)"
    FUZZ_SECONDS=${FUZZ_SECONDS:-30} BUILD_ROOT="$(dirname "$build_dir")" scripts/fuzz-and-sanitize.sh
fi
# ----------------------------------------------------------------------------------------------

echo "run-tests: all stages passed"
