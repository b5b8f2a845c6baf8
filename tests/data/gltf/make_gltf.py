#!/usr/bin/env python3
"""Writes the small hand-made glTF files the loader and renderer tests read.

Run from anywhere: `python3 tests/data/gltf/make_gltf.py`; it rewrites the
files next to itself. Every number the tests expect is derived by hand in the
test that uses the file, not read back from here.
"""
import base64
import json
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

FLOAT, UBYTE, USHORT, UINT, BYTE, SHORT = 5126, 5121, 5123, 5125, 5120, 5122
FORMATS = {FLOAT: "f", UBYTE: "B", USHORT: "H", UINT: "I", BYTE: "b", SHORT: "h"}
SIZES = {FLOAT: 4, UBYTE: 1, USHORT: 2, UINT: 4, BYTE: 1, SHORT: 2}
COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}


class Builder:
    """One glTF document with a single buffer that grows as views are added."""

    def __init__(self):
        self.doc = {"asset": {"version": "2.0", "generator": "penumbra tests/data/gltf/make_gltf.py"}}
        self.data = bytearray()

    def _list(self, key):
        return self.doc.setdefault(key, [])

    def view(self, raw, stride=None, align=4):
        while len(self.data) % align:
            self.data.append(0)
        v = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(raw)}
        if stride:
            v["byteStride"] = stride
        self.data += raw
        self._list("bufferViews").append(v)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, values, ctype=FLOAT, atype="VEC3", normalized=False, view=None, offset=0,
                 count=None, minmax=False):
        """values: flat list; packs them into a new view unless `view` is given."""
        n = COMPONENTS[atype]
        if view is None:
            view = self.view(struct.pack("<%d%s" % (len(values), FORMATS[ctype]), *values))
        a = {"bufferView": view, "componentType": ctype, "type": atype,
             "count": count if count is not None else len(values) // n}
        if offset:
            a["byteOffset"] = offset
        if normalized:
            a["normalized"] = True
        if minmax:
            a["min"] = [min(values[i::n]) for i in range(n)]
            a["max"] = [max(values[i::n]) for i in range(n)]
        self._list("accessors").append(a)
        return len(self.doc["accessors"]) - 1

    def add(self, key, item):
        self._list(key).append(item)
        return len(self.doc[key]) - 1

    def finish_embedded(self):
        uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.data)).decode()
        self.doc["buffers"] = [{"byteLength": len(self.data), "uri": uri}]
        return self.doc

    def write_gltf(self, name):
        write_json(name, self.finish_embedded())

    def write_external(self, name, bin_name):
        self.doc["buffers"] = [{"byteLength": len(self.data), "uri": bin_name}]
        write_json(name, self.doc)
        with open(os.path.join(HERE, bin_name), "wb") as f:
            f.write(self.data)

    def write_glb(self, name):
        self.doc["buffers"] = [{"byteLength": len(self.data)}]
        text = json.dumps(self.doc, separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        binary = bytes(self.data) + b"\0" * (-len(self.data) % 4)
        total = 12 + 8 + len(text) + 8 + len(binary)
        out = struct.pack("<III", 0x46546C67, 2, total)
        out += struct.pack("<II", len(text), 0x4E4F534A) + text
        out += struct.pack("<II", len(binary), 0x004E4942) + binary
        with open(os.path.join(HERE, name), "wb") as f:
            f.write(out)


def write_json(name, doc):
    with open(os.path.join(HERE, name), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def write_text(name, text):
    with open(os.path.join(HERE, name), "w") as f:
        f.write(text)


TRIANGLE = [0, 0, 0, 1, 0, 0, 0, 1, 0]


def triangle_file():
    """One triangle (0,0,0) (1,0,0) (0,1,0), indexed, one node."""
    b = Builder()
    pos = b.accessor(TRIANGLE, minmax=True)
    idx = b.accessor([0, 1, 2], USHORT, "SCALAR")
    b.add("meshes", {"name": "tri", "primitives": [{"attributes": {"POSITION": pos}, "indices": idx}]})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.doc["scene"] = 0
    return b


def transforms():
    """Instancing and node transforms: mesh 'tri' under a TRS parent, the same
    mesh under a matrix node and a TRS node that mean the same transform, and a
    two-primitive mesh."""
    b = Builder()
    pos = b.accessor(TRIANGLE, minmax=True)
    nrm = b.accessor([0, 0, 1] * 3)
    idx = b.accessor([0, 1, 2], USHORT, "SCALAR")
    prim = {"attributes": {"POSITION": pos, "NORMAL": nrm}, "indices": idx}
    b.add("meshes", {"name": "tri", "primitives": [prim]})
    b.add("meshes", {"name": "pair", "primitives": [prim, dict(prim)]})
    s, c = math.sin(math.pi / 4), math.cos(math.pi / 4)
    # parent: translate (10,0,0), rotate 90 degrees about +z, scale 2.
    b.add("nodes", {"name": "parent", "translation": [10, 0, 0], "rotation": [0, 0, s, c],
                    "scale": [2, 2, 2], "children": [1]})
    b.add("nodes", {"name": "child", "translation": [0, 0, 1], "mesh": 0})
    # The parent's transform as a column-major matrix.
    b.add("nodes", {"name": "matrix", "mesh": 0,
                    "matrix": [0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 10, 0, 0, 1]})
    b.add("nodes", {"name": "trs", "mesh": 0, "translation": [10, 0, 0], "rotation": [0, 0, s, c],
                    "scale": [2, 2, 2]})
    b.add("nodes", {"name": "pair", "mesh": 1, "translation": [0, 5, 0]})
    b.doc["scenes"] = [{"nodes": [0, 2, 3, 4]}]
    b.doc["scene"] = 0
    b.write_gltf("transforms.gltf")


def sparse():
    """POSITION of 4 vertices with a sparse substitution of vertices 1 and 3,
    and a TEXCOORD_0 with no buffer view (zeros) and one sparse value."""
    b = Builder()
    base = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]
    view = b.view(struct.pack("<12f", *base))
    sidx = b.view(struct.pack("<2H", 1, 3))
    sval = b.view(struct.pack("<6f", 2, 0, 0, 0, 3, 0))
    b.doc.setdefault("accessors", []).append({
        "bufferView": view, "componentType": FLOAT, "type": "VEC3", "count": 4,
        "min": [0, 0, 0], "max": [2, 3, 0],
        "sparse": {"count": 2, "indices": {"bufferView": sidx, "componentType": USHORT},
                   "values": {"bufferView": sval}}})
    uidx = b.view(struct.pack("<B", 2), align=1)
    uval = b.view(struct.pack("<2f", 0.25, 0.75))
    b.doc["accessors"].append({
        "componentType": FLOAT, "type": "VEC2", "count": 4,
        "sparse": {"count": 1, "indices": {"bufferView": uidx, "componentType": UBYTE},
                   "values": {"bufferView": uval}}})
    idx = b.accessor([0, 1, 2, 0, 2, 3], UBYTE, "SCALAR")
    b.add("meshes", {"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": idx}]})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.write_gltf("sparse.gltf")


