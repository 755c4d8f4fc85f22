#!/usr/bin/env bash
# cpu_info.sh: one line naming the CPU and its caches, printed by every benchmark script next to
# its figures (docs/performance.md asks for them with every figure).
#
#   bench/cpu_info.sh    ->  cpu: AMD EPYC (family 26 model 2), 2 CPUs; L1d 48K, L2 1M, L3 508M; load 0.52
#
# Takes the model, family and CPU count from lscpu and the cache sizes from lscpu when it lists
# them, else from getconf (CPUID, also inside virtual machines that hide /sys/.../cache), and adds
# the load average so that a figure taken on a busy machine says so.
set -euo pipefail

field() { lscpu 2>/dev/null | awk -F': *' -v k="$1" '$1 == k {print $2; exit}'; }
size() {  # bytes -> 48K / 1M
    local b="$1"
    if [[ -z "$b" || "$b" == 0 ]]; then echo "?"; return; fi
    if (( b >= 1048576 )); then echo "$((b / 1048576))M"; else echo "$((b / 1024))K"; fi
}
cache() {  # lscpu name, getconf name
    local v
    v="$(field "$1")"
    if [[ -n "$v" ]]; then echo "$v"; return; fi  # e.g. "4 MiB (2 instances)"
    size "$(getconf "$2" 2>/dev/null || echo 0)"
}
model="$(field 'Model name')"
family="$(field 'CPU family')"
number="$(field 'Model')"
cpus="$(field 'CPU(s)')"
echo "cpu: ${model:-unknown} (family ${family:-?} model ${number:-?}), ${cpus:-?} CPUs;" \
     "L1d $(cache 'L1d cache' LEVEL1_DCACHE_SIZE), L2 $(cache 'L2 cache' LEVEL2_CACHE_SIZE)," \
     "L3 $(cache 'L3 cache' LEVEL3_CACHE_SIZE); load $(cut -d' ' -f1 /proc/loadavg)"
