#!/usr/bin/env bash
# Set-up command 1: installs missing dependencies, builds Release and runs the
# snow scene: a window when a display is usable, otherwise a headless
# time-lapse of the village to PNG files, a contact sheet and an MP4 (the
# paths are printed). Extra arguments go to snow_game.
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
# Headless, the village tells its story: a storm of four simulated minutes in
# 120 frames (the cover deepens, drifts grow at the windward walls, the house's
# roof slides onto the porch, the walker cuts a trail that fills again),
# written as PNG frames, a contact sheet of 8 moments and, with ffmpeg, an MP4.
OUT_DIR=${OUT_DIR:-out/timelapse}
echo "[play] no display: rendering the village time-lapse headless into ${OUT_DIR}"
"$BUILD_DIR/game/snow_game" --timelapse --out "$OUT_DIR" "$@"
echo "[play] frames:        $(realpath "$OUT_DIR")/frame_*.png"
if [ -f "$OUT_DIR/contact_sheet.png" ]; then
    echo "[play] contact sheet: $(realpath "$OUT_DIR/contact_sheet.png")"
fi
if [ -f "$OUT_DIR/snow.mp4" ]; then
    echo "[play] video:         $(realpath "$OUT_DIR/snow.mp4")"
fi