def attributes():
    """Normalized integer attributes and byte strides. Primitive 0: positions
    and normals interleaved (stride 24), TEXCOORD_0 as normalized unsigned
    bytes in a view of stride 4 (2 bytes padding each). Primitive 1:
    TEXCOORD_0 as normalized unsigned shorts, TANGENT as normalized signed
    shorts, NORMAL as normalized signed bytes (stride 4)."""
    b = Builder()
    inter = []
    for p in ([0, 0, 0], [1, 0, 0], [0, 1, 0]):
        inter += p + [0, 0, 1]
    v = b.view(struct.pack("<18f", *inter), stride=24)
    pos = b.accessor(None or [], FLOAT, "VEC3", view=v, count=3)
    b.doc["accessors"][pos]["min"] = [0, 0, 0]
    b.doc["accessors"][pos]["max"] = [1, 1, 0]
    nrm = b.accessor([], FLOAT, "VEC3", view=v, offset=12, count=3)
    uv8 = b.view(struct.pack("<12B", 0, 255, 9, 9, 255, 0, 9, 9, 128, 51, 9, 9), stride=4)
    uvb = b.accessor([], UBYTE, "VEC2", normalized=True, view=uv8, count=3)
    b.add("meshes", {"primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm, "TEXCOORD_0": uvb}}]})

    uvs = b.accessor([0, 65535, 32768, 0, 65535, 13107], USHORT, "VEC2", normalized=True)
    tan = b.accessor([32767, 0, 0, -32768, 0, 32767, 0, -32767, 0, 0, -32768, -32768], SHORT, "VEC4",
                     normalized=True)
    n8 = b.view(struct.pack("<12b", 0, 0, 127, 0, 0, 0, 127, 0, -128, 0, 0, 0), stride=4)
    nb = b.accessor([], BYTE, "VEC3", normalized=True, view=n8, count=3)
    b.add("meshes", {"primitives": [{"attributes": {"POSITION": pos, "NORMAL": nb, "TEXCOORD_0": uvs,
                                                    "TANGENT": tan}}]})
    b.add("nodes", {"mesh": 0})
    b.add("nodes", {"mesh": 1})
    b.doc["scenes"] = [{"nodes": [0, 1]}]
    b.write_gltf("attributes.gltf")


def vertex_colors():
    """COLOR_0 as glTF allows it: primitive 0 (the unit triangle) with RGB as
    normalized unsigned bytes (255, 0, 0), (0, 255, 0), (0, 0, 51); primitive 1
    with RGBA floats (0.25, 0.5, 0.75, 0.5) at every corner, one corner's
    red out of range (1.5, clamped to 1)."""
    b = Builder()
    pos = b.accessor(TRIANGLE, minmax=True)
    rgb = b.view(struct.pack("<12B", 255, 0, 0, 0, 0, 255, 0, 0, 0, 0, 51, 0), stride=4)
    c8 = b.accessor([], UBYTE, "VEC3", normalized=True, view=rgb, count=3)
    cf = b.accessor([1.5, 0.5, 0.75, 0.5] + [0.25, 0.5, 0.75, 0.5] * 2, FLOAT, "VEC4")
    b.add("meshes", {"primitives": [{"attributes": {"POSITION": pos, "COLOR_0": c8}},
                                    {"attributes": {"POSITION": pos, "COLOR_0": cf}}]})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.write_gltf("vertex_colors.gltf")


def mesh_quantization():
    """KHR_mesh_quantization (required): a unit quad stored as integers.
    POSITION as signed shorts (not normalized) 0 or 1000, stride 8, under a
    node that scales by 0.001 and moves by (0, 0, 5); NORMAL as normalized
    signed bytes (0, 0, 127); TANGENT as normalized signed bytes
    (127, 0, 0, -128); TEXCOORD_0 as unsigned bytes, not normalized, 0 or 1.
    Vertices: (0,0), (1000,0), (0,1000), (1000,1000); triangles 0 1 2, 1 3 2."""
    b = Builder()
    corners = [(0, 0), (1000, 0), (0, 1000), (1000, 1000)]
    pv = b.view(b"".join(struct.pack("<4h", x, y, 0, 0) for x, y in corners), stride=8)
    pos = b.accessor([], SHORT, "VEC3", view=pv, count=4)
    b.doc["accessors"][pos]["min"] = [0, 0, 0]
    b.doc["accessors"][pos]["max"] = [1000, 1000, 0]
    nv = b.view(struct.pack("<16b", *([0, 0, 127, 0] * 4)), stride=4)
    nrm = b.accessor([], BYTE, "VEC3", normalized=True, view=nv, count=4)
    tan = b.accessor([127, 0, 0, -128] * 4, BYTE, "VEC4", normalized=True)
    uvv = b.view(struct.pack("<16B", *[c for x, y in corners for c in (x // 1000, y // 1000, 0, 0)]),
                 stride=4)
    uv = b.accessor([], UBYTE, "VEC2", view=uvv, count=4)
    idx = b.accessor([0, 1, 2, 1, 3, 2], UBYTE, "SCALAR")
    b.add("meshes", {"primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm, "TANGENT": tan,
                                                    "TEXCOORD_0": uv}, "indices": idx}]})
    b.add("nodes", {"mesh": 0, "scale": [0.001, 0.001, 0.001], "translation": [0, 0, 5]})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.doc["extensionsUsed"] = ["KHR_mesh_quantization"]
    b.doc["extensionsRequired"] = ["KHR_mesh_quantization"]
    b.write_gltf("mesh_quantization.gltf")


def gpu_instancing():
    """EXT_mesh_gpu_instancing: the unit triangle under a node at (10, 0, 0)
    drawn three times: as is; turned 90 degrees about +z and moved by
    (2, 0, 0); scaled by 2 and moved by (0, 3, 0). And a file whose
    attributes disagree on the count (3 translations, 2 scales)."""
    def build(scales):
        b = triangle_file()
        t = b.accessor([0, 0, 0, 2, 0, 0, 0, 3, 0], FLOAT, "VEC3")
        h = math.sqrt(0.5)
        r = b.accessor([0, 0, 0, 1, 0, 0, h, h, 0, 0, 0, 1], FLOAT, "VEC4")
        sc = b.accessor(scales, FLOAT, "VEC3")
        b.doc["nodes"] = [{"mesh": 0, "translation": [10, 0, 0], "extensions": {
            "EXT_mesh_gpu_instancing": {"attributes": {"TRANSLATION": t, "ROTATION": r, "SCALE": sc}}}}]
        b.doc["extensionsUsed"] = ["EXT_mesh_gpu_instancing"]
        b.doc["extensionsRequired"] = ["EXT_mesh_gpu_instancing"]
        return b
    build([1, 1, 1, 1, 1, 1, 2, 2, 2]).write_gltf("gpu_instancing.gltf")
    build([1, 1, 1, 2, 2, 2]).write_gltf("invalid_instancing_counts.gltf")


def generated():
    """Primitive 0: a folded pair of triangles without NORMAL (flat normals).
    Primitive 1: a quad in the xy plane with +z normals and the usual UV
    layout (v down), no TANGENT. Primitive 2: the same with u mirrored.
    Primitive 3: the quad with normals tilted to (0.6, 0, 0.8)."""
    b = Builder()
    fold = b.accessor([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1], minmax=True)
    fidx = b.accessor([0, 1, 2, 1, 3, 2], USHORT, "SCALAR")
    quad = b.accessor([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], minmax=True)
    up = b.accessor([0, 0, 1] * 4)
    tilted = b.accessor([0.6, 0, 0.8] * 4)
    uv = b.accessor([0, 1, 1, 1, 1, 0, 0, 0], atype="VEC2")
    mirrored = b.accessor([1, 1, 0, 1, 0, 0, 1, 0], atype="VEC2")
    qidx = b.accessor([0, 1, 2, 0, 2, 3], USHORT, "SCALAR")
    b.add("meshes", {"primitives": [
        {"attributes": {"POSITION": fold, "TEXCOORD_0": uv}, "indices": fidx},
        {"attributes": {"POSITION": quad, "NORMAL": up, "TEXCOORD_0": uv}, "indices": qidx},
        {"attributes": {"POSITION": quad, "NORMAL": up, "TEXCOORD_0": mirrored}, "indices": qidx},
        {"attributes": {"POSITION": quad, "NORMAL": tilted, "TEXCOORD_0": uv}, "indices": qidx}]})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.write_gltf("generated.gltf")


def containers():
    """The same triangle as .glb, as .gltf with an external .bin, and embedded."""
    triangle_file().write_glb("triangle.glb")
    triangle_file().write_external("external.gltf", "external.bin")
    triangle_file().write_gltf("embedded.gltf")


def materials():
    """One primitive per material; each material exercises one extension."""
    b = Builder()
    pos = b.accessor(TRIANGLE, minmax=True)
    mats = [
        {"name": "base", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1, 1],
                                                  "metallicFactor": 0.3, "roughnessFactor": 0.7}},
        {"name": "emissive", "emissiveFactor": [1, 0.5, 0.25],
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}},
        {"name": "glass", "extensions": {"KHR_materials_transmission": {"transmissionFactor": 0.9},
                                         "KHR_materials_ior": {"ior": 1.33}}},
        {"name": "volume", "extensions": {
            "KHR_materials_transmission": {"transmissionFactor": 1},
            "KHR_materials_volume": {"thicknessFactor": 0.5, "attenuationDistance": 2,
                                     "attenuationColor": [1, 0.5, 0.5]},
            "KHR_materials_dispersion": {"dispersion": 0.4}}},
        {"name": "coat", "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 0.8,
                                                                    "clearcoatRoughnessFactor": 0.2}}},
        {"name": "specular", "extensions": {"KHR_materials_specular": {
            "specularFactor": 0.5, "specularColorFactor": [10, 1, 0.2]},
            "KHR_materials_ior": {"ior": 2}}},
        {"name": "sheen", "extensions": {"KHR_materials_sheen": {
            "sheenColorFactor": [0.2, 0.6, 0.4], "sheenRoughnessFactor": 0.5}}},
        {"name": "mask", "alphaMode": "MASK", "alphaCutoff": 0.5,
         "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 0.2]}},
        {"name": "defaults"},
    ]
    b.doc["materials"] = mats
    prims = [{"attributes": {"POSITION": pos}, "material": i} for i in range(len(mats))]
    prims.append({"attributes": {"POSITION": pos}})  # no material: glTF's default
    b.add("meshes", {"primitives": prims})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.doc["extensionsUsed"] = sorted({k for m in mats for k in m.get("extensions", {})})
    b.write_gltf("materials.gltf")


