#!/usr/bin/env bash
# The source rules the compiler cannot check (run by scripts/run-tests.sh and by ctest as
# `source_rules`):
#   1. no command-line vocabulary in the library: no "--flag" in any string literal under
#      libdtm/ (the library names options as `field`; tools/dtm maps fields to flags);
#   2. io does not run the triangulator: nothing under libdtm/*/io includes algo/triangulate.hpp;
#   3. no `x = {};` under libdtm/src/methods: for a vector it keeps the capacity, so it frees
#      nothing (detail::free_storage(x) does);
#   4. every tracked C++ file is formatted with the repository's .clang-format (clang-format
#      --dry-run -Werror; skipped outside a git checkout or without clang-format).
# Usage: scripts/check-sources.sh [--no-format]
set -euo pipefail

repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$repo_root"
status=0

python3 - <<'PY' || status=1
import pathlib, re, sys

literal = re.compile(r'"((?:[^"\\\n]|\\.)*)"')
flag = re.compile(r'(?:^|[^A-Za-z0-9_-])--[A-Za-z]')
bad = []
for path in sorted(pathlib.Path("libdtm").rglob("*")):
    if path.suffix not in (".cpp", ".hpp", ".h"):
        continue
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        code = line.split("//", 1)[0] if not line.lstrip().startswith("//") else ""
        # a // inside a literal (a URL) would cut the line short: scan the whole line when the
        # cut leaves an odd number of quotes
        if code.count('"') % 2:
            code = line
        for m in literal.finditer(code):
            if flag.search(m.group(1)):
                bad.append(f"{path}:{number}: command-line flag in a library string: {m.group(0)}")
io = [p for p in pathlib.Path("libdtm").rglob("*") if "/io/" in p.as_posix() and p.suffix in (".cpp", ".hpp")]
for path in io:
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if re.match(r'\s*#\s*include\s*[<"]dtm/algo/triangulate\.hpp[">]', line):
            bad.append(f"{path}:{number}: io includes the triangulator (algo/triangulate.hpp)")
for path in sorted(pathlib.Path("libdtm/src/methods").rglob("*")):
    if path.suffix not in (".cpp", ".hpp"):
        continue
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if re.match(r'\s*[A-Za-z_][A-Za-z0-9_.]*\s*=\s*\{\s*\};', line):
            bad.append(f"{path}:{number}: '= {{}};' keeps a vector's memory: use free_storage()")
for b in bad:
    print(f"check-sources: {b}", file=sys.stderr)
sys.exit(1 if bad else 0)
PY

if [[ "${1:-}" != "--no-format" ]]; then
    clang_format=$(command -v clang-format-14 || command -v clang-format || true)
    if [[ -z "$clang_format" ]]; then
        echo "check-sources: clang-format not found: formatting not checked" >&2
    elif ! git -C "$repo_root" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
        echo "check-sources: not a git checkout: formatting not checked" >&2
    else
        git ls-files -z -- '*.cpp' '*.hpp' '*.h' | xargs -0 -r "$clang_format" --dry-run -Werror \
            || { echo "check-sources: run clang-format -i on the files above" >&2; status=1; }
    fi
fi
[[ $status -eq 0 ]] && echo "check-sources: library strings, io includes and formatting are fine"
exit $status
