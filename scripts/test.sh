#!/usr/bin/env bash
# Set-up command 2: installs missing dependencies, builds (Release) and runs
# the whole test suite with ctest. Extra arguments go to cmake's configure step.
# Environment: BUILD_DIR (default build), JOBS (default: number of cores).
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-$(nproc)}

./scripts/deps.sh
echo "[test] configuring ${BUILD_DIR}"
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
echo "[test] building with ${JOBS} jobs"
cmake --build "$BUILD_DIR" -j "$JOBS"
echo "[test] running tests"
export MESA_SHADER_CACHE_DISABLE=true
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS"
