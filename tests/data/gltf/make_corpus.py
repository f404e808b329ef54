#!/usr/bin/env python3
"""Writes the small glTF files of this folder: one valid triangle and broken variants, each
breaking one rule the loader must report (file, element, what is wrong). Run it from
anywhere; the files are committed, so tests need no Python."""
import base64
import json
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def data_uri(raw):
    return "data:application/octet-stream;base64," + base64.b64encode(raw).decode()


def triangle(positions=None, indices=(0, 1, 2)):
    """A triangle with indices: 3 float3 positions then 3 uint16 indices (padded)."""
    positions = positions or [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
    pos = b"".join(struct.pack("<3f", *p) for p in positions)
    idx = b"".join(struct.pack("<H", i) for i in indices) + b"\0\0"
    raw = pos + idx
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(raw), "uri": data_uri(raw)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
                        {"buffer": 0, "byteOffset": len(pos), "byteLength": len(idx)}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
    }


def png(width, height, rgba_rows):
    """A minimal RGBA8 PNG (stdlib only): rows of width * 4 bytes, top row first."""
    import zlib

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    raw = b"".join(b"\0" + row for row in rgba_rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def textured_quad(image_bytes):
    """A unit quad in the xy plane with normals and TEXCOORD_0, its material masked with a
    2x1 texture (left texel opaque red, right clear green), sampled NEAREST and clamped,
    and a KHR_texture_transform offset of (0.25, 0)."""
    pos = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    nrm = [(0, 0, 1)] * 4
    uv = [(0, 1), (1, 1), (1, 0), (0, 0)]
    idx = (0, 1, 2, 0, 2, 3)
    blobs = [b"".join(struct.pack("<3f", *p) for p in pos),
             b"".join(struct.pack("<3f", *n) for n in nrm),
             b"".join(struct.pack("<2f", *t) for t in uv),
             b"".join(struct.pack("<H", i) for i in idx)]
    raw, views, offset = b"", [], 0
    for b in blobs:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(b)})
        raw += b
        offset += len(b)
    return {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_texture_transform"],
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                    "indices": 3, "material": 0}]}],
        "materials": [{"name": "cut", "alphaMode": "MASK", "alphaCutoff": 0.4,
                       "doubleSided": True,
                       "pbrMetallicRoughness": {
                           "baseColorFactor": [1, 1, 1, 0.9],
                           "baseColorTexture": {"index": 0, "extensions": {
                               "KHR_texture_transform": {"offset": [0.25, 0]}}}}}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9728, "minFilter": 9728, "wrapS": 33071, "wrapT": 33071}],
        "images": [{"uri": "data:image/png;base64," + base64.b64encode(image_bytes).decode()}],
        "buffers": [{"byteLength": len(raw), "uri": data_uri(raw)}],
        "bufferViews": views,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
    }


def sphere(segments, rings, radius, centre):
    """A UV sphere's positions, normals and uint16 indices (outward, counter-clockwise)."""
    import math
    pos, nrm, idx = [], [], []
    for r in range(rings + 1):
        phi = math.pi * r / rings
        for s in range(segments + 1):
            theta = 2 * math.pi * s / segments
            n = (math.sin(phi) * math.cos(theta), math.cos(phi), math.sin(phi) * math.sin(theta))
            nrm.append(n)
            pos.append(tuple(centre[k] + radius * n[k] for k in range(3)))
    for r in range(rings):
        for s in range(segments):
            a, b = r * (segments + 1) + s, (r + 1) * (segments + 1) + s
            if r > 0:
                idx += [a, a + 1, b]
            if r < rings - 1:
                idx += [a + 1, b + 1, b]
    return pos, nrm, idx


