#!/usr/bin/env python3
"""Tones the Cycles reference as our renderer tones a frame and measures our
frames against it over the snow (scripts/cycles_reference.sh):

  cycles_compare.py SCENE.gltf CYCLES.npy MASKS FRAME.png [FRAME.png ...]

Writes CYCLES.png beside CYCLES.npy: the radiance times the sun's exposure
through the filmic curve of common.glsl, no sRGB step (ours has none), over
the sky colour drawn as is (ours draws the sky without the curve). MASKS is
the path of our frame's masks without _snow.png / _shadow.png (snow_game
--aov). Prints, for each frame, over the pixels the mask shows at least half
snow: the mean SSIM (skimage, 7x7 windows, on the whole frame, averaged over
those pixels), the mean absolute difference in levels of 255 (all channels),
the mean colour of the sunlit snow (shadow mask <= 10 %) and of the shaded
snow (>= 50 %), as tests/render/snow_image_measures.* count them, and the
spread (standard deviation) of the sunlit snow's luma."""
import json
import sys

import numpy as np
from skimage import io
from skimage.metrics import structural_similarity


def sun_exposure(sun):
    """render/renderer.cpp sun_exposure(): flat sunlit snow at 1.1 before the curve."""
    d = np.asarray(sun["direction"], dtype=float)
    height = max(d[1] / np.linalg.norm(d), 0.2)
    return 1.1 / (0.9 * sun["intensity"] * height)


def filmic(x):
    """common.glsl filmic(): [ACES], Narkowicz's fit."""
    return np.clip(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0)


def reference_image(scene_path, npy_path):
    with open(scene_path) as f:
        gltf = json.load(f)
    extras = gltf["scenes"][gltf.get("scene", 0)]["extras"]["snow"]
    rgba = np.load(npy_path)
    colour = filmic(rgba[..., :3] * sun_exposure(extras["sun"]))
    sky = np.asarray(extras["environment"]["sky"])
    colour += (1.0 - rgba[..., 3:]) * sky
    return np.round(np.clip(colour, 0.0, 1.0) * 255.0).astype(np.uint8)


def rgb(path):
    return io.imread(path)[..., :3]


def main(argv):
    if len(argv) < 4 or not argv[1].endswith(".npy"):
        print(__doc__.split("\n\n")[1].strip(), file=sys.stderr)
        sys.exit(2)
    scene_path, npy_path, masks, frames = argv[0], argv[1], argv[2], argv[3:]
    reference = reference_image(scene_path, npy_path)
    reference_path = npy_path[:-4] + ".png"
    io.imsave(reference_path, reference, check_contrast=False)
    snow = rgb(masks + "_snow.png")[..., 0] >= 128
    shadow = rgb(masks + "_shadow.png")[..., 0]
    lit, shaded = snow & (shadow <= 25), snow & (shadow >= 128)
    print(f"snow pixels: {snow.sum()} of {snow.size}, sunlit {lit.sum()}, shaded {shaded.sum()}")
    print("| frame | SSIM over the snow | mean abs. difference (levels) | sunlit snow RGB | shaded snow RGB | sunlit luma sd |")
    print("|---|---:|---:|---|---|---:|")
    for path in [reference_path] + frames:
        image = rgb(path)
        _, ssim = structural_similarity(image, reference, channel_axis=2, data_range=255, full=True)
        mad = np.abs(image.astype(float) - reference)[snow].mean()
        means = [" ".join(f"{c:.0f}" for c in image[where].mean(axis=0)) for where in (lit, shaded)]
        spread = (image[lit] @ [0.2126, 0.7152, 0.0722]).std()
        print(f"| {path} | {ssim.mean(axis=2)[snow].mean():.3f} | {mad:.1f} | {means[0]} | {means[1]} "
              f"| {spread:.1f} |")


if __name__ == "__main__":
    main(sys.argv[1:])
