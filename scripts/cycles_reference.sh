#!/usr/bin/env bash
# A path-traced reference for our snow (docs/rendering.md, "A path-traced
# reference"). Runs village_effects (without fog, far-field snow, lamps and
# the walker: scripts/cycles_scene.py) for --ticks, exports the snow, draws
# the frame and its snow mask with snow_game, renders the same snow, camera,
# sun and sky with Blender's Cycles (scripts/cycles_reference.py) and
# compares them over the snow (scripts/cycles_compare.py). With
# --before-build, also the frame as the renderer before the sun drew it
# (a build of $before_commit). --docs copies the reference, our frame and
# the one before into docs/img/cycles_*.png. Needs blender and
# python3-skimage (Debian).
# Not part of the tests: it takes minutes and its images are committed.
set -euo pipefail
python=/usr/bin/python3 # Debian's, which python3-skimage installs into
cd "$(dirname "$0")/.."

before_commit=6f656b827b68985122aaea3417fafd47cca885cc # parent of 4e57bf2, "A sun for the renderer"
usage="usage: scripts/cycles_reference.sh [--build DIR] [--before-build DIR] [--docs] [--out DIR]
                                   [--ticks N] [--size WxH] [--samples N]
defaults: --build build --out out/cycles --ticks 12000 --size 640x360 --samples 256"
fail() {
    printf 'cycles_reference.sh: %s\n%s\n' "$1" "$usage" >&2
    exit 2
}

build=build before_build='' docs='' out=out/cycles ticks=12000 size=640x360 samples=256
while [ $# -gt 0 ]; do
    case $1 in
    --build | --before-build | --out | --ticks | --size | --samples)
        [ $# -ge 2 ] || fail "$1: expected a value"
        declare "$(echo "${1#--}" | tr - _)=$2" # --before-build DIR sets before_build
        shift 2
        ;;
    --docs)
        docs=1
        shift
        ;;
    --help)
        echo "$usage"
        exit 0
        ;;
    *) fail "unknown argument '$1'" ;;
    esac
done
[[ $ticks =~ ^[1-9][0-9]{0,6}$ && $ticks -ge 2 ]] || fail "--ticks: expected a whole number from 2, got '$ticks'"
[[ $size =~ ^([1-9][0-9]{1,3})x([1-9][0-9]{1,3})$ ]] || fail "--size: expected WxH, e.g. 640x360, got '$size'"
width=${BASH_REMATCH[1]} height=${BASH_REMATCH[2]}
[[ $samples =~ ^[1-9][0-9]{0,4}$ ]] || fail "--samples: expected a whole number from 1, got '$samples'"
[ -z "$docs" ] || [ -n "$before_build" ] || fail "--docs: needs --before-build (the images show the frame before too)"
for app in "$build/game/snow_run" "$build/game/snow_game" ${before_build:+"$before_build/game/snow_game"}; do
    [ -x "$app" ] || fail "no $app: build it first (scripts/test.sh)"
done
command -v blender >/dev/null || fail "blender is missing: apt-get install blender"
"$python" -c 'import skimage' 2>/dev/null || fail "python3-skimage is missing: apt-get install python3-skimage"

mkdir -p "$out"
# snow_game ticks twice (1/30 s) before its first headless frame; --quality
# medium simulates semi-implicitly, so snow_run does too.
frame=(--headless --frames 1 --size "$size" --warmup $((ticks - 2)) --camera fly --quality medium)
"$python" scripts/cycles_scene.py assets/scenes/village_effects.gltf "$out/scene.gltf"
"$python" scripts/cycles_scene.py assets/scenes/village_effects.gltf "$out/scene_lamps.gltf" --keep-lamps
"$build/game/snow_run" --scene "$out/scene.gltf" --ticks "$ticks" --integrator semi_implicit \
    --export "$out/snow.glb" >"$out/snow_run.log"
"$build/game/snow_game" --scene "$out/scene.gltf" "${frame[@]}" --aov --out "$out/ours" >"$out/ours.log"
"$build/game/snow_game" --scene "$out/scene_lamps.gltf" "${frame[@]}" --out "$out/ours_lamps" >"$out/ours_lamps.log"
"$build/game/snow_game" --scene "$out/scene.gltf" "${frame[@]}" --no-detail-normals --no-sparkle \
    --out "$out/ours_plain" >"$out/ours_plain.log"
frames=("$out/ours/frame_00000.png" "$out/ours_lamps/frame_00000.png" "$out/ours_plain/frame_00000.png")
if [ -n "$before_build" ]; then
    git show "$before_commit:assets/scenes/village_effects.gltf" >"$out/village_effects_before.gltf"
    "$python" scripts/cycles_scene.py "$out/village_effects_before.gltf" "$out/scene_before.gltf" --keep-lamps
    "$before_build/game/snow_game" --scene "$out/scene_before.gltf" "${frame[@]}" --out "$out/before" >"$out/before.log"
    frames+=("$out/before/frame_00000.png")
fi
echo "cycles_reference.sh: rendering with Cycles ($size, $samples samples; log in $out/blender.log)"
blender -b --factory-startup -P scripts/cycles_reference.py -- "$out/scene.gltf" "$out/snow.glb" \
    "$out/cycles.npy" "$width" "$height" "$samples" >"$out/blender.log" 2>&1 ||
    { tail -20 "$out/blender.log" >&2; exit 1; }
grep -o 'Time: [0-9:.]*' "$out/blender.log" | tail -1
"$python" scripts/cycles_compare.py "$out/scene.gltf" "$out/cycles.npy" "$out/ours/frame_00000" "${frames[@]}"
if [ -n "$docs" ]; then
    cp "$out/cycles.png" docs/img/cycles_reference.png
    cp "$out/ours/frame_00000.png" docs/img/cycles_ours.png
    cp "$out/before/frame_00000.png" docs/img/cycles_before.png
fi