def lod_spheres():
    """A sphere of radius 0.5 resting on nothing at (0, 1, 0) whose node names two coarser
    spheres as its MSFT_lod versions (nodes 1 and 2, outside the scene's node list)."""
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
           "extensionsUsed": ["MSFT_lod"], "meshes": [], "accessors": [], "bufferViews": []}
    raw = b""
    for segments, rings in ((48, 24), (16, 8), (8, 4)):
        pos, nrm, idx = sphere(segments, rings, 0.5, (0.0, 1.0, 0.0))
        first = len(doc["accessors"])
        for data, kind, fmt, comp in ((pos, "VEC3", "<3f", 5126), (nrm, "VEC3", "<3f", 5126),
                                      (idx, "SCALAR", "<H", 5123)):
            blob = b"".join(struct.pack(fmt, *(v if isinstance(v, tuple) else (v,))) for v in data)
            blob += b"\0" * (-len(blob) % 4)
            doc["bufferViews"].append({"buffer": 0, "byteOffset": len(raw), "byteLength": len(blob)})
            accessor = {"bufferView": len(doc["bufferViews"]) - 1, "componentType": comp,
                        "count": len(data), "type": kind}
            if data is pos:
                accessor["min"] = [min(p[k] for p in pos) for k in range(3)]
                accessor["max"] = [max(p[k] for p in pos) for k in range(3)]
            doc["accessors"].append(accessor)
            raw += blob
        doc["meshes"].append({"primitives": [{"attributes": {"POSITION": first, "NORMAL": first + 1},
                                              "indices": first + 2}]})
    doc["buffers"] = [{"byteLength": len(raw), "uri": data_uri(raw)}]
    doc["nodes"] = [{"name": "sphere", "mesh": 0, "extensions": {"MSFT_lod": {"ids": [1, 2]}},
                     "extras": {"MSFT_screencoverage": [0.5, 0.2, 0.01]}},
                    {"name": "sphere medium", "mesh": 1}, {"name": "sphere low", "mesh": 2}]
    return doc


def write(name, doc):
    with open(os.path.join(HERE, name), "w") as f:
        f.write(doc if isinstance(doc, str) else json.dumps(doc, indent=1))


def main():
    write("triangle.gltf", triangle())
    write("bad_json.gltf", '{"asset": {"version": "2.0"}, "nodes": [')
    d = triangle()
    d["buffers"][0]["uri"] = "nothere.bin"
    write("missing_buffer.gltf", d)
    d = triangle()
    d["buffers"][0]["uri"] = "../secret.bin"
    write("escape_uri.gltf", d)
    d = triangle()
    d["buffers"][0]["uri"] = "/etc/hostname"
    write("absolute_uri.gltf", d)
    write("index_out_of_range.gltf", triangle(indices=(0, 1, 7)))
    d = triangle()
    d["accessors"][0]["count"] = 40  # 480 bytes from a 36-byte view
    write("accessor_overrun.gltf", d)
    write("nan_position.gltf",
          triangle(positions=[(0.0, 0.0, 0.0), (float("nan"), 0.0, 0.0), (0.0, 1.0, 0.0)]))
    d = triangle()
    d["extensionsUsed"] = d["extensionsRequired"] = ["KHR_draco_mesh_compression"]
    write("required_extension.gltf", d)
    # The same, refused by tinygltf first (its buffer is missing, as a Draco file's accessors
    # fail tinygltf's parse): the refusal names the extension too.
    d = triangle()
    d["extensionsUsed"] = d["extensionsRequired"] = ["KHR_draco_mesh_compression"]
    d["buffers"][0]["uri"] = "nothere.bin"
    write("draco_unparsed.gltf", d)
    d = triangle()
    d["nodes"] = [{"mesh": 0, "children": [1]}, {"children": [0]}]
    write("cycle.gltf", d)
    d = triangle()
    d["scenes"] = [{"nodes": []}]
    write("empty_scene.gltf", d)
    write("zero_area.gltf",
          triangle(positions=[(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (2.0, 0.0, 0.0)]))
    d = triangle()
    d["meshes"][0]["primitives"][0]["mode"] = 1  # lines
    write("lines_only.gltf", d)
    write("textured_quad.gltf",
          textured_quad(png(2, 1, [bytes([255, 0, 0, 255, 0, 255, 0, 0])])))
    write("bad_image.gltf", textured_quad(b"\x89PNG\r\n\x1a\nnot really a png"))
    write("lod_spheres.gltf", lod_spheres())
    d = triangle()
    d["nodes"][0]["extensions"] = {"MSFT_lod": {"ids": [7]}}
    write("lod_missing_node.gltf", d)
    with open(os.path.join(HERE, "truncated.glb"), "wb") as f:
        f.write(b"glTF" + struct.pack("<II", 2, 1000) + b"\x10\0\0\0JSON{")


if __name__ == "__main__":
    main()
