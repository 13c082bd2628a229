#!/usr/bin/env python3
"""Writes glTF test data shaped like other tools' exports to assets/testdata/.

    python3 scripts/make_test_gltf.py [--check]

Standard library only; deterministic (--check exits 1 if a file would change).
No file here carries `extras.snow`: they are what a user brings from a
modeller, and the loader must read them as the glTF 2.0 spec says.

  tool_export.glb   a binary glTF as exporters write it: a JSON chunk and one
                    BIN chunk; a named scene; a node hierarchy with
                    translation/rotation/scale; a ground (16-bit indices), a
                    crate with normals and texture coordinates, a tree with two
                    primitives (32-bit indices, two materials); a LINES
                    primitive (edges, skipped by the loader with a warning); a
                    texture whose PNG image (wood planks) lies in a bufferView;
                    a camera node; interleaved vertex data (byteStride);
                    foreign extras.
  plain.gltf        + plain.bin: a .gltf without a `scenes` array (all root
                    nodes are the scene), an external buffer, a node `matrix`,
                    8-bit indices, a non-indexed primitive, and a texture in an
                    image file beside it (textures/bark.png).
"""

import json
import math
import struct
import sys
import zlib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
OUT_DIR = ROOT / "assets" / "testdata"

FLOAT, UBYTE, USHORT, UINT = 5126, 5121, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
LINES = 1


class Buffer:
    """Accumulates bufferViews and accessors over one byte buffer."""

    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def view(self, payload, target=None, stride=None):
        while len(self.data) % 4:
            self.data.append(0)
        v = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(payload)}
        if target is not None:
            v["target"] = target
        if stride is not None:
            v["byteStride"] = stride
        self.data += payload
        self.views.append(v)
        return len(self.views) - 1

    def accessor(self, view, component, count, kind, offset=0, bounds=None):
        a = {"bufferView": view, "componentType": component, "count": count, "type": kind}
        if offset:
            a["byteOffset"] = offset
        if bounds:
            a["min"], a["max"] = bounds
        self.accessors.append(a)
        return len(self.accessors) - 1

    def positions(self, points):
        flat = [c for p in points for c in p]
        view = self.view(struct.pack("<%df" % len(flat), *flat), ARRAY_BUFFER)
        lo = [min(p[i] for p in points) for i in range(3)]
        hi = [max(p[i] for p in points) for i in range(3)]
        return self.accessor(view, FLOAT, len(points), "VEC3", bounds=(lo, hi))

    def indices(self, values, component):
        fmt = {UBYTE: "B", USHORT: "H", UINT: "I"}[component]
        view = self.view(struct.pack("<%d%s" % (len(values), fmt), *values), ELEMENT_ARRAY_BUFFER)
        return self.accessor(view, component, len(values), "SCALAR")


def box(sx, sy, sz):
    """Flat-shaded box centred at the origin: 24 vertices, normals, uvs, 36 indices."""
    faces = [
        ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
        ((-1, 0, 0), (0, 1, 0), (0, 0, -1)),
        ((0, 1, 0), (0, 0, 1), (1, 0, 0)),
        ((0, -1, 0), (0, 0, -1), (1, 0, 0)),
        ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
        ((0, 0, -1), (-1, 0, 0), (0, 1, 0)),
    ]
    half = (sx / 2, sy / 2, sz / 2)
    pos, nrm, uv, idx = [], [], [], []
    for n, u, v in faces:
        base = len(pos)
        for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            p = [half[i] * (n[i] + a * u[i] + b * v[i]) for i in range(3)]
            # u x v = n keeps the quad counter-clockwise seen from outside.
            pos.append(p)
            nrm.append(list(n))
            uv.append([(a + 1) / 2, (b + 1) / 2])
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nrm, uv, idx


def cone(radius, height, segments):
    """A closed cone (apex up, base at y = 0), no normals (the loader computes them)."""
    pos = [[0.0, height, 0.0], [0.0, 0.0, 0.0]]
    for k in range(segments):
        a = 2 * math.pi * k / segments
        pos.append([radius * math.cos(a), 0.0, -radius * math.sin(a)])
    idx = []
    for k in range(segments):
        i, j = 2 + k, 2 + (k + 1) % segments
        idx += [0, i, j, 1, j, i]
    return pos, idx


