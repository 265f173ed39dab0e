#!/usr/bin/env bash
# Runs clang-tidy-14 (config: .clang-tidy) on every src/ file, using a build's compile database.
#   tests/clang_tidy.sh [BUILD_DIR]     (default build-tidy; configured here if it has no database)
# Exits non-zero on any finding. Needs only the configure step, not a build.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-tidy}"
tidy="$(command -v clang-tidy-14 || command -v clang-tidy)"
if [[ ! -f "$build/compile_commands.json" ]]; then
    cmake -S "$root" -B "$build" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DPERPDOT_BUILD_TESTS=OFF \
        -DPERPDOT_BUILD_DEMOS=OFF -DPERPDOT_BUILD_BENCH=OFF >/dev/null
fi
mapfile -t files < <(cd "$root" && git ls-files 'src/*.cpp' | sed "s|^|$root/|")
jobs="${PERPDOT_JOBS:-2}"
printf '%s\n' "${files[@]}" | xargs -P "$jobs" -n 4 "$tidy" -p "$build" --quiet 2>/dev/null
echo "clang-tidy: ${#files[@]} files clean"
