#!/usr/bin/env bash
# The aarch64 promise (docs/toolchain.md "aarch64"): the same scene gives the
# same state hash on 64-bit ARM as here. Builds snow_state_hash and
# snow_libm_hash natively and cross-built for aarch64 (Debian's
# g++-aarch64-linux-gnu, linked statically), runs the aarch64 ones under
# qemu-aarch64, and compares every output with the native one computed in
# this run: the two pinned scenes and the stormy yard (gusts, a wind field,
# wind transport, bodies, a cover, a tilted sky camera) on 1 and 2 threads,
# the stormy yard with every integrator, and the libm results.
# Usage: scripts/check_aarch64.sh [HOST_BUILD_DIR]
#   HOST_BUILD_DIR: a native build to reuse (CI passes build); by default
#   build-host, configured here with only the simulation and the tools.
#   The cross build goes to build-aarch64. Only the two tools are built.
# Environment: JOBS (default: number of cores).
# Exit status: 0 all equal (or skipped: no cross compiler or no qemu;
# `scripts/deps.sh g++-aarch64-linux-gnu qemu-user` installs them), 1 a
# mismatch or a failed run.
set -euo pipefail
cd "$(dirname "$0")/.."

HOST_BUILD=${1:-build-host}
CROSS_BUILD=build-aarch64
JOBS=${JOBS:-$(nproc)}
START=$(date +%s)

missing=()
command -v aarch64-linux-gnu-g++ >/dev/null 2>&1 || missing+=(g++-aarch64-linux-gnu)
command -v qemu-aarch64 >/dev/null 2>&1 || missing+=(qemu-user)
if [ ${#missing[@]} -gt 0 ]; then
    echo "[aarch64] SKIPPED: no aarch64-linux-gnu-g++ or qemu-aarch64 on PATH;" \
         "install them with: scripts/deps.sh ${missing[*]}"
    exit 0
fi

tools=(snow_state_hash snow_libm_hash)
only_tools=(-G Ninja -DCMAKE_BUILD_TYPE=Release -DSNOW_BUILD_RENDER=OFF -DSNOW_BUILD_GAME=OFF
            -DSNOW_BUILD_TESTS=OFF -DSNOW_BUILD_BENCH=OFF -DSNOW_BUILD_TOOLS=ON)
if [ ! -f "$HOST_BUILD/CMakeCache.txt" ]; then
    cmake -S . -B "$HOST_BUILD" "${only_tools[@]}" >/dev/null
fi
echo "[aarch64] native build ($HOST_BUILD)"
cmake --build "$HOST_BUILD" -j "$JOBS" --target "${tools[@]}"
echo "[aarch64] cross build ($CROSS_BUILD)"
cmake -S . -B "$CROSS_BUILD" "${only_tools[@]}" \
      -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/aarch64-linux-gnu.cmake" >/dev/null
cmake --build "$CROSS_BUILD" -j "$JOBS" --target "${tools[@]}"

# Each case: snow_state_hash's arguments. The pinned scenes as their tests
# run them (Determinism: busy_yard, 300 ticks; WindField: field_yard, 200).
cases=("busy_yard 300 1" "busy_yard 300 2" "field_yard 200 1" "field_yard 200 2"
       "stormy_yard 300 1" "stormy_yard 300 2")
for integrator in semi_implicit exponential rk4 auto; do
    cases+=("stormy_yard 200 2 $integrator")
done

out=$CROSS_BUILD/check
rm -rf "$out"
mkdir -p "$out/native" "$out/aarch64"
native=$HOST_BUILD/tools
arm=(qemu-aarch64 "$CROSS_BUILD/tools")

# run FILE COMMAND...: in the background, at most JOBS at a time; the output
# goes to FILE.out, the exit status to FILE.rc.
run() {
    local file=$1
    shift
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do
        wait -n || true
    done
    ( set +e; "$@" >"$file.out" 2>&1; echo $? >"$file.rc" ) &
}

echo "[aarch64] running ${#cases[@]} scenes and the libm probe, native and under qemu-aarch64"
run "$out/aarch64/libm" "${arm[0]}" "${arm[1]}/snow_libm_hash"
run "$out/native/libm" "$native/snow_libm_hash"
for i in "${!cases[@]}"; do
    read -r -a args <<<"${cases[$i]}"
    run "$out/aarch64/$i" "${arm[0]}" "${arm[1]}/snow_state_hash" "${args[@]}"
    run "$out/native/$i" "$native/snow_state_hash" "${args[@]}"
done
wait

failed=0
# same NAME LABEL: compares the native and aarch64 runs of NAME.
same() {
    local n=$out/native/$1 a=$out/aarch64/$1
    if [ "$(cat "$n.rc")" != 0 ] || [ "$(cat "$a.rc")" != 0 ]; then
        echo "FAILED    $2: exit $(cat "$n.rc") native, $(cat "$a.rc") aarch64"
        cat "$n.out" "$a.out"
        failed=1
    elif ! cmp -s "$n.out" "$a.out"; then
        echo "MISMATCH  $2 (native <, aarch64 >):"
        diff "$n.out" "$a.out" || true
        failed=1
    else
        echo "same      $2: $(head -n 1 "$n.out")"
    fi
}
for i in "${!cases[@]}"; do
    same "$i" "snow_state_hash ${cases[$i]}"
done
same libm "snow_libm_hash (first line shown; all $(wc -l <"$out/native/libm.out") compared)"

echo "[aarch64] $(uname -m) and aarch64 (qemu) $([ $failed = 0 ] && echo agree || echo DISAGREE)" \
     "($(( $(date +%s) - START )) s)"
exit $failed
