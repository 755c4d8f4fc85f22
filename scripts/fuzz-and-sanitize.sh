#!/usr/bin/env bash
# Hardening run: (a) builds the libFuzzer targets (csv, hpgl, ply, mesh_2dm, landxml, jvf, dxf,
# las, sniff) with clang (-DDTM_FUZZ=ON: fuzzer coverage +
# ASan + UBSan) and runs each for a bounded time from seeds in tests/data (and the shared real
# data when present); (b) builds the test suite with -DDTM_SANITIZE=ON in its own build directory
# and runs ctest (without the `slow` tests and the `crash` kill tests, which test process
# semantics, not memory safety, and run in the normal build). Exit status is non-zero if a fuzzer finds a crash or a test fails.
#
# Usage: scripts/fuzz-and-sanitize.sh [--fuzz-only|--sanitize-only]
# Environment: FUZZ_SECONDS (default 60 per fuzzer), READER_FUZZ_SECONDS (landxml, jvf, dxf, las,
#              sniff; default 10, CI time being short), JOBS (default 2),
#              BUILD_ROOT (default <repo>), DTM_SHARED_DATA_DIR (default <repo>/../shared/data).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_root="${BUILD_ROOT:-$repo}"
fuzz_seconds="${FUZZ_SECONDS:-60}"
reader_fuzz_seconds="${READER_FUZZ_SECONDS:-10}"
jobs="${JOBS:-2}"
shared="${DTM_SHARED_DATA_DIR:-$repo/../shared/data}"
mode="${1:-all}"

run_fuzzers() {
    local build="$build_root/build-fuzz"
    cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DDTM_FUZZ=ON -DDTM_WITH_MPI=OFF \
        -DDTM_BUILD_TESTS=OFF -DDTM_BUILD_BENCH=OFF -DDTM_BUILD_SAMPLES=OFF >/dev/null || return 1
    cmake --build "$build" --target dtm_fuzzers -j "$jobs" || return 1
    local status=0
    for fuzzer in "$build"/fuzz/*_fuzz; do
        [ -x "$fuzzer" ] || continue
        local name corpus seconds="$fuzz_seconds"
        name="$(basename "$fuzzer" _fuzz)"
        corpus="$build/corpus/$name"
        mkdir -p "$corpus" "$build/artifacts"
        # Seeds: this format's fixtures, plus the real files of the same kind when available.
        case "$name" in
            csv)
                cp -f "$repo"/tests/data/readers/* "$corpus"/ 2>/dev/null || true
                for f in "$shared"/points-pdal-text-variants/*.{txt,xyz,pts} \
                         "$shared"/points-breaklines-pputils-hurdville/holes.csv; do
                    [ -f "$f" ] && cp -f "$f" "$corpus"/
                done ;;
            hpgl)
                cp -f "$repo"/tests/data/hpgl/* "$corpus"/ 2>/dev/null || true
                for d in hpgl-hp2xx hpgl-autocad-hpgl2 hpgl-instrument-plots; do
                    [ -d "$shared/$d" ] && find "$shared/$d" -type f -size -200k \
                        ! -name SOURCE.txt -exec cp -f {} "$corpus"/ \;
                done ;;
            ply)
                cp -f "$repo"/tests/data/tin/*.ply "$corpus"/ 2>/dev/null || true ;;
            mesh_2dm)
                cp -f "$repo"/tests/data/tin/*.2dm "$corpus"/ 2>/dev/null || true ;;
            landxml)
                cp -f "$repo"/tests/data/landxml/* "$corpus"/ 2>/dev/null || true
                [ -d "$shared/landxml-surfaces" ] && find "$shared/landxml-surfaces" -type f \
                    -name '*.xml' -size -200k -exec cp -f {} "$corpus"/ \; ;;
            sniff)
                cp -f "$repo"/fuzz/seeds/*/* "$repo"/tests/data/readers/* "$repo"/tests/data/hpgl/* \
                    "$corpus"/ 2>/dev/null || true ;;
        esac
        case "$name" in
            landxml|jvf|dxf|las|sniff)
                seconds="$reader_fuzz_seconds"
                cp -f "$repo"/fuzz/seeds/"$name"/* "$corpus"/ 2>/dev/null || true ;;
        esac
        echo "== fuzzing $name for ${seconds}s ($(ls "$corpus" | wc -l) seeds)"
        if ! "$fuzzer" "$corpus" -max_total_time="$seconds" -max_len=65536 -timeout=20 \
                -rss_limit_mb=2048 -artifact_prefix="$build/artifacts/${name}-" \
                -print_final_stats=1 2>"$build/$name.log"; then
            echo "!! $name found a problem: see $build/$name.log and $build/artifacts/"
            tail -n 30 "$build/$name.log"
            status=1
        else
            grep -E "stat::number_of_executed_units|cov:" "$build/$name.log" | tail -n 2 || true
        fi
    done
    return $status
}

run_sanitized_tests() {
    local build="$build_root/build-sanitize"
    # -O1 -g1 (line tables): enough for the sanitizers' stack traces, and the build (the longest
    # step of CI) compiles much faster than with -O2 -g. The tests and the CLI compile as unity
    # batches (DTM_UNITY_TESTS: 19 -> about 12 minutes on 2 cores).
    cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDTM_SANITIZE=ON \
        -DDTM_UNITY_TESTS=ON \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
        -DDTM_BUILD_BENCH=OFF -DDTM_BUILD_SAMPLES=OFF -DDTM_WITH_MPI=OFF >/dev/null || return 1
    cmake --build "$build" -j "$jobs" || return 1
    ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS="suppressions=$repo/tests/support/lsan.supp:print_suppressions=0" UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        ctest --test-dir "$build" --output-on-failure -j "$jobs" -LE "slow|crash"
}

start=$(date +%s)
status=0
if [ "$mode" != "--sanitize-only" ]; then run_fuzzers || status=1; fi
if [ "$mode" != "--fuzz-only" ]; then run_sanitized_tests || status=1; fi
echo "fuzz-and-sanitize: $(( $(date +%s) - start )) s, status $status"
exit $status