def cameras():
    """Cameras: node 1 'front' (camera 1 'second', 5 m along +z), node 2 'side'
    (camera 0 'first', at (5,0,0) turned 90 degrees about +y), node 3 'flat'
    (camera 2 'ortho', orthographic, 3 m wide and 2 m tall, 2 m above the
    origin looking down)."""
    b = triangle_file()
    b.doc["cameras"] = [
        {"name": "first", "type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.1}},
        {"name": "second", "type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1,
                                                                  "aspectRatio": 1.5}},
        {"name": "ortho", "type": "orthographic",
         "orthographic": {"xmag": 1.5, "ymag": 1, "znear": 0.1, "zfar": 10}},
    ]
    s, c = math.sin(math.pi / 4), math.cos(math.pi / 4)
    b.add("nodes", {"name": "front", "camera": 1, "translation": [0, 0, 5]})
    b.add("nodes", {"name": "side", "camera": 0, "translation": [5, 0, 0], "rotation": [0, s, 0, c]})
    b.add("nodes", {"name": "flat", "camera": 2, "translation": [0, 2, 0],
                    "rotation": [-s, 0, 0, c]})
    # Scene order differs from node order: the default view follows node order.
    b.doc["scenes"] = [{"nodes": [3, 2, 0, 1]}]
    b.write_gltf("cameras.gltf")


def extensions():
    b = triangle_file()
    b.doc["extensionsUsed"] = ["KHR_texture_basisu"]
    b.doc["extensionsRequired"] = ["KHR_texture_basisu"]
    b.write_gltf("extension_required.gltf")
    # As such files are: the texture's only source is a KTX2 image (which is
    # not there).
    b = triangle_file()
    b.doc["extensionsUsed"] = ["KHR_texture_basisu"]
    b.doc["extensionsRequired"] = ["KHR_texture_basisu"]
    b.doc["images"] = [{"uri": "missing.ktx2", "mimeType": "image/ktx2"}]
    b.doc["textures"] = [{"extensions": {"KHR_texture_basisu": {"source": 0}}}]
    b.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    b.doc["meshes"][0]["primitives"][0]["material"] = 0
    b.write_gltf("extension_required_compressed.gltf")
    b = triangle_file()
    b.doc["extensionsUsed"] = ["KHR_materials_pbrSpecularGlossiness", "KHR_materials_clearcoat"]
    b.write_gltf("extension_optional.gltf")
    # Dispersion on thin glass (no volume) bends nothing: warned about.
    b = triangle_file()
    b.doc["materials"] = [{"name": "thin glass", "extensions": {
        "KHR_materials_transmission": {"transmissionFactor": 1},
        "KHR_materials_dispersion": {"dispersion": 0.5}}}]
    b.doc["meshes"][0]["primitives"][0]["material"] = 0
    b.doc["extensionsUsed"] = ["KHR_materials_dispersion", "KHR_materials_transmission"]
    b.write_gltf("dispersion_thin.gltf")


