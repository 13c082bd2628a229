#!/usr/bin/env bash
# Set-up command 1: installs missing dependencies, builds Release and runs the
# snow scene: a window when a display is usable, otherwise a headless render
# to PNG files (the path is printed). Extra arguments go to snow_game.
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD_DIR=${BUILD_DIR:-build}
./scripts/deps.sh
echo "[play] configuring ${BUILD_DIR}"
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
echo "[play] building snow_game"
cmake --build "$BUILD_DIR" -j "$(nproc)" --target snow_game

if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
    echo "[play] starting the snow scene in a window (press H for help)"
    exec "$BUILD_DIR/game/snow_game" "$@"
fi
OUT_DIR=${OUT_DIR:-out/frames}
echo "[play] no display: rendering headless into ${OUT_DIR} (120 frames unless --frames N is given)"
exec "$BUILD_DIR/game/snow_game" --headless --frames 120 --out "$OUT_DIR" "$@"
