#!/usr/bin/env bash
# Writes docs/performance.md and the README's performance table (between its "performance"
# marker comments) from one run, so the two always show the same figures.
#
#   scripts/performance.sh [BUILD_DIR]        (default build/, configured Release if it has no perpdot)
#
# For each of Box2D v3's ten benchmark scenes, R rounds (PERPDOT_PERF_REPEAT, default 3), each round:
#   - `perpdot bench SCENE --engine perpdot --repeat 1`: perpdot alone over the scene's own steps;
#   - Box2D v3's `benchmark -t=1 -w=1 -b=NAME -r=1`, if PERPDOT_BOX2D_V3_BENCHMARK names a
#     benchmark program the user built from Box2D v3's sources (this repository holds no Box2D v3
#     code and no recipe to build it); without it the v3 column says "not measured".
# Rounds alternate the two programs so that both see the same machine load; the figure is the
# median of the rounds. Then `perpdot bench SCENE --steps N --repeat R` times perpdot and Box2D
# 2.4.1 side by side in one process over the scene's first N steps (PERPDOT_PERF_BOX2D_STEPS,
# default 60: Box2D 2.4.1 takes seconds per step in spinner). Last, where the time goes:
# callgrind's instruction counts of World::step's stages over the first PERPDOT_PERF_PROFILE_STEPS
# steps (default 120; PERPDOT_PERF_PROFILE=0 skips it, as does a machine without valgrind).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
repeat="${PERPDOT_PERF_REPEAT:-3}"
box2dSteps="${PERPDOT_PERF_BOX2D_STEPS:-60}"
profileSteps="${PERPDOT_PERF_PROFILE_STEPS:-120}"
profile="${PERPDOT_PERF_PROFILE:-1}"
v3="${PERPDOT_BOX2D_V3_BENCHMARK:-}"
page="$root/docs/performance.md"
readme="$root/README.md"

if [[ ! -x "$build/perpdot" ]]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$build" --target perpdot-cli -j"${PERPDOT_JOBS:-$(nproc)}" >/dev/null
fi
perpdot="$build/perpdot"
if [[ -n "$v3" && ! -x "$v3" ]]; then
    echo "PERPDOT_BOX2D_V3_BENCHMARK=$v3 is not an executable" >&2
    exit 2
fi
command -v valgrind >/dev/null && command -v callgrind_annotate >/dev/null || profile=0

# perpdot scene : Box2D v3 benchmark name
scenes=(large_pyramid:large_pyramid many_pyramids:many_pyramids joint_grid:joint_grid bench_tumbler:tumbler
        smash:smash ragdoll_rain:rain spinner:spinner washer:washer compounds:compounds junkyard:junkyard)

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