def png(rows):
    """An 8-bit RGB PNG of `rows` (top row first, (r, g, b) per pixel)."""
    def chunk(kind, payload):
        return (struct.pack(">I", len(payload)) + kind + payload
                + struct.pack(">I", zlib.crc32(kind + payload)))
    header = struct.pack(">IIBBBBB", len(rows[0]), len(rows), 8, 2, 0, 0, 0)
    raw = b"".join(b"\0" + bytes(c for px in row for c in px) for row in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def glb(doc, data):
    text = json.dumps(doc, separators=(",", ":"), sort_keys=True).encode()
    text += b" " * (-len(text) % 4)
    data = bytes(data) + b"\0" * (-len(data) % 4)
    total = 12 + 8 + len(text) + 8 + len(data)
    return (
        struct.pack("<4sII", b"glTF", 2, total)
        + struct.pack("<II", len(text), 0x4E4F534A)
        + text
        + struct.pack("<II", len(data), 0x004E4942)
        + data
    )


def tool_export():
    b = Buffer()
    ground = b.positions([[-6, 0, -6], [6, 0, -6], [6, 0, 6], [-6, 0, 6]])
    ground_idx = b.indices([0, 2, 1, 0, 3, 2], USHORT)

    # The crate interleaves position, normal and uv in one view (stride 32).
    pos, nrm, uv, idx = box(1.0, 1.0, 1.0)
    interleaved = b"".join(struct.pack("<8f", *pos[i], *nrm[i], *uv[i]) for i in range(len(pos)))
    crate_view = b.view(interleaved, ARRAY_BUFFER, stride=32)
    bounds = ([-0.5] * 3, [0.5] * 3)
    crate_pos = b.accessor(crate_view, FLOAT, len(pos), "VEC3", 0, bounds)
    crate_nrm = b.accessor(crate_view, FLOAT, len(pos), "VEC3", 12)
    crate_uv = b.accessor(crate_view, FLOAT, len(pos), "VEC2", 24)
    crate_idx = b.indices(idx, USHORT)
    edges_idx = b.indices([0, 1, 1, 2, 2, 3, 3, 0], USHORT)

    crown_pos, crown_idx = cone(1.2, 2.5, 12)
    trunk_p, trunk_n, _, trunk_i = box(0.3, 1.0, 0.3)
    crown = b.positions([[p[0], p[1] + 1.0, p[2]] for p in crown_pos])
    crown_i = b.indices(crown_idx, UINT)
    trunk = b.positions([[p[0], p[1] + 0.5, p[2]] for p in trunk_p])
    trunk_nrm = b.positions(trunk_n)
    trunk_ix = b.indices(trunk_i, UINT)

    # Wood: four planks across, a dark seam between them.
    wood = [[(92, 58, 30) if x % 4 == 3 else (150 + 6 * (y % 3), 100, 56) for x in range(16)]
            for y in range(16)]
    image_view = b.view(png(wood))

    doc = {
        "asset": {"version": "2.0", "generator": "Khronos glTF Blender I/O v3.6.27"},
        "extensionsUsed": ["KHR_materials_specular"],
        "scene": 0,
        "scenes": [{"name": "Scene", "nodes": [0, 1, 5]}],
        "nodes": [
            {"name": "Ground", "mesh": 0},
            {"name": "Yard", "translation": [1.0, 0.0, -1.0], "children": [2, 3],
             "extras": {"blender_collection": "props"}},
            {"name": "Crate", "mesh": 1, "translation": [0.0, 0.5, 0.0],
             "rotation": [0.0, 0.3826834323650898, 0.0, 0.9238795325112867],
             "scale": [1.0, 1.0, 1.5]},
            {"name": "Tree", "mesh": 2, "translation": [-3.0, 0.0, 2.0], "children": [4]},
            {"name": "Camera", "camera": 0, "translation": [0.0, 1.6, 8.0]},
            {"name": "Light", "translation": [2.0, 6.0, 2.0]},
        ],
        "cameras": [{"type": "perspective",
                     "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100.0}}],
        "meshes": [
            {"name": "Plane", "primitives": [
                {"attributes": {"POSITION": ground}, "indices": ground_idx, "material": 0}]},
            {"name": "Cube", "primitives": [
                {"attributes": {"POSITION": crate_pos, "NORMAL": crate_nrm,
                                "TEXCOORD_0": crate_uv},
                 "indices": crate_idx, "material": 1},
                {"attributes": {"POSITION": crate_pos}, "indices": edges_idx, "mode": LINES}]},
            {"name": "Tree", "primitives": [
                {"attributes": {"POSITION": trunk, "NORMAL": trunk_nrm}, "indices": trunk_ix,
                 "material": 2},
                {"attributes": {"POSITION": crown}, "indices": crown_i, "material": 3}]},
        ],
        "materials": [
            {"name": "Grass", "pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.5, 0.2, 1.0],
                                                      "metallicFactor": 0.0}},
            {"name": "Wood", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                                     "metallicFactor": 0.0,
                                                     "roughnessFactor": 0.8},
             "extensions": {"KHR_materials_specular": {"specularFactor": 0.5}}},
            {"name": "Bark", "pbrMetallicRoughness": {"baseColorFactor": [0.4, 0.25, 0.1, 1.0]}},
            {"name": "Needles", "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.35, 0.15,
                                                                            1.0]}},
        ],
        "textures": [{"sampler": 0, "source": 0}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987}],
        "images": [{"name": "wood", "mimeType": "image/png", "bufferView": image_view}],
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": [{"byteLength": len(b.data)}],
    }
    return glb(doc, b.data)


