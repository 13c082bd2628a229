#!/usr/bin/env python3
"""Writes a .gltf whose one buffer is a base64 data URI as a .glb: the
buffer's bytes move into the BIN chunk (glTF 2.0, "GLB File Format
Specification"). Made fuzz/corpus/glb's seeds from assets/scenes."""
import base64
import json
import struct
import sys

src, dst = sys.argv[1], sys.argv[2]
doc = json.load(open(src))
uri = doc["buffers"][0].pop("uri")
binary = base64.b64decode(uri.split(",", 1)[1])
binary += b"\0" * (-len(binary) % 4)
text = json.dumps(doc, separators=(",", ":")).encode()
text += b" " * (-len(text) % 4)
chunks = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(binary), b"BIN\0") + binary
with open(dst, "wb") as out:
    out.write(struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks)
