#!/usr/bin/env python3
"""Writes two scenes that declare all the work a WorkBudget allows at once
(docs/reliability.md "Bounded work"), each under 256 KiB:
  assets/testdata/at_default_budget.gltf  every WorkBudget default reached
  fuzz/corpus/gltf/at_fuzz_budget.gltf    every fuzz::budget() limit reached
Flakes fill the pool on the first tick; bodies jump from their node to their
path; mesh colliders instance one grid mesh. Made from assets/scenes/minimal.gltf.
With --large DIR, also the largest inputs the loader takes, not committed:
  DIR/largest.gltf  the default-budget scene with about 2^20 JSON values and a
                    data URI buffer: just under 16 MiB of JSON
  DIR/largest.glb   the default-budget scene with a render mesh of nearly
                    2^22 vertices and 2^24 indices in its BIN chunk
Usage: fuzz/make_budget_scenes.py [--large DIR] (from the repository root)."""
import array
import os
import base64
import copy
import json
import struct
import sys

BASE = json.load(open("assets/scenes/minimal.gltf"))

def grid_mesh(doc):
    """Adds a two-sided 16x16 grid (1024 triangles); returns its mesh index."""
    n = 17
    verts = [c for j in range(n) for i in range(n) for c in (i / (n - 1) - 0.5, 0.0, j / (n - 1) - 0.5)]
    idx = []
    for j in range(n - 1):
        for i in range(n - 1):
            a = j * n + i
            b, c = a + 1, a + n
            idx += [a, c, b, b, c, c + 1, a, b, c, b, c + 1, c]
    raw = bytearray(base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1]))
    off = len(raw)
    vb = struct.pack("<%df" % len(verts), *verts)
    ib = struct.pack("<%dH" % len(idx), *idx)
    raw += vb + ib
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(bytes(raw)).decode()
    doc["buffers"][0]["byteLength"] = len(raw)
    views = doc["bufferViews"]
    views += [{"buffer": 0, "byteOffset": off, "byteLength": len(vb)},
              {"buffer": 0, "byteOffset": off + len(vb), "byteLength": len(ib)}]
    acc = doc["accessors"]
    acc += [{"bufferView": len(views) - 2, "componentType": 5126, "count": n * n, "type": "VEC3",
             "min": [-0.5, 0, -0.5], "max": [0.5, 0, 0.5]},
            {"bufferView": len(views) - 1, "componentType": 5123, "count": len(idx), "type": "SCALAR"}]
    doc["meshes"].append({"name": "grid", "primitives": [{"attributes": {"POSITION": len(acc) - 2},
                                                           "indices": len(acc) - 1}]})
    return len(doc["meshes"]) - 1, len(idx) // 3