def plain():
    b = Buffer()
    slab_p, slab_n, slab_t, slab_i = box(4.0, 0.2, 3.0)
    slab = b.positions(slab_p)
    slab_nrm = b.positions(slab_n)
    flat_uv = [c for t in slab_t for c in t]
    slab_uv = b.accessor(b.view(struct.pack("<%df" % len(flat_uv), *flat_uv), ARRAY_BUFFER),
                         FLOAT, len(slab_t), "VEC2")
    slab_idx = b.indices(slab_i, UBYTE)
    # A non-indexed ramp: two triangles, six vertices in order.
    ramp = b.positions([[0, 0, 0], [2, 0, 1], [2, 1, 0], [0, 0, 0], [0, 0, 1], [2, 0, 1]])
    doc = {
        "asset": {"version": "2.0", "generator": "a plain exporter"},
        "nodes": [
            {"name": "slab", "mesh": 0,
             "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5, 1.0, -0.5, 1]},
            {"name": "ramp", "mesh": 1, "translation": [3.0, 0.0, 0.0]},
        ],
        "meshes": [
            {"primitives": [{"attributes": {"POSITION": slab, "NORMAL": slab_nrm,
                                            "TEXCOORD_0": slab_uv},
                             "indices": slab_idx, "material": 0}]},
            {"primitives": [{"attributes": {"POSITION": ramp}}]},
        ],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0}],
        "images": [{"uri": "textures/bark.png"}],
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": [{"byteLength": len(b.data), "uri": "plain.bin"}],
    }
    text = json.dumps(doc, indent=1, sort_keys=True) + "\n"
    # Bark: grey-brown furrows running down.
    bark = [[(70, 52, 40) if x % 3 == 0 else (112, 90, 70) for x in range(6)] for _ in range(6)]
    return text.encode(), bytes(b.data), png(bark)


def main():
    check = "--check" in sys.argv[1:]
    plain_text, plain_bin, bark_png = plain()
    files = {"tool_export.glb": tool_export(), "plain.gltf": plain_text, "plain.bin": plain_bin,
             "textures/bark.png": bark_png}
    stale = []
    for name, data in files.items():
        path = OUT_DIR / name
        if check:
            if not path.exists() or path.read_bytes() != data:
                stale.append(name)
            continue
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)
        print("make_test_gltf: wrote assets/testdata/" + name)
    if stale:
        print("make_test_gltf: out of date: " + ", ".join(stale), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