def invalid():
    """Files that must fail with one clear error each."""
    good = json.dumps(triangle_file().finish_embedded(), indent=1)
    write_text("invalid_truncated.gltf", good[: len(good) // 2])

    b = triangle_file()
    b.doc["accessors"][0]["count"] = 4  # 48 bytes from a 36-byte view
    b.write_gltf("invalid_accessor_range.gltf")

    b = triangle_file()
    b.finish_embedded()
    b.doc["bufferViews"][1]["byteOffset"] = 64  # past the end of the 42-byte buffer
    write_json("invalid_short_buffer.gltf", b.doc)

    b = triangle_file()
    b.doc["buffers"] = [{"byteLength": len(b.data), "uri": "missing.bin"}]
    write_json("invalid_missing_buffer.gltf", b.doc)

    b = triangle_file()
    b.doc["images"] = [{"uri": "missing.png"}]
    b.doc["textures"] = [{"source": 0}]
    b.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    b.doc["meshes"][0]["primitives"][0]["material"] = 0
    b.write_gltf("invalid_missing_image.gltf")

    b = Builder()
    pos = b.accessor(TRIANGLE, minmax=True)
    idx = b.accessor([0, 1, 7], USHORT, "SCALAR")
    b.add("meshes", {"primitives": [{"attributes": {"POSITION": pos}, "indices": idx}]})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.write_gltf("invalid_index.gltf")

    b = triangle_file()
    b.doc["nodes"] = [{"mesh": 0, "children": [1]}, {"name": "loop", "children": [0]}]
    b.write_gltf("invalid_cycle.gltf")

    b = Builder()
    pos = b.accessor([0, 0, 0, 1, float("nan"), 0, 0, 1, 0])
    b.doc["accessors"][pos]["min"] = [0, 0, 0]
    b.doc["accessors"][pos]["max"] = [1, 1, 0]
    b.add("meshes", {"primitives": [{"attributes": {"POSITION": pos}}]})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.write_gltf("invalid_nan.gltf")

    b = triangle_file()
    b.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9
    b.write_gltf("invalid_accessor_index.gltf")

    # An orthographic view 2e-40 m tall: below the smallest float.
    b = triangle_file()
    b.doc["cameras"] = [{"type": "orthographic",
                         "orthographic": {"xmag": 1, "ymag": 1e-40, "znear": 0, "zfar": 10}}]
    b.add("nodes", {"camera": 0, "translation": [0, 0, 2]})
    b.doc["scenes"] = [{"nodes": [0, 1]}]
    b.write_gltf("invalid_orthographic_height.gltf")

    b = triangle_file()
    b.doc["materials"] = [{"name": "tinted", "extensions": {
        "KHR_materials_specular": {"specularColorFactor": [1, -0.5, 1]}}}]
    b.doc["extensionsUsed"] = ["KHR_materials_specular"]
    b.doc["meshes"][0]["primitives"][0]["material"] = 0
    b.write_gltf("invalid_specular_color.gltf")


def quad(b, corners, normal):
    """A quad (two triangles v0 v1 v2, v0 v2 v3) with one normal."""
    pos = b.accessor([c for p in corners for c in p], minmax=True)
    nrm = b.accessor(list(normal) * 4)
    idx = b.accessor([0, 1, 2, 0, 2, 3], USHORT, "SCALAR")
    return {"attributes": {"POSITION": pos, "NORMAL": nrm}, "indices": idx}


def emissive_quad():
    """A 1 m square light facing down 1 m above a grey floor (albedo 0.5),
    emitting radiance 2.5 x 4 = 10, and a camera looking at the floor under
    the light's centre from the side with a narrow field of view."""
    b = Builder()
    b.doc["materials"] = [
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1],
                                                   "metallicFactor": 0, "roughnessFactor": 1},
         "extensions": {"KHR_materials_specular": {"specularFactor": 0}}},
        {"name": "light", "emissiveFactor": [2.5, 2.5, 2.5],
         "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0},
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}},
    ]
    b.doc["extensionsUsed"] = ["KHR_materials_emissive_strength", "KHR_materials_specular"]
    floor = quad(b, [(-20, 0, 20), (20, 0, 20), (20, 0, -20), (-20, 0, -20)], (0, 1, 0))
    floor["material"] = 0
    # Counter-clockwise seen from below: the emitting face points down.
    light = quad(b, [(-0.5, 1, -0.5), (0.5, 1, -0.5), (0.5, 1, 0.5), (-0.5, 1, 0.5)], (0, -1, 0))
    light["material"] = 1
    b.add("meshes", {"name": "floor", "primitives": [floor]})
    b.add("meshes", {"name": "light", "primitives": [light]})
    b.add("nodes", {"mesh": 0})
    b.add("nodes", {"mesh": 1})
    b.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.02, "znear": 0.01}}]
    # At (0, 0.5, 2) looking at the origin: rotated about +x by -atan(0.5 / 2).
    a = -math.atan2(0.5, 2) / 2
    b.add("nodes", {"name": "view", "camera": 0, "translation": [0, 0.5, 2],
                    "rotation": [math.sin(a), 0, 0, math.cos(a)]})
    b.doc["scenes"] = [{"nodes": [0, 1, 2]}]
    b.write_gltf("emissive_quad.gltf")


def spheres():
    """A UV sphere of radius 1 (12 x 8 segments), with smooth normals
    (sphere_smooth.gltf) and without normals (sphere_flat.gltf: flat)."""
    rows, cols = 8, 12
    pos, nrm = [], []
    for r in range(rows + 1):
        theta = math.pi * r / rows
        for c in range(cols + 1):
            phi = 2 * math.pi * c / cols
            p = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            pos += p
            nrm += p
    idx = []
    for r in range(rows):
        for c in range(cols):
            a, b_, d, e = r * (cols + 1) + c, r * (cols + 1) + c + 1, (r + 1) * (cols + 1) + c, (r + 1) * (cols + 1) + c + 1
            # Counter-clockwise seen from outside.
            idx += [a, d, e, a, e, b_]
    for name, with_normals in (("sphere_smooth.gltf", True), ("sphere_flat.gltf", False)):
        b = Builder()
        attrs = {"POSITION": b.accessor(pos, minmax=True)}
        if with_normals:
            attrs["NORMAL"] = b.accessor(nrm)
        i = b.accessor(idx, USHORT, "SCALAR")
        b.doc["materials"] = [{"name": "grey", "pbrMetallicRoughness": {
            "baseColorFactor": [0.8, 0.8, 0.8, 1], "metallicFactor": 0, "roughnessFactor": 1}}]
        b.add("meshes", {"primitives": [{"attributes": attrs, "indices": i, "material": 0}]})
        b.add("nodes", {"mesh": 0})
        b.doc["scenes"] = [{"nodes": [0]}]
        b.write_gltf(name)


