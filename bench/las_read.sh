#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# LAS reading speed and memory, in one run:
#
#   bench/las_read.sh [DTM_BINARY] [POINTS] [WORKDIR]
#
# 1. Writes POINTS (default 10^7) random points as LAS 1.4 point format 6 (30-byte records,
#    S-JTSK offsets, classes 2 / 5 / 9) with numpy (bench/las_points.py).
# 2. Times `dtm info` on it (every point kept), with `--classes 2,9`, and with `--classes 2,9
#    --thin 1` (peak RSS from /usr/bin/time), and the reference: numpy reading the same records
#    through a structured dtype and applying scale and offset (np.memmap: the floor of what any
#    reader of the layout costs in memory traffic). Prints seconds, the ratio dtm / numpy and
#    bytes of peak RSS per point read.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
dtm="${1:-$here/../build/tools/dtm}"
points="${2:-10000000}"
work="${3:-$(mktemp -d /tmp/dtm-las-read.XXXXXX)}"
mkdir -p "$work"
las="$work/cloud.las"
[ -f "$las" ] || /usr/bin/python3 "$here/las_points.py" write "$las" "$points"
"$here/cpu_info.sh" 2>/dev/null || true

run() {  # label, command...: prints "label seconds peak_kb"
    local label="$1"
    shift
    local start end
    start=$(date +%s.%N)
    /usr/bin/time -f "%M" -o "$work/time.txt" "$@" > /dev/null
    end=$(date +%s.%N)
    printf '%s %.3f %s\n' "$label" "$(echo "$end - $start" | bc)" "$(cat "$work/time.txt")"
}

ref=$(run numpy /usr/bin/python3 "$here/las_points.py" read "$las")
all=$(run dtm_all "$dtm" info "$las")
cls=$(run dtm_classes "$dtm" info "$las" --classes 2,9)
thin=$(run dtm_thin "$dtm" info "$las" --classes 2,9 --thin 1)
ref_s=$(echo "$ref" | cut -d' ' -f2)
for line in "$all" "$cls" "$thin" "$ref"; do
    read -r label seconds kb <<< "$line"
    printf '%-12s %8.3f s  ratio to numpy %5.2f  peak RSS %7.1f MB = %6.1f bytes/point\n' \
        "$label" "$seconds" "$(echo "$seconds / $ref_s" | bc -l)" "$(echo "$kb / 1024" | bc -l)" \
        "$(echo "$kb * 1024 / $points" | bc -l)"
done
