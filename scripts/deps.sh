#!/usr/bin/env bash
# Installs the Debian packages snow needs, only those missing. Idempotent.
# Usage: scripts/deps.sh            (everything: build, render, scenes, tests, bench)
#        scripts/deps.sh PACKAGE...  (those too, e.g. CI's aarch64 step:
#                                     g++-aarch64-linux-gnu qemu-user)
set -euo pipefail

packages=(
    g++ cmake ninja-build pkg-config python3
    clang                                        # CI's second compiler (its ASan+UBSan build, build-asan)
    libclang-rt-14-dev                           # the sanitizers' and libFuzzer's runtimes (scripts/fuzz.sh)
    libglm-dev                                   # snow_sim (the only dependency of the simulation)
    libglfw3-dev libosmesa6-dev libegl-dev libegl-mesa0 libstb-dev python3-glad libimgui-dev  # snow_render, snow_game
    nlohmann-json3-dev                           # snow_scene
    zlib1g-dev                                   # snow_export (16-bit depth PNGs)
    googletest libgtest-dev libbenchmark-dev     # snow_tests, snow_bench
    libtinygltf-dev                              # snow_gltf_oracle_tests (tinygltf 2.7, the loader's oracle)
    xvfb xauth                                   # window tests without a display
    gnuplot-nox                                  # plots in docs/
    ffmpeg                                       # play.sh headless: the time-lapse as MP4
    libirrlicht-dev                              # examples/irrlicht (snow inside the Irrlicht engine)
    "$@"
)
# The glTF validator test (npm gltf-validator) needs node and npm; any
# install of them will do, so Debian's are added only when there are none.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
    packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "[deps] all ${#packages[@]} packages present"
    exit 0
fi

echo "[deps] installing: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
        SUDO="sudo"
    else
        echo "[deps] error: not root and no sudo; install these packages: ${missing[*]}" >&2
        exit 1
    fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "[deps] done"
