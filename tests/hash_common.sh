# Sourced by the determinism checks, tests/cross_compiler_hash.sh (compilers, SIMD, threads) and
# tests/cross_arch_hash.sh (x86-64, ARM64, 32-bit x86): the scenes both run, and how a state_hash
# and a snapshot's round trip are compared. A build is a name and a command that runs its perpdot
# ("build/perpdot", "qemu-aarch64 build-arch-aarch64/perpdot"; split at spaces).
#
# `scenes` exercise stacking, friction, restitution, rotation, many contacts and joints (scalar and
# 4-wide: revolute in joint_grid, weld, prismatic and wheel in joint_rack, distance in
# distance_net, motor in motor_swarm). SCENE:N runs N steps (perpdot run --steps N) instead of the
# scene's own, to keep the benchmark scenes short. `snapshotScenes` (SCENE:N:K) are saved at step K
# and continued to step N.
scenes=(single_box vertical_stack pyramid bouncing_balls friction_ramp rolling_disc spinning_box
        off_center_push card_house newtons_cradle tumbler rain dominoes chain suspension_bridge ragdoll
        joint_grid:200 joint_rack:150 distance_net:150
        motor_swarm:150)
snapshotScenes=(pyramid:200:100 vertical_stack:500:400 ragdoll:120:60 car:150:75 bullet_wall:20:2
                sensor_zone:160:80 tumbler:120:60 joint_grid:60:30)

hashOf() {  # perpdot-command scene[:steps] [perpdot run flags...]
    local steps=()
    [[ "$2" == *:* ]] && steps=(--steps "${2#*:}")
    $1 run "${2%%:*}" "${steps[@]}" "${@:3}" | sed -n 's/.*state_hash=\([0-9a-f]*\).*/\1/p'
}

# compareSnapshots NAME=COMMAND...: for each of `snapshotScenes`, every build saves the run at step
# K (`perpdot run --save-at`), the files must be the same bytes, and every build loads every
# build's file (`--load`) and runs on to step N: every state hash must equal the first build's
# uninterrupted run. Prints one line a scene; sets failed=1 on a difference.
compareSnapshots() {
    local names=() commands=() build entry scene steps saveAt i j hashes dir
    for build in "$@"; do names+=("${build%%=*}"); commands+=("${build#*=}"); done
    dir="$(mktemp -d)"
    for entry in "${snapshotScenes[@]}"; do
        IFS=: read -r scene steps saveAt <<<"$entry"
        for i in "${!names[@]}"; do
            ${commands[$i]} run "$scene" --steps "$steps" --save-at "$saveAt" "$dir/$scene.${names[$i]}" >/dev/null
        done
        hashes=("uninterrupted=$(hashOf "${commands[0]}" "$scene:$steps")")
        for i in "${!names[@]}"; do
            cmp -s "$dir/$scene.${names[0]}" "$dir/$scene.${names[$i]}" ||
                { echo "DIFFERENT $scene snapshot bytes ${names[0]} vs ${names[$i]}"; failed=1; }
            for j in "${!names[@]}"; do
                hashes+=("${names[$j]}<-${names[$i]}=$(${commands[$j]} run "$scene" --steps "$steps" \
                    --load "$dir/$scene.${names[$i]}" | sed -n 's/.*state_hash=\([0-9a-f]*\).*/\1/p')")
            done
        done
        if [[ "$(printf '%s\n' "${hashes[@]}" | sed 's/.*=//' | sort -u | wc -l)" != 1 || "${hashes[0]}" == *= ]]; then
            echo "DIFFERENT $scene restored: ${hashes[*]}"
            failed=1
        else
            echo "same      $scene saved at $saveAt, loaded by every build: ${hashes[0]#*=}"
        fi
    done
    rm -rf "$dir"
}
