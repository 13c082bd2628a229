#!/usr/bin/env python3
"""The garage's lee with and without the wind field (README, docs/wind_field.md).

    python3 scripts/lee_images.py [--build DIR] [--out DIR] [--seconds S]

Writes two variants of assets/scenes/village.gltf into BUILD/lee/ that differ
only in extras.snow.wind.field (none, or 64 x 16 x 64 cells), both with a
fast-forwarded snowfall (200 kg/m2/h, 13 x the scene's) so the snow is deep
enough to read; runs `snow_run --export-depth` on each for the same simulated
time and seed; and draws the ground's depth around the garage, seen from
above, in one colour scale: OUT/lee_without_field.png, OUT/lee_with_field.png
(default OUT: docs/img). Prints the mean depth of the lee strip the test
WindFieldScene.SnowDropsOutInTheLeeOfTheGarage measures. Standard library
only; takes about two minutes on 2 cores.
"""

import argparse
import json
import struct
import subprocess
import sys
import zlib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SNOWFALL = 200.0  # kg/m2/h
PARCELS = 40000.0  # parcels/s: enough to carry it
FIELD = {"cells": [64, 16, 64]}
# World rectangle drawn (x0, z0, x1, z1): the garage (x 3..7, z -3..0) and its lee
# up to the ground's edge.
VIEW = (1.0, -6.0, 10.0, 3.0)
GARAGE = (3.0, -3.0, 7.0, 0.0)
LEE_STRIP = (7.25, -3.0, 9.25, 0.0)  # tests/game/scene/test_wind_field_scene.cpp
SCALE = 4  # pixels per cell


def scene_variant(field):
    doc = json.loads((ROOT / "assets" / "scenes" / "village.gltf").read_text())
    snow = doc["scenes"][0]["extras"]["snow"]
    snow["emitter"]["rate"] = PARCELS
    snow["emitter"]["snowfall_kg_m2_h"] = SNOWFALL
    if field:
        snow["wind"]["field"] = FIELD
    return doc


def read_gray16(path):
    """Width, height and rows of a 16-bit grayscale PNG with filter 0 (png16.cpp)."""
    data = path.read_bytes()
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height = struct.unpack(">II", body[:8])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = 1 + 2 * width
    return width, height, [struct.unpack(">%dH" % width, raw[r * stride + 1:(r + 1) * stride])
                           for r in range(height)]


def write_rgb(path, width, height, pixels):
    """An 8-bit RGB PNG; pixels[y][x] = (r, g, b)."""
    rows = b"".join(b"\0" + bytes(c for p in row for c in p) for row in pixels)

    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body +
                struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))

    path.write_bytes(b"\x89PNG\r\n\x1a\n" +
                     chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                     chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


RAMP = [(0.05, 0.05, 0.2), (0.1, 0.3, 0.7), (0.1, 0.7, 0.7), (0.6, 0.9, 0.3), (1.0, 1.0, 0.6)]


def colour(share):
    t = min(max(share, 0.0), 1.0) * (len(RAMP) - 1)
    i = min(int(t), len(RAMP) - 2)
    u = t - i
    return tuple(int(255 * (a + u * (b - a))) for a, b in zip(RAMP[i], RAMP[i + 1]))


def ground(depth_dir):
    """The ground surface's depth (mm) and grid: the surface whose origin is (-10, -10)."""
    for meta_path in sorted(depth_dir.glob("surface_*.json")):
        meta = json.loads(meta_path.read_text())
        if meta["origin"] == [-10.0, -10.0]:
            return meta, read_gray16(meta_path.with_suffix(".png"))[2]
    sys.exit("lee_images: no ground surface in " + str(depth_dir))


def strip_mean_mm(meta, depth, box):
    x0, z0 = meta["origin"]
    cell = meta["cell"]
    values = [depth[iz][ix] for iz in range(len(depth)) for ix in range(len(depth[0]))
              if box[0] < x0 + (ix + 0.5) * cell < box[2] and box[1] < z0 + (iz + 0.5) * cell < box[3]]
    return sum(values) / len(values)


def view_depths_mm(meta, depth):
    """Depths of the ground cells in VIEW outside the garage."""
    x0, z0 = meta["origin"]
    cell = meta["cell"]
    out = []
    for iz, row in enumerate(depth):
        for ix, mm in enumerate(row):
            x, z = x0 + (ix + 0.5) * cell, z0 + (iz + 0.5) * cell
            in_view = VIEW[0] < x < VIEW[2] and VIEW[1] < z < VIEW[3]
            on_garage = GARAGE[0] < x < GARAGE[2] and GARAGE[1] < z < GARAGE[3]
            if in_view and not on_garage:
                out.append(mm)
    return out


def draw(meta, depth, top_mm, path):
    x0, z0 = meta["origin"]
    cell = meta["cell"]
    ix0, ix1 = int((VIEW[0] - x0) / cell), int((VIEW[2] - x0) / cell)
    iz0, iz1 = int((VIEW[1] - z0) / cell), int((VIEW[3] - z0) / cell)

    def inside(box, ix, iz):
        x, z = x0 + (ix + 0.5) * cell, z0 + (iz + 0.5) * cell
        return box[0] < x < box[2] and box[1] < z < box[3]

    def edge(box, ix, iz):
        return inside(box, ix, iz) and not all(
            inside(box, ix + dx, iz + dz) for dx, dz in ((1, 0), (-1, 0), (0, 1), (0, -1)))

    pixels = []
    for iz in range(iz0, iz1):  # +z is down the image: seen from above, +x to the right
        row = []
        for ix in range(ix0, ix1):
            if edge(GARAGE, ix, iz):
                c = (0, 0, 0)
            elif edge(LEE_STRIP, ix, iz):
                c = (255, 255, 255)
            elif inside(GARAGE, ix, iz):
                c = (90, 90, 90)  # the garage roof: not the ground
            else:
                c = colour(depth[iz][ix] / top_mm)
            row += [c] * SCALE
        pixels += [row] * SCALE
    write_rgb(path, (ix1 - ix0) * SCALE, (iz1 - iz0) * SCALE, pixels)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--build", default=str(ROOT / "build"))
    p.add_argument("--out", default=str(ROOT / "docs" / "img"))
    p.add_argument("--seconds", type=float, default=60.0)
    a = p.parse_args()
    work = Path(a.build) / "lee"
    work.mkdir(parents=True, exist_ok=True)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    runs = {}
    for name, field in (("without_field", False), ("with_field", True)):
        scene = work / (name + ".gltf")
        scene.write_text(json.dumps(scene_variant(field)))
        depth_dir = work / (name + "_depth")
        ticks = str(round(a.seconds * 60))
        subprocess.run([str(Path(a.build) / "game" / "snow_run"), "--scene", str(scene), "--ticks",
                        ticks, "--max-flakes", "400000", "--export-depth", str(depth_dir)],
                       check=True, stdout=subprocess.DEVNULL)
        runs[name] = ground(depth_dir)
    # The top of the colour scale: the 98th percentile of both views (the
    # drift against the garage's windward face would squash the rest).
    both = sorted(mm for meta, depth in runs.values() for mm in view_depths_mm(meta, depth))
    top = max(1, both[int(0.98 * (len(both) - 1))])
    for name, (meta, depth) in runs.items():
        draw(meta, depth, top, out / ("lee_" + name + ".png"))
        print("lee_images: %s: lee strip mean %.1f mm, colour scale 0 - %d mm (deeper: the top colour) -> %s" %
              (name, strip_mean_mm(meta, depth, LEE_STRIP), top, out / ("lee_" + name + ".png")))


if __name__ == "__main__":
    main()
