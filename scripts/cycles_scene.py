#!/usr/bin/env python3
"""The scene scripts/cycles_reference.sh draws both ways: SRC without what the
path-traced reference cannot show the same: fog and far-field snow, moving
bodies (the glTF holds their start, our frame their pose after the run) and,
unless --keep-lamps, the lamps (the reference has only the sun and the sky).
Its snowfall is fast-forwarded to 20 kg/m2/h, about the most the village's
emitter rate carries, so that a few minutes lay millimetres of snow (the
export holds what the simulation laid; our renderer also whitens open meshes
where the simulation has laid little) while as many flakes fly as before.

usage: cycles_scene.py SRC.gltf DST.gltf [--keep-lamps]"""
import json
import sys

SNOWFALL = 20.0  # kg/m2/h; 21 at most for the village's 3000 parcels/s


def dropped(node, keep_lamps):
    lamp = "KHR_lights_punctual" in node.get("extensions", {})
    moving = "motion" in node.get("extras", {}).get("snow", {})
    return moving or (lamp and not keep_lamps)


def main(argv):
    if len(argv) not in (2, 3) or argv[2:] not in ([], ["--keep-lamps"]):
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        sys.exit(2)
    with open(argv[0]) as f:
        gltf = json.load(f)
    scene = gltf["scenes"][gltf.get("scene", 0)]
    scene["extras"]["snow"]["emitter"]["snowfall_kg_m2_h"] = SNOWFALL
    for key in ("fog", "spectral"):
        scene["extras"]["snow"].pop(key, None)
    keep_lamps = len(argv) == 3
    scene["nodes"] = [n for n in scene["nodes"] if not dropped(gltf["nodes"][n], keep_lamps)]
    with open(argv[1], "w") as f:
        json.dump(gltf, f)


if __name__ == "__main__":
    main(sys.argv[1:])
