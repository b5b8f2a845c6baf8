#!/usr/bin/env python3
"""Writes a glTF UV sphere whose triangles are stored in random order, the
way some exporters leave large meshes (docs/results.md, "Triangle order").

  scripts/shuffled_mesh.py OUT.gltf [SEGMENTS [SEED]]

SEGMENTS around (and half as many rings, so 2 x SEGMENTS x (SEGMENTS/2 - 1)
triangles; 212 gives 44 520), shuffled with Python's Mersenne Twister from
SEED. The buffer is a data URI, so the file stands alone.
"""
import base64
import json
import math
import random
import struct
import sys


def main():
    out = sys.argv[1]
    segments = int(sys.argv[2]) if len(sys.argv) > 2 else 212
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    rings = segments // 2
    positions, normals = [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            positions.append(n)
            normals.append(n)
    triangles = []
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b, c, d = a + 1, a + segments + 1, a + segments + 2
            if r > 0:
                triangles.append((a, b, c))  # counter-clockwise seen from outside
            if r < rings - 1:
                triangles.append((b, d, c))
    random.Random(seed).shuffle(triangles)
    indices = [i for t in triangles for i in t]
    pos = struct.pack("<%df" % (3 * len(positions)), *[x for p in positions for x in p])
    nrm = struct.pack("<%df" % (3 * len(normals)), *[x for p in normals for x in p])
    idx = struct.pack("<%dI" % len(indices), *indices)
    data = pos + nrm + idx
    doc = {
        "asset": {"version": "2.0", "generator": "penumbra scripts/shuffled_mesh.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "shuffled sphere"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2,
                                    "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1],
                                                "metallicFactor": 0, "roughnessFactor": 0.5}}],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
            {"buffer": 0, "byteOffset": len(pos), "byteLength": len(nrm)},
            {"buffer": 0, "byteOffset": len(pos) + len(nrm), "byteLength": len(idx)},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": len(positions),
             "min": [-1, -1, -1], "max": [1, 1, 1]},
            {"bufferView": 1, "componentType": 5126, "type": "VEC3", "count": len(normals)},
            {"bufferView": 2, "componentType": 5125, "type": "SCALAR", "count": len(indices)},
        ],
    }
    with open(out, "w") as f:
        json.dump(doc, f)
    print("%s: %d triangles, shuffled with seed %d" % (out, len(triangles), seed))


if __name__ == "__main__":
    main()
