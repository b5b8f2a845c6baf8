#!/usr/bin/env python3
"""Writes a glTF scene for texture level of detail (docs/results.md, "Texture
level of detail"): a 200 m square floor tiled 100 times with a TEXELS x
TEXELS texture of random grey texels (sRGB PNG), seen from eye height
across it, so that most of the image minifies the texture, the worst case
for a GPU's texture caches without mipmaps.

  scripts/textured_floor.py OUT_DIR [TEXELS [SEED]]

OUT_DIR gets floor.gltf and floor.png (default 2048 texels, seed 1). No
lights: the default environment lights it.
"""
import base64
import json
import os
import random
import struct
import sys
import zlib


def png(path, size, seed):
    rng = random.Random(seed)
    rows = bytearray()
    for _ in range(size):
        rows.append(0)  # filter: none
        rows.extend(bytes(v for _ in range(size) for v in (rng.randrange(256),) * 3))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(bytes(rows), 6)))
        f.write(chunk(b"IEND", b""))


def main():
    out = sys.argv[1]
    size = int(sys.argv[2]) if len(sys.argv) > 2 else 2048
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    os.makedirs(out, exist_ok=True)
    png(os.path.join(out, "floor.png"), size, seed)
    half, tiles = 100.0, 100.0
    positions = [(-half, 0, -half), (half, 0, -half), (half, 0, half), (-half, 0, half)]
    uvs = [(0, 0), (tiles, 0), (tiles, tiles), (0, tiles)]
    indices = [0, 2, 1, 0, 3, 2]  # counter-clockwise seen from above
    data = b"".join(struct.pack("<3f", *p) for p in positions)
    data += b"".join(struct.pack("<3f", 0, 1, 0) for _ in positions)
    data += b"".join(struct.pack("<2f", *t) for t in uvs)
    data += b"".join(struct.pack("<H", i) for i in indices)
    views = [(0, 48), (48, 48), (96, 32), (128, 12)]
    gltf = {
        "asset": {"version": "2.0", "generator": "scripts/textured_floor.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [
            {"mesh": 0},
            # At 1.7 m, looking 10 degrees down (a rotation about +x).
            {"camera": 0, "translation": [0, 1.7, 90],
             "rotation": [-0.0871557, 0, 0, 0.9961947]},
        ],
        "cameras": [{"type": "perspective",
                     "perspective": {"yfov": 0.8, "znear": 0.1, "aspectRatio": 1.7778}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                    "indices": 3, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                                "metallicFactor": 0, "roughnessFactor": 0.6}}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"wrapS": 10497, "wrapT": 10497}],
        "images": [{"uri": "floor.png"}],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n} for o, n in views],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-half, 0, -half], "max": [half, 0, half]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
    }
    with open(os.path.join(out, "floor.gltf"), "w") as f:
        json.dump(gltf, f, indent=1)


if __name__ == "__main__":
    main()