def leak():
    """A 2 m floor (y = 0, front +y) in two strips whose vertex normals lean
    away from the geometric normal: (0.8, 0.6, 0), 53 degrees off but above
    the horizon, and (0.8, -0.6, 0), below it."""
    b = Builder()
    b.doc["materials"] = [{"name": "white", "pbrMetallicRoughness": {
        "baseColorFactor": [0.8, 0.8, 0.8, 1], "metallicFactor": 0, "roughnessFactor": 0.5}}]
    left = quad(b, [(-1, 0, 1), (0, 0, 1), (0, 0, -1), (-1, 0, -1)], (0.8, 0.6, 0))
    right = quad(b, [(0, 0, 1), (1, 0, 1), (1, 0, -1), (0, 0, -1)], (0.8, -0.6, 0))
    left["material"] = right["material"] = 0
    b.add("meshes", {"primitives": [left, right]})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.write_gltf("leak.gltf")


def modes():
    """A unit square as POINTS, LINES, TRIANGLE_STRIP (corners in zigzag
    order) and TRIANGLE_FAN (corners in counter-clockwise order)."""
    b = Builder()
    zigzag = b.accessor([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0], minmax=True)
    cyclic = b.accessor([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], minmax=True)
    b.add("meshes", {"primitives": [{"attributes": {"POSITION": zigzag}, "mode": 0},
                                    {"attributes": {"POSITION": zigzag}, "mode": 1},
                                    {"attributes": {"POSITION": zigzag}, "mode": 5},
                                    {"attributes": {"POSITION": cyclic}, "mode": 6}]})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.write_gltf("modes.gltf")


PNG_GREY, PNG_RGB, PNG_GREY_ALPHA, PNG_RGBA = 0, 2, 4, 6
PNG_CHANNELS = {PNG_GREY: 1, PNG_RGB: 3, PNG_GREY_ALPHA: 2, PNG_RGBA: 4}


def png(width, height, samples, color_type=PNG_RGBA, bits=8):
    """A PNG (no filters, not interlaced) of `samples`: every channel of every
    pixel, rows top first, 8- or 16-bit values (16-bit stored big-endian)."""
    import zlib
    row = width * PNG_CHANNELS[color_type]
    fmt = ">%d%s" % (row, "B" if bits == 8 else "H")
    raw = b"".join(b"\0" + struct.pack(fmt, *samples[y * row:(y + 1) * row]) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    header = struct.pack(">IIBBBBB", width, height, bits, color_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw))
            + chunk(b"IEND", b""))


def png_rgba(width, height, pixels):
    """A PNG of 8-bit RGBA pixels (rows top first)."""
    return png(width, height, pixels)


def data_uri(png_bytes):
    return "data:image/png;base64," + base64.b64encode(png_bytes).decode()


def write_binary(name, data):
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)