median() { sort -g | awk '{ v[NR] = $1 } END { if (NR == 0) print "-"; else if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# The data line of a `perpdot bench` run (the line after the header).
benchLine() { "$perpdot" bench "$@" | sed -n 2p; }

# --- timings -----------------------------------------------------------------------------------
rows="$work/rows"
: >"$rows"
for entry in "${scenes[@]}"; do
    scene="${entry%%:*}" v3name="${entry#*:}"
    : >"$work/p" && : >"$work/v"
    for ((r = 0; r < repeat; ++r)); do
        line="$(benchLine "$scene" --engine perpdot --repeat 1)"
        echo "$line" | awk '{ print $4 }' >>"$work/p"
        echo "$line" >"$work/last"
        if [[ -n "$v3" ]]; then
            # v3 times steps 1 … N-1 of N (its first step is left out) and prints "run k : MS (ms)".
            out="$(cd "$work" && "$v3" -t=1 -w=1 -b="$v3name" -r=1)"
            steps="$(echo "$out" | sed -n 's/^benchmark: .*, steps = \([0-9]*\)$/\1/p')"
            echo "$out" | sed -n 's/^run [0-9]* : \([0-9.e+]*\) (ms)$/\1/p' | awk -v n="$steps" '{ print $1 / (n - 1) }' >>"$work/v"
        fi
    done
    p="$(median <"$work/p")"
    v="$(median <"$work/v")"
    # bodies, steps and the stability figure from perpdot's last round
    read -r _ bodies steps _ <"$work/last"
    stability="$(sed 's/.*  \([a-z ]*\): \([^ ]*\) \/ - \(.*\)$/\1 \2 \3/' "$work/last")"
    side="$(benchLine "$scene" --steps "$box2dSteps" --repeat "$repeat")"
    ratio24="$(echo "$side" | awk '{ print $6 }')"
    printf '%s|%s|%s|%s|%s|%s|%s|%s\n' "$scene" "$v3name" "$bodies" "$steps" "$p" "$v" "$ratio24" "$stability" >>"$rows"
    echo "timed $scene: perpdot $p ms, v3 $v ms, perpdot/2.4.1 $ratio24 ($stability)" >&2
done

# --- where the time goes -----------------------------------------------------------------------
# Inclusive instructions of each stage of World::step (src/core/world/step.cpp), as a share of the step's.
stages=(updatePairs updateContacts integrateVelocities prepareJoints startTreeRefit selectContacts colorJoints
        prepareContactBlocks "SolverStages::run" finalizeBodies updateSleep)
stageNames=("broadphase pairs" "narrowphase" "forces" "joints prepared" "tree re-fit ahead" "contacts selected"
            "joints coloured" "contact blocks prepared" "substeps (solver)" "finalize, continuous" "islands, sleep")
profileRows="$work/profile"
: >"$profileRows"
if [[ "$profile" != 0 ]]; then
    for entry in "${scenes[@]}"; do
        scene="${entry%%:*}"
        valgrind --tool=callgrind --callgrind-out-file="$work/cg.$scene" \
            "$perpdot" bench "$scene" --engine perpdot --repeat 1 --steps "$profileSteps" >/dev/null 2>&1
        callgrind_annotate --inclusive=yes --threshold=100 "$work/cg.$scene" >"$work/cga.$scene" 2>/dev/null
        irOf() {  # the inclusive Ir of the first function whose name matches "$1("
            { grep -E "[ :]${1}\(" "$work/cga.$scene" || true; } | head -1 | awk '{ gsub(",", "", $1); print $1 + 0 }'
        }
        total="$(irOf "World::step")"
        line="$scene"
        for stage in "${stages[@]}"; do
            ir="$(irOf "$stage")"
            line="$line|$(awk -v a="${ir:-0}" -v t="${total:-0}" 'BEGIN { if (t > 0 && a > 0) printf "%.0f", 100 * a / t; else printf "-" }')"
        done
        echo "$line" >>"$profileRows"
        echo "profiled $scene" >&2
    done
    # A stage met in no scene was renamed or inlined: its column would say nothing.
    for i in "${!stages[@]}"; do
        if ! cut -d'|' -f$((i + 2)) "$profileRows" | grep -qv '^-$'; then
            echo "performance.sh: no scene's profile has ${stages[$i]}(): update the stages list" >&2
            exit 1
        fi
    done
fi

# --- the page ----------------------------------------------------------------------------------
date="$(date -u +%F)"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
cpu="$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)"
cores="$(nproc)"
compiler="$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null | head -1)"
compilerVersion="$("${compiler:-c++}" --version 2>/dev/null | head -1)"
command="scripts/performance.sh"
[[ -n "$v3" ]] && command="PERPDOT_BOX2D_V3_BENCHMARK=/path/to/box2d-v3/build/bin/benchmark $command"

# The table both files show: one row per scene.
table() {
    echo "| scene (v3 name) | bodies | steps | perpdot ms/step | Box2D v3 ms/step | perpdot / v3 | perpdot / 2.4.1 (first $box2dSteps steps) |"
    echo "|---|---|---|---|---|---|---|"
    while IFS='|' read -r scene v3name bodies steps p v ratio24 _; do
        local ratio="not measured" vText="not measured"
        if [[ "$v" != "-" ]]; then
            vText="$(printf '%.2f' "$v")"
            ratio="$(awk -v a="$p" -v b="$v" 'BEGIN { r = a / b; printf (r > 1 ? "**%.2fx** (behind)" : "%.2fx"), r }')"
        fi
        printf '| `%s` (%s) | %s | %s | %.2f | %s | %s | %s |\n' "$scene" "$v3name" "$bodies" "$steps" "$p" "$vText" "$ratio" "$ratio24"
    done <"$rows"
}
machine="$date, $cpu ($cores cores), $compilerVersion, one thread, perpdot at $commit"

{
    cat <<EOF
# Performance

<!-- Written by scripts/performance.sh; edit the script, not this page. -->

perpdot against Box2D v3 (its own benchmark program) and Box2D 2.4.1 on Box2D v3's ten benchmark
scenes, one thread. Measured $machine:

\`\`\`sh
$command
\`\`\`

$(table)

ms/step is wall-clock time per step, the median of $repeat rounds. A ratio below 1x means perpdot
takes less time; **bold** marks the scenes where perpdot is behind Box2D v3.

## Method

- **The scenes** are perpdot's built-in scenes of the same names (\`perpdot list\`), built as
  Box2D v3's benchmark (\`shared/benchmarks.c\`) builds its scenes: the same bodies, shapes, sizes,
  densities, frictions and step counts, dt = 1/60, 4 substeps, sleeping where v3 allows it.
  The differences are listed below.
- **perpdot** is timed by \`perpdot bench SCENE --engine perpdot --repeat 1\` over the scene's whole
  step count (world creation excluded), the Release build of this repository.
- **Box2D v3** is timed by its own \`benchmark -t=1 -w=1 -b=NAME -r=1\`, built by the user from
  Box2D v3's sources (Release, \`BOX2D_VALIDATE=OFF\` as a shipped game builds it, its default SIMD: SSE2 on x86-64) and passed in
  \`PERPDOT_BOX2D_V3_BENCHMARK\`; this repository holds no Box2D v3 code. It times steps 2 … N of N;
  the script divides by N − 1. Without that program the column says "not measured".
- The two alternate round by round, so that both see the same load on a shared machine; each
  figure is the median of the rounds.
- **Box2D 2.4.1** (Debian's libbox2d, 8 velocity and 3 position iterations) is timed beside perpdot
  in one process by \`perpdot bench SCENE --steps $box2dSteps --repeat $repeat\`, which alternates
  the engines and prints the ratio; only the first $box2dSteps steps, because Box2D 2.4.1 takes
  seconds per step once spinner's bar turns fast.
- Each run also prints a stability figure (docs/crosscheck.md, "Stability figures"), so a fast
  run is also checked to be a sound one; perpdot's, over the whole scene:

| scene | perpdot's stability figure at the end |
|---|---|
$(while IFS='|' read -r scene _ _ _ _ _ _ stability; do printf '| `%s` | %s |\n' "$scene" "$stability"; done <"$rows")

### Where the scenes differ from Box2D v3's

- \`bench_tumbler\` is v3's "tumbler" and \`ragdoll_rain\` its "rain"; rain's ragdolls are perpdot's
  figure (\`ragdoll\`), wider than v3's human, five to a group 1 m apart, without v3's joint
  friction and springs.
- \`spinner\` stirs 6,000 shapes of 0.4 m on v3's 0.5 m grid (v3: 3,038 capsules, circles and
  squares of 0.7 m, which overlap at the start) and keeps the bar's column free.
- \`washer\`: v3 asks for hit events on every box (\`enableHitEvents\`); a perpdot scene file has no
  per-shape hit-event switch, so perpdot's boxes report none (hit events cost v3 a little).
- \`junkyard\`: v3 moves the pusher with \`b2Body_SetTargetTransform\` each step; perpdot's scene
  script gives it the velocity that reaches the same pose in one step (\`SceneEditor::setVelocity\`).
- \`compounds\`: v3 puts the catching segment on the bin's body; perpdot puts it on a static body of
  its own (the same physics).

## Where the time goes

EOF
    if [[ -s "$profileRows" ]]; then
        cat <<EOF
Share of \`World::step\`'s instructions spent in each stage (callgrind, inclusive, one worker, over
each scene's first $profileSteps steps: \`valgrind --tool=callgrind build/perpdot bench SCENE
--engine perpdot --repeat 1 --steps $profileSteps\`). Instructions are not time (cache misses
cost time without instructions), but they show which stage a scene spends its step in.

EOF
        header="| scene |" rule="|---|"
        for name in "${stageNames[@]}"; do header="$header $name |" rule="$rule---|"; done
        echo "$header"
        echo "$rule"
        while IFS='|' read -r scene rest; do echo "| \`$scene\` | ${rest//|/ % | } % |"; done <"$profileRows"
        echo
    else
        echo "(not profiled in this run: valgrind missing or PERPDOT_PERF_PROFILE=0)"
        echo
    fi
    cat <<'EOF'
What the stages are: docs/architecture.md, "One step".

## Where perpdot is behind

EOF
    behind="$(while IFS='|' read -r scene v3name _ _ p v _; do
        [[ "$v" == "-" ]] && continue
        awk -v s="$scene" -v n="$v3name" -v a="$p" -v b="$v" 'BEGIN { if (a > b) printf "- `%s` (%s): perpdot takes %.2f ms a step, Box2D v3 %.2f ms (%.2fx).\n", s, n, a, b, a / b }'
    done <"$rows")"
    if [[ -z "$v3" ]]; then
        echo "Box2D v3 was not measured in this run, so this page cannot say."
    elif [[ -n "$behind" ]]; then
        echo "On this machine, one thread, perpdot takes longer than Box2D v3 on:"
        echo
        echo "$behind"
    else
        echo "On this machine, one thread, perpdot takes less time than Box2D v3 on every scene."
    fi
    cat <<'EOF'

Beyond the table: Box2D v3 keeps each constraint's graph colour while it lives, where perpdot
colours every step, serially; joint rows go four wide in perpdot, also on AVX2 CPUs where its
contact rows go eight wide; and perpdot's threads have been measured on two cores only.
EOF
} >"$page"

# --- the README's table ------------------------------------------------------------------------
begin="<!-- performance: begin (scripts/performance.sh writes this table) -->"
end="<!-- performance: end -->"
if ! grep -qF "$begin" "$readme" || ! grep -qF "$end" "$readme"; then
    echo "README.md lacks the performance markers" >&2
    exit 1
fi
{
    echo "$begin"
    echo
    echo "Measured $machine (\`$command\`; method and where the time goes: [docs/performance.md](docs/performance.md)):"
    echo
    table
    echo
    echo "$end"
} >"$work/table"
awk -v b="$begin" -v e="$end" -v f="$work/table" '
    $0 == b { while ((getline line < f) > 0) print line; skip = 1; next }
    $0 == e { skip = 0; next }
    !skip' "$readme" >"$work/readme"
cp "$work/readme" "$readme"
echo "wrote $page and the table in $readme" >&2
