#!/bin/sh
# The repository describes the design, not how it was worked on: no work-tracker numbers (the
# word for a tracker entry followed by a number, or a hash sign followed by digits), no word for a
# sitting of work, and no "this/last/next …" or numbered work periods. The patterns are spelled
# out below. Every tracked file is searched (git ls-files, or every file under the source tree
# when git is absent) and each hit is printed as file:line.
# Usage: wording_test.sh SOURCE_DIR
set -u
root=$1
cd "$root" || exit 2

# The patterns are put together from pieces so that this file does not match itself.
sitting="ses""sion"
entry="iss""ue"
period="st""op"
patterns="${sitting}
\\b${entry}s? [0-9]+
(^|[^&[:alnum:]_/])#[0-9]+\\b
\\b(this|last|next|that|previous) ${period}\\b
\\b${period} [0-9]+\\b"

if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    files=$(git ls-files)
else
    files=$(find . -path ./build -prune -o -path './build-*' -prune -o -path ./.git -prune -o -type f -print | sed 's|^\./||')
fi

hits=$(printf '%s\n' "$files" | while IFS= read -r f; do
    [ -f "$f" ] || continue
    # binary files (images) are skipped: grep -I
    printf '%s\n' "$patterns" | grep -I -n -i -E -f - -- "$f" 2>/dev/null | sed "s|^|$f:|"
done)

if [ -n "$hits" ]; then
    echo "wording: tracker numbers or work-period words (reword as design statements):"
    printf '%s\n' "$hits"
    exit 1
fi
echo "wording: no tracker numbers or work-period words in $(printf '%s\n' "$files" | wc -l) files"