def textured():
    """A triangle whose material has a base-colour texture (a 2 x 2 PNG in a data URI)."""
    b = triangle_file()
    png = png_rgba(2, 2, [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255])
    b.doc["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(png).decode()}]
    b.doc["textures"] = [{"source": 0}]
    b.doc["materials"] = [{"name": "painted",
                           "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                                    "baseColorFactor": [0.5, 0.5, 0.5, 1]}}]
    b.doc["meshes"][0]["primitives"][0]["material"] = 0
    b.write_gltf("textured.gltf")


# glTF enums for samplers.
NEAREST, LINEAR = 9728, 9729
NEAREST_MIPMAP_NEAREST, LINEAR_MIPMAP_NEAREST = 9984, 9985
NEAREST_MIPMAP_LINEAR, LINEAR_MIPMAP_LINEAR = 9986, 9987
REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE = 10497, 33648, 33071

# The 2 x 2 RGBA8 image of textures.gltf and textures.glb, rows top first:
# red, half-transparent green / transparent blue, (10, 20, 30, 40).
CHECKER_2X2 = [255, 0, 0, 255, 0, 255, 0, 128,
               0, 0, 255, 0, 10, 20, 30, 40]


def unit_quad(b, uv1=False):
    """The unit square in z = 0 facing +z, uv0 with v down (the image upright
    seen from +z), uv1 the middle half of that."""
    attrs = {"POSITION": b.accessor([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], minmax=True),
             "NORMAL": b.accessor([0, 0, 1] * 4),
             "TEXCOORD_0": b.accessor([0, 1, 1, 1, 1, 0, 0, 0], atype="VEC2")}
    if uv1:
        attrs["TEXCOORD_1"] = b.accessor([0.25, 0.75, 0.75, 0.75, 0.75, 0.25, 0.25, 0.25],
                                         atype="VEC2")
    return {"attributes": attrs, "indices": b.accessor([0, 1, 2, 0, 2, 3], USHORT, "SCALAR")}


def textures():
    """textures.gltf: images of every PNG layout, samplers, texture infos with
    KHR_texture_transform, alpha modes. Primitive 0 (material 'painted') has
    TEXCOORD_0 and TEXCOORD_1, primitive 1 ('transformed') only TEXCOORD_0."""
    write_binary("textures_rgba.png", png(2, 2, CHECKER_2X2))
    b = Builder()
    painted = unit_quad(b, uv1=True)
    painted["material"] = 0
    transformed = unit_quad(b)
    transformed["material"] = 1
    b.add("meshes", {"primitives": [painted, transformed]})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.doc["images"] = [
        {"name": "checker", "uri": "textures_rgba.png"},
        # grey 8-bit, 3 x 1: 0, 128, 255
        {"name": "grey", "uri": data_uri(png(3, 1, [0, 128, 255], PNG_GREY))},
        # grey + alpha 8-bit, 2 x 1: (50, 100), (200, 250)
        {"name": "greyAlpha", "uri": data_uri(png(2, 1, [50, 100, 200, 250], PNG_GREY_ALPHA))},
        # rgb 8-bit, 1 x 2: (1, 2, 3) over (250, 251, 252)
        {"name": "rgb", "uri": data_uri(png(1, 2, [1, 2, 3, 250, 251, 252], PNG_RGB))},
        # rgba 16-bit, 2 x 1. 25829 * 255 / 65535 = 100.502 (rounds to 101,
        # while the high byte is 100), 25828 -> 100.498, 32768 -> 127.502,
        # 32767 -> 127.498, 257 -> 1.
        {"name": "rgba16", "uri": data_uri(png(2, 1, [65535, 25829, 25828, 0, 257, 32768, 32767, 65535],
                                               PNG_RGBA, 16))},
        # grey 16-bit, 1 x 1: 25829
        {"name": "grey16", "uri": data_uri(png(1, 1, [25829], PNG_GREY, 16))},
    ]
    b.doc["samplers"] = [
        {"magFilter": NEAREST, "minFilter": NEAREST_MIPMAP_LINEAR, "wrapS": CLAMP_TO_EDGE,
         "wrapT": MIRRORED_REPEAT},
        {"magFilter": LINEAR, "minFilter": LINEAR_MIPMAP_NEAREST, "wrapS": MIRRORED_REPEAT,
         "wrapT": REPEAT},
        {},
        {"minFilter": NEAREST_MIPMAP_NEAREST},
    ]
    b.doc["textures"] = [
        {"source": 0, "sampler": 0},
        {"source": 0},
        {"source": 0, "sampler": 1},
        {"source": 1, "sampler": 2},
        {"source": 2, "sampler": 3},
        {"source": 3},
        {"source": 4},
        {"source": 5},
    ]
    transform = {"offset": [0.25, -0.5], "rotation": 0.5, "scale": [2, 3], "texCoord": 1}
    b.doc["materials"] = [
        {"name": "painted", "alphaMode": "MASK", "alphaCutoff": 0.3, "emissiveFactor": [1, 1, 1],
         "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "baseColorFactor": [1, 1, 1, 0.2],
                                  "metallicRoughnessTexture": {"index": 1}},
         "normalTexture": {"index": 1, "scale": 0.75},
         "emissiveTexture": {"index": 0},
         "occlusionTexture": {"index": 1, "texCoord": 1, "strength": 0.25}},
        {"name": "transformed", "emissiveFactor": [1, 1, 1],
         "pbrMetallicRoughness": {
             "baseColorTexture": {"index": 2, "texCoord": 0,
                                  "extensions": {"KHR_texture_transform": transform}},
             "metallicRoughnessTexture": {"index": 1, "texCoord": 5}},
         "emissiveTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"rotation": math.pi / 2}}},
         "occlusionTexture": {"index": 1, "texCoord": 1}},
        {"name": "grey", "pbrMetallicRoughness": {"baseColorTexture": {"index": 3}}},
        {"name": "greyAlpha", "pbrMetallicRoughness": {"baseColorTexture": {"index": 4}}},
        {"name": "rgb", "pbrMetallicRoughness": {"baseColorTexture": {"index": 5}}},
        {"name": "rgba16", "pbrMetallicRoughness": {"baseColorTexture": {"index": 6}}},
        {"name": "grey16", "pbrMetallicRoughness": {"baseColorTexture": {"index": 7}}},
        {"name": "blend", "alphaMode": "BLEND", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
        {"name": "coated", "extensions": {
            "KHR_materials_clearcoat": {
                "clearcoatFactor": 0.5, "clearcoatTexture": {"index": 1},
                "clearcoatRoughnessTexture": {"index": 1},
                "clearcoatNormalTexture": {"index": 1, "texCoord": 1, "scale": 0.6}},
            # Not read: warned about.
            "KHR_materials_volume": {"thicknessFactor": 0.5, "thicknessTexture": {"index": 1}}}},
        {"name": "layered", "extensions": {
            "KHR_materials_sheen": {"sheenColorFactor": [1, 1, 1], "sheenColorTexture": {"index": 3},
                                    "sheenRoughnessTexture": {"index": 1}},
            "KHR_materials_specular": {"specularTexture": {"index": 4},
                                       "specularColorTexture": {"index": 5}},
            "KHR_materials_transmission": {
                "transmissionFactor": 1,
                "transmissionTexture": {"index": 1, "texCoord": 1, "extensions": {
                    "KHR_texture_transform": {"offset": [0.5, 0]}}}},
            "KHR_materials_diffuse_transmission": {
                "diffuseTransmissionFactor": 0.25, "diffuseTransmissionTexture": {"index": 4},
                "diffuseTransmissionColorFactor": [0.5, 1, 1],
                "diffuseTransmissionColorTexture": {"index": 5}}}},
        {"name": "brushed", "pbrMetallicRoughness": {"metallicFactor": 1, "roughnessFactor": 0.2},
         "extensions": {"KHR_materials_anisotropy": {
             "anisotropyStrength": 0.6, "anisotropyRotation": 7.0,
             "anisotropyTexture": {"index": 1, "texCoord": 1}},
             "KHR_materials_iridescence": {
                 "iridescenceFactor": 0.7, "iridescenceIor": 1.8, "iridescenceThicknessMinimum": 50,
                 "iridescenceThicknessMaximum": 600, "iridescenceTexture": {"index": 4},
                 "iridescenceThicknessTexture": {"index": 1, "texCoord": 1}}}},
    ]
    b.doc["extensionsUsed"] = ["KHR_materials_clearcoat", "KHR_materials_sheen", "KHR_materials_specular",
                               "KHR_materials_transmission", "KHR_materials_anisotropy",
                               "KHR_materials_volume", "KHR_materials_diffuse_transmission",
                               "KHR_materials_iridescence", "KHR_texture_transform"]
    b.write_gltf("textures.gltf")

    # The checker again, stored in the .glb's binary chunk.
    b = Builder()
    prim = unit_quad(b)
    prim["material"] = 0
    b.add("meshes", {"primitives": [prim]})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.doc["images"] = [{"name": "checker", "bufferView": b.view(png(2, 2, CHECKER_2X2)),
                        "mimeType": "image/png"}]
    b.doc["textures"] = [{"source": 0}]
    b.doc["materials"] = [{"name": "painted", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    b.write_glb("textures.glb")


def invalid_textures():
    """Texture files that must fail with one clear error each."""
    def textured_triangle(images, textures, texture_index=0):
        b = triangle_file()
        b.doc["images"] = images
        b.doc["textures"] = textures
        b.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": texture_index}}}]
        b.doc["meshes"][0]["primitives"][0]["material"] = 0
        return b

    good = [{"uri": data_uri(png(1, 1, [1, 2, 3, 4]))}]
    write_binary("undecodable.png", b"this is not a PNG file\n")
    textured_triangle([{"uri": "undecodable.png"}], [{"source": 0}]).write_gltf(
        "invalid_undecodable_image.gltf")
    write_binary("empty.png", b"")
    textured_triangle([{"uri": "empty.png"}], [{"source": 0}]).write_gltf("invalid_empty_image.gltf")
    textured_triangle(good, [{"source": 3}]).write_gltf("invalid_texture_source.gltf")
    textured_triangle(good, [{"sampler": 0}]).write_gltf("invalid_texture_no_source.gltf")
    textured_triangle(good, [{"source": 0}], texture_index=4).write_gltf("invalid_texture_index.gltf")
    # A .glb image whose buffer view runs 1000 bytes past the buffer's end.
    b = textured_triangle([], [{"source": 0}])
    view = b.view(png(1, 1, [1, 2, 3, 4]))
    b.doc["images"] = [{"bufferView": view, "mimeType": "image/png"}]
    b.doc["bufferViews"][view]["byteLength"] += 1000
    b.write_glb("invalid_image_view.glb")


def render_quad(b, material):
    """The renderer's 2 m quad in z = 0 facing +z (counter-clockwise seen from
    +z), uv (0, 1) (1, 1) (1, 0) (0, 0) so the image is upright seen from +z."""
    prim = {"attributes": {
        "POSITION": b.accessor([-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0], minmax=True),
        "NORMAL": b.accessor([0, 0, 1] * 4),
        "TANGENT": b.accessor([1, 0, 0, 1] * 4, atype="VEC4"),
        "TEXCOORD_0": b.accessor([0, 1, 1, 1, 1, 0, 0, 0], atype="VEC2")},
        "indices": b.accessor([0, 1, 2, 0, 2, 3], USHORT, "SCALAR"), "material": material}
    b.add("meshes", {"name": "quad", "primitives": [prim]})
    b.add("nodes", {"name": "quad", "mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.doc["scene"] = 0


LEVELS = [0, 85, 170, 255]


def checker_4x4():
    """Texel (x, y) (x right, y down): (LEVELS[x], LEVELS[y], 255 if x + y
    is odd else 0, 255); all 16 colours differ."""
    px = []
    for y in range(4):
        for x in range(4):
            px += [LEVELS[x], LEVELS[y], 255 if (x + y) % 2 else 0, 255]
    return px


def alpha_checker_4x4():
    """Texel (x, y): rgb 128, alpha 255 where x + y is even, else 0."""
    px = []
    for y in range(4):
        for x in range(4):
            px += [128, 128, 128, 0 if (x + y) % 2 else 255]
    return px


def render_quads():
    """The renderer's test files (README.md here describes them)."""
    nearest_clamp = {"magFilter": NEAREST, "minFilter": NEAREST, "wrapS": CLAMP_TO_EDGE,
                     "wrapT": CLAMP_TO_EDGE}
    write_binary("textured_quad_checker.png", png(4, 4, checker_4x4()))
    b = Builder()
    render_quad(b, 0)
    b.doc["images"] = [{"name": "checker", "uri": "textured_quad_checker.png"}]
    b.doc["samplers"] = [nearest_clamp]
    b.doc["textures"] = [{"source": 0, "sampler": 0}]
    b.doc["materials"] = [{
        "name": "unlit checker", "emissiveFactor": [1, 1, 1], "emissiveTexture": {"index": 0},
        "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0,
                                 "roughnessFactor": 1},
        "extensions": {"KHR_materials_specular": {"specularFactor": 0}}}]
    b.doc["extensionsUsed"] = ["KHR_materials_specular"]
    b.write_gltf("textured_quad.gltf")

    write_binary("alpha_mask_quad.png", png(4, 4, alpha_checker_4x4()))
    b = Builder()
    render_quad(b, 0)
    b.doc["images"] = [{"name": "alpha checker", "uri": "alpha_mask_quad.png"}]
    b.doc["samplers"] = [nearest_clamp]
    b.doc["textures"] = [{"source": 0, "sampler": 0}]
    b.doc["materials"] = [{
        "name": "alpha mask", "alphaMode": "MASK", "alphaCutoff": 0.5,
        "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "baseColorFactor": [1, 1, 1, 1],
                                 "metallicFactor": 0, "roughnessFactor": 1}}]
    b.write_gltf("alpha_mask_quad.gltf")


def scene_files():
    """Penumbra scene files that reference the glTF files above."""
    # Near the camera, so the shadow terminator (where faceted geometry
    # shadows itself whatever the normals) stays at the silhouette.
    light = {"type": "point", "position": [1.5, 1.5, 4], "intensity": [20, 20, 20]}
    camera = {"position": [0, 0, 4], "forward": [0, 0, -1], "up": [0, 1, 0],
              "verticalFovDegrees": 35}
    for name, model in (("sphere_smooth.json", "sphere_smooth.gltf"),
                        ("sphere_flat.json", "sphere_flat.gltf")):
        write_json(name, {"format": "penumbra-scene", "version": 1, "name": name[:-5],
                          "camera": camera, "lights": [light], "gltf": [{"file": model}]})
    camera_above = {"position": [0, 2, 2], "forward": [0, -1, -1], "up": [0, 1, 0],
                    "verticalFovDegrees": 60}
    for name, y in (("leak_below.json", -1), ("leak_above.json", 1)):
        write_json(name, {"format": "penumbra-scene", "version": 1, "name": name[:-5],
                          "camera": camera_above,
                          "lights": [{"type": "point", "position": [0, y, 0], "intensity": [10, 10, 10]}],
                          "gltf": [{"file": "leak.gltf"}]})
    # The light and floor mirrored in x (symmetric, so the view is unchanged):
    # the emitter's front face must survive the mirroring transform.
    write_json("emissive_mirrored.json", {
        "format": "penumbra-scene", "version": 1, "name": "emissive_mirrored",
        "gltf": [{"file": "emissive_quad.gltf", "scale": [-1, 1, 1]}]})
    # Two textured glTF files after a scene-file material: texture and
    # texture-reference indices are offset as the files are appended.
    write_json("textured_merged.json", {
        "format": "penumbra-scene", "version": 1, "name": "textured_merged",
        "materials": {"white": {"model": "lambert", "albedo": [0.5, 0.5, 0.5]}},
        "meshes": [{"name": "floor", "material": "white",
                    "quads": [[[-1, -2, -1], [-1, -2, 1], [1, -2, 1], [1, -2, -1]]]}],
        "gltf": [{"file": "textured_quad.gltf"},
                 {"file": "alpha_mask_quad.gltf", "translation": [0, 0, -1]}]})
    write_json("merged.json", {
        "format": "penumbra-scene", "version": 1, "name": "merged",
        "materials": {"white": {"model": "lambert", "albedo": [0.5, 0.5, 0.5]}},
        "meshes": [{"name": "floor", "material": "white",
                    "quads": [[[-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]]]}],
        "gltf": [{"file": "cameras.gltf", "translation": [0, 0, -3], "scale": [2, 2, 2],
                  "camera": "side"},
                 {"file": "transforms.gltf",
                  "transform": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 100, 0, 1]}]})


def large_world():
    """degenerate.gltf: four triangles, two of zero area (a repeated corner;
    three collinear corners); degenerate_primitives.gltf: that primitive three
    times in one mesh; far_translation.gltf: the unit triangle under a
    root node translated by (1000000.03, -200000.01, 0.07), which a float
    cannot hold (its spacing at 1e6 is 0.0625)."""
    b = Builder()
    pos = b.accessor([0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0, 1, 1, 0], minmax=True)
    idx = b.accessor([0, 1, 2, 0, 0, 1, 0, 1, 3, 1, 4, 2], USHORT, "SCALAR")
    b.add("meshes", {"name": "some degenerate", "primitives": [{"attributes": {"POSITION": pos}, "indices": idx}]})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.doc["scene"] = 0
    b.write_gltf("degenerate.gltf")
    # The same primitive three times: one line for the file, not three.
    b.doc["meshes"][0]["primitives"] *= 3
    b.write_gltf("degenerate_primitives.gltf")

    b = triangle_file()
    b.doc["nodes"] = [{"translation": [1000000.03, -200000.01, 0.07], "children": [1]}, {"mesh": 0}]
    b.write_gltf("far_translation.gltf")


def animated():
    """A skinned strip for the command line: two quads up the y axis, 1 m
    wide and 2 m tall, facing +z; the bottom row of vertices on joint 0 (node
    1, at the origin), the middle half on each joint, the top on joint 1
    (node 2, child of node 1 at (0,1,0)). Animation "Bend" turns joint 1 by 90
    degrees about +z from 0 s to 1 s; "Slide" moves joint 0 from x = 0 to
    x = 2 in 2 s."""
    b = Builder()
    pos = b.accessor([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0, 1, 2, 0], minmax=True)
    nrm = b.accessor([0, 0, 1] * 6)
    idx = b.accessor([0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4], USHORT, "SCALAR")
    joints = b.accessor([0, 0, 0, 0] * 2 + [0, 1, 0, 0] * 2 + [1, 0, 0, 0] * 2, UBYTE, "VEC4")
    weights = b.accessor([1, 0, 0, 0] * 2 + [0.5, 0.5, 0, 0] * 2 + [1, 0, 0, 0] * 2, atype="VEC4")
    b.doc["accessors"].append({"bufferView": b.view(struct.pack("<32f", *(
        [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1] +
        [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1]))),
        "componentType": FLOAT, "type": "MAT4", "count": 2})
    bind = len(b.doc["accessors"]) - 1
    b.add("meshes", {"name": "strip", "primitives": [
        {"attributes": {"POSITION": pos, "NORMAL": nrm, "JOINTS_0": joints, "WEIGHTS_0": weights},
         "indices": idx}]})
    b.add("skins", {"joints": [1, 2], "inverseBindMatrices": bind})
    b.add("nodes", {"name": "strip", "mesh": 0, "skin": 0})
    b.add("nodes", {"name": "root", "children": [2]})
    b.add("nodes", {"name": "tip", "translation": [0, 1, 0]})
    s45 = math.sin(math.pi / 4)
    times1 = b.accessor([0, 1], atype="SCALAR")
    times2 = b.accessor([0, 2], atype="SCALAR")
    turn = b.accessor([0, 0, 0, 1, 0, 0, s45, s45], atype="VEC4")
    slide = b.accessor([0, 0, 0, 2, 0, 0])
    b.add("animations", {"name": "Bend", "samplers": [{"input": times1, "output": turn}],
                         "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}}]})
    b.add("animations", {"name": "Slide", "samplers": [{"input": times2, "output": slide}],
                         "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}}]})
    b.doc["scenes"] = [{"nodes": [0, 1]}]
    b.doc["scene"] = 0
    b.write_gltf("animated.gltf")


def unlit():
    """KHR_materials_unlit: a 2 m square facing +z at z = 0 (no camera: the
    loader frames it), baseColorFactor (0.5, 0.5, 0.5) times COLOR_0
    (0.2, 0.4, 0.8) at every vertex, so (0.1, 0.2, 0.4) wherever it is seen;
    its emissiveFactor (1, 1, 1) must be ignored, as the extension says."""
    b = Builder()
    b.doc["materials"] = [
        {"name": "unlit", "emissiveFactor": [1, 1, 1],
         "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]},
         "extensions": {"KHR_materials_unlit": {}}}]
    b.doc["extensionsUsed"] = ["KHR_materials_unlit"]
    prim = quad(b, [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)], (0, 0, 1))
    prim["attributes"]["COLOR_0"] = b.accessor([0.2, 0.4, 0.8] * 4)
    prim["material"] = 0
    b.add("meshes", {"name": "unlit", "primitives": [prim]})
    b.add("nodes", {"mesh": 0})
    b.doc["scenes"] = [{"nodes": [0]}]
    b.write_gltf("unlit.gltf")


def punctual_lights():
    """KHR_lights_punctual over a grey floor (albedo 0.5, no specular layer,
    40 m square at y = 0), seen by a camera 3 m above the origin looking
    straight down (yfov 90 degrees; image right = +x, image down = +z):
    a coloured point light 2 m up, the same with range 3, a spot facing down
    (inner 20, outer 40 degrees), a directional light travelling down and
    towards +z at 45 degrees; and two invalid files."""
    def base():
        b = Builder()
        b.doc["materials"] = [
            {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1],
                                                       "metallicFactor": 0, "roughnessFactor": 1},
             "extensions": {"KHR_materials_specular": {"specularFactor": 0}}}]
        b.doc["extensionsUsed"] = ["KHR_materials_specular", "KHR_lights_punctual"]
        floor = quad(b, [(-20, 0, 20), (20, 0, 20), (20, 0, -20), (-20, 0, -20)], (0, 1, 0))
        floor["material"] = 0
        b.add("meshes", {"name": "floor", "primitives": [floor]})
        b.add("nodes", {"mesh": 0})
        b.doc["cameras"] = [{"type": "perspective",
                             "perspective": {"yfov": math.pi / 2, "znear": 0.01}}]
        h = math.sqrt(0.5)
        b.add("nodes", {"name": "view", "camera": 0, "translation": [0, 3, 0],
                        "rotation": [-h, 0, 0, h]})
        return b

    def with_light(light, node):
        b = base()
        b.doc["extensions"] = {"KHR_lights_punctual": {"lights": [light]}}
        node["extensions"] = {"KHR_lights_punctual": {"light": 0}}
        b.add("nodes", node)
        b.doc["scenes"] = [{"nodes": [0, 1, 2]}]
        return b

    h = math.sqrt(0.5)
    down = [-h, 0, 0, h]  # the light's -z turned to -y
    with_light({"type": "point", "color": [1, 0.5, 0.25], "intensity": 8},
               {"translation": [0, 2, 0]}).write_gltf("lights_point.gltf")
    with_light({"type": "point", "intensity": 8, "range": 3},
               {"translation": [0, 2, 0]}).write_gltf("lights_point_range.gltf")
    with_light({"type": "spot", "intensity": 8,
                "spot": {"innerConeAngle": math.radians(20), "outerConeAngle": math.radians(40)}},
               {"translation": [0, 2, 0], "rotation": down}).write_gltf("lights_spot.gltf")
    # -z turned by -135 degrees about x: travelling along (0, -1, 1) / sqrt 2.
    a = math.radians(-135) / 2
    with_light({"type": "directional", "intensity": 3},
               {"rotation": [math.sin(a), 0, 0, math.cos(a)]}).write_gltf("lights_directional.gltf")
    with_light({"type": "spot", "intensity": 8,
                "spot": {"innerConeAngle": 0.6, "outerConeAngle": 0.4}},
               {"translation": [0, 2, 0], "rotation": down}).write_gltf("invalid_light_cone.gltf")
    b = with_light({"type": "point", "intensity": 8}, {"translation": [0, 2, 0]})
    b.doc["nodes"][2]["extensions"]["KHR_lights_punctual"]["light"] = 3
    b.write_gltf("invalid_light_index.gltf")


if __name__ == "__main__":
    transforms()
    sparse()
    attributes()
    vertex_colors()
    mesh_quantization()
    gpu_instancing()
    generated()
    containers()
    materials()
    cameras()
    extensions()
    invalid()
    emissive_quad()
    spheres()
    leak()
    modes()
    textured()
    textures()
    invalid_textures()
    render_quads()
    scene_files()
    large_world()
    punctual_lights()
    animated()
    unlit()
