#!/usr/bin/env bash
# The distributed kernel (issue 18) measured on this machine: in-process ranks 1-64 (bytes per
# phase, bands, time against the serial kernel in the same run), then mpirun -np 1 2 4 (time
# against the serial kernel, slots checked), and every rank's peak memory at 8*10^6 points on
# 1, 2 and 4 ranks. Usage: BUILD=build bench/dist_simulation.sh [N...]
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD:-$repo/build}
sizes=("$@")
[[ ${#sizes[@]} -gt 0 ]] || sizes=(100000 1000000)
"$repo/bench/cpu_info.sh" || true
"$build/bench/dist_simulation" "${sizes[@]}"
if command -v mpirun >/dev/null; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
        OMPI_MCA_btl=self,vader OMPI_MCA_oob_tcp_if_include=lo
    echo
    echo "| points | ranks | serial kernel | partition + kernel (slowest rank) | ratio | check |"
    echo "|---|---|---|---|---|---|"
    for np in 1 2 4; do
        mpirun -np "$np" "$build/bench/dist_simulation" "${sizes[@]}"
    done
    # Peak memory per rank (no serial reference in these runs), DIST_MEMORY_POINTS points.
    echo
    echo "| points | ranks | partition + kernel | memory |"
    echo "|---|---|---|---|"
    for np in 1 2 4; do
        DTM_SIM_MEMORY=1 mpirun -x DTM_SIM_MEMORY -np "$np" "$build/bench/dist_simulation" \
            "${DIST_MEMORY_POINTS:-8000000}"
    done
fi