def scene(path, name, cell, surfaces, bodies, triangles, flakes, field, sweeps, occlusion):
    """`cell`: ground and cover cell (10 m each); the other arguments are the budget's limits."""
    doc = copy.deepcopy(BASE)
    sc = doc["scenes"][0]
    sc["name"] = name
    iterations = sweeps // (field[0] * field[1] * field[2])
    sc["extras"]["snow"] = {
        "simulation": {"dt": 1 / 60, "seed": 1, "max_flakes": flakes,
                       "bounds": {"min": [-6, -0.5, -6], "max": [6, 6, 6]}},
        "emitter": {"rate": 1.0e8, "snowfall_kg_m2_h": 15.0},
        "wind": {"base": [3, 0, 1], "field": {"cells": field, "pressure_iterations": iterations,
                                              "transport": {"roughness": 0.002}}},
        "occlusion": {"resolution": occlusion},
        "cover": {"min": [-5, -5], "max": [5, 5], "cell": cell}}
    doc["nodes"][0]["extras"]["snow"]["surface"]["cell"] = cell
    grid, grid_triangles = grid_mesh(doc)
    for i in range(surfaces - 1):  # one-cell roofs
        doc["nodes"].append({"mesh": 0, "translation": [(i % 32) * 0.3 - 5, 1 + (i // 32) * 0.05, (i // 32) * 0.3 - 5],
                             "scale": [0.01, 0.01, 0.01],
                             "extras": {"snow": {"collider": "box", "surface": {"cell": 0.01}}}})
    for i in range(bodies):
        doc["nodes"].append({"mesh": 0, "translation": [(i % 16) * 0.6 - 5, 0.3, (i // 16) * 0.6 - 5],
                             "scale": [0.2, 0.2, 0.2],
                             "extras": {"snow": {"snowball": True, "motion": {
                                 "waypoints": [[0, 0.3, 0], [1, 0.3, 0]], "speed": 2, "loop": True}}}})
    for i in range(triangles // grid_triangles):
        doc["nodes"].append({"mesh": grid, "translation": [(i % 16) * 0.6 - 5, 0.5 + i * 0.01, (i // 16) * 0.6 - 5],
                             "extras": {"snow": {"collider": "mesh"}}})
    sc["nodes"] = list(range(len(doc["nodes"])))
    json.dump(doc, open(path, "w"), separators=(",", ":"))

# Ground and cover hold 2^21 cells less the roofs' (1023 + 1023 <= spare).
scene("assets/testdata/at_default_budget.gltf", "at the default work budget", 0.0101, 1024, 64,
      1 << 18, 1 << 20, [64, 32, 64], 1 << 21, 1024)
scene("fuzz/corpus/gltf/at_fuzz_budget.gltf", "at the fuzz work budget", 0.04, 64, 8,
      1 << 14, 1 << 16, [32, 16, 32], 1 << 17, 256)

if len(sys.argv) == 3 and sys.argv[1] == "--large":
    out = sys.argv[2]
    os.makedirs(out, exist_ok=True)
    doc = json.load(open("assets/testdata/at_default_budget.gltf"))
    big = copy.deepcopy(doc)
    big["asset"]["extras"] = {"pad": [0.123456] * (1000000 - 60000)}
    pad = bytes(5 << 20)
    big["buffers"].append({"byteLength": len(pad), "uri": "data:application/octet-stream;base64,"
                           + base64.b64encode(pad).decode()})
    json.dump(big, open(os.path.join(out, "largest.gltf"), "w"), separators=(",", ":"))
    raw = bytearray(base64.b64decode(doc["buffers"][0].pop("uri").split(",", 1)[1]))
    raw += bytes(-len(raw) % 4)
    nv, ni = (1 << 22) - 100000, (1 << 24) - 300000
    verts = array.array("f", [0.0]) * (nv * 3)
    for i in range(0, nv * 3, 3):
        verts[i], verts[i + 2] = (i % 1000) * 0.001, (i // 1000 % 1000) * 0.001
    idx = array.array("I", (i % nv for i in range(ni)))
    off = len(raw)
    raw += verts.tobytes() + idx.tobytes()
    doc["buffers"][0]["byteLength"] = len(raw)
    views = doc["bufferViews"]
    views += [{"buffer": 0, "byteOffset": off, "byteLength": nv * 12},
              {"buffer": 0, "byteOffset": off + nv * 12, "byteLength": ni * 4}]
    acc = doc["accessors"]
    acc += [{"bufferView": len(views) - 2, "componentType": 5126, "count": nv, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 0, 1]},
            {"bufferView": len(views) - 1, "componentType": 5125, "count": ni, "type": "SCALAR"}]
    doc["meshes"].append({"primitives": [{"attributes": {"POSITION": len(acc) - 2}, "indices": len(acc) - 1}]})
    doc["nodes"].append({"mesh": len(doc["meshes"]) - 1})
    doc["scenes"][0]["nodes"].append(len(doc["nodes"]) - 1)
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(raw), b"BIN\0") + bytes(raw)
    with open(os.path.join(out, "largest.glb"), "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks)
