#!/usr/bin/env bash
# Runs the libFuzzer targets of fuzz/ (docs/reliability.md "Fuzzing"):
# fuzz_gltf (.gltf text), fuzz_glb (.glb bytes), fuzz_snapshot (snapshot
# bytes) and fuzz_cli (snow_run's and snow_game's command lines), each for
# SECONDS on its seed corpus and dictionary.
# Usage: scripts/fuzz.sh [--build DIR] [--seconds S] [--timeout T] [TARGET...]
#   --build DIR   a build configured with -DSNOW_FUZZ=ON (Clang); by default
#                 build-fuzz, configured here at -O1 with ASan+UBSan (what the
#                 campaigns in docs/reliability.md ran). CI passes build-asan.
#   --seconds S   time per target (default 60)
#   --timeout T   a unit slower than T seconds is a finding (default 2: the
#                 bound docs/reliability.md promises under ASan)
#   --no-build    run DIR's targets as they are (a campaign beside a rebuild)
#   --keep-going  a campaign: run on past findings (libFuzzer's fork mode),
#                 saving each; the exit status still says whether any was found
# Seeds: fuzz/corpus/TARGET, the shipped scenes (gltf, glb) and, for
# fuzz_snapshot, a snapshot written by the current build (so its format is
# always current). New units go to DIR/fuzz/corpus/TARGET; a crash, leak,
# timeout or out-of-memory unit to DIR/fuzz/findings/TARGET, and the script
# exits 1 naming it (units over 1 s are kept there too, as slow-unit-*, but
# only reported). Environment: JOBS (default: number of cores).
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD=build-fuzz
SECONDS_EACH=60
TIMEOUT=2
KEEP_GOING=()
BUILD_FIRST=1
TARGETS=()
while [ $# -gt 0 ]; do
    case "$1" in
    --build) BUILD=$2; shift 2 ;;
    --seconds) SECONDS_EACH=$2; shift 2 ;;
    --timeout) TIMEOUT=$2; shift 2 ;;
    --no-build) BUILD_FIRST=0; shift ;;
    --keep-going) KEEP_GOING=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1); shift ;;
    fuzz_gltf | fuzz_glb | fuzz_snapshot | fuzz_cli) TARGETS+=("$1"); shift ;;
    *) echo "fuzz.sh: unknown argument '$1' (see the comment at the top)" >&2; exit 2 ;;
    esac
done
[ ${#TARGETS[@]} -gt 0 ] || TARGETS=(fuzz_gltf fuzz_glb fuzz_snapshot fuzz_cli)
JOBS=${JOBS:-$(nproc)}

if [ "$BUILD_FIRST" = 1 ] && [ ! -f "$BUILD/CMakeCache.txt" ]; then
    CC=clang CXX=clang++ cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g" \
        -DSNOW_FUZZ=ON -DSNOW_BUILD_TESTS=OFF -DSNOW_BUILD_BENCH=OFF -DSNOW_BUILD_TOOLS=OFF \
        -DSNOW_NATIVE=OFF >/dev/null
fi
grep -q '^SNOW_FUZZ:BOOL=ON' "$BUILD/CMakeCache.txt" ||
    { echo "fuzz.sh: $BUILD is not configured with -DSNOW_FUZZ=ON" >&2; exit 2; }
[ "$BUILD_FIRST" = 0 ] || cmake --build "$BUILD" -j "$JOBS" --target "${TARGETS[@]}"

export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1
status=0
for t in "${TARGETS[@]}"; do
    name=${t#fuzz_}
    work="$BUILD/fuzz/corpus/$name" findings="$BUILD/fuzz/findings/$name"
    rm -rf "$findings" && mkdir -p "$work" "$findings" # findings of this run only
    seeds=()
    [ -d "fuzz/corpus/$name" ] && seeds+=("fuzz/corpus/$name")
    case "$name" in
    gltf) seeds+=(assets/scenes assets/testdata) ;; # each target skips the other's inputs
    glb) seeds+=(assets/testdata) ;;
    snapshot)
        SNOW_FUZZ_WRITE_SEED="$work/current.snap" "$BUILD/fuzz/$t" >/dev/null 2>&1 ||
            { echo "fuzz.sh: $t could not write its seed snapshot" >&2; exit 1; } ;;
    esac
    max_len=262144 # a .gltf or .glb up to 256 KiB; a snapshot as long as the seed
    [ "$name" = snapshot ] && max_len=$(stat -c %s "$work/current.snap")
    dict=(); [ -f "fuzz/dict/$name.dict" ] && dict=(-dict="fuzz/dict/$name.dict")
    echo "[fuzz] $t: ${SECONDS_EACH} s, timeout ${TIMEOUT} s"
    if ! "$BUILD/fuzz/$t" "$work" "${seeds[@]}" "${dict[@]}" -max_total_time="$SECONDS_EACH" \
        -timeout="$TIMEOUT" -rss_limit_mb=2048 -max_len="$max_len" -report_slow_units=1 \
        -close_fd_mask=3 -print_final_stats=1 -artifact_prefix="$findings/" "${KEEP_GOING[@]}" \
        2>"$BUILD/fuzz/$name.log" || ls "$findings" | grep -qvE '^slow-unit-'; then
        status=1
        echo "[fuzz] $t: FINDING (log $BUILD/fuzz/$name.log):"
        ls "$findings"
        grep -E '^(==[0-9]+==ERROR|SUMMARY|ALARM|.*runtime error|.*exiting)' \
            "$BUILD/fuzz/$name.log" | head -5 || true
    fi
    { grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ +DONE)' \
        "$BUILD/fuzz/$name.log"; grep -E 'Slowest unit' "$BUILD/fuzz/$name.log" | tail -1; } |
        sed "s/^/[fuzz] $t: /" || true
done
exit $status
