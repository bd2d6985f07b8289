#!/usr/bin/env python3
"""Writes the vertex colour (COLOR_0) test files of tests/render/test_gltf.cpp, beside this script.

One floor triangle at y = 0, corners (-8, 0, 8), (8, 0, 8), (0, 0, -8), facing +y, in a material of
base colour 1, metallic 0, roughness 1 and KHR_materials_ior 1 (F0 = 0: a Lambertian base alone):

vertex-colors-white.gltf  no COLOR_0: the reference.
vertex-colors.gltf        COLOR_0 as VEC3 of FLOAT: red, green and blue at the corners.
vertex-colors-u8.gltf     COLOR_0 as VEC4 of normalized UNSIGNED_BYTE (alpha 128, which the OPAQUE
                          material ignores): (255, 128, 0), (0, 255, 64), (32, 0, 255).
vertex-colors-bad.gltf    COLOR_0 as VEC3 of FLOAT with a component 1.5 (the located error).
vertex-alpha-mask.gltf    COLOR_0 as VEC4 of FLOAT, white with alpha 0, 0, 1 at the corners, in the
                          same material as MASK (alphaCutoff 0.5): the floor is cut where the
                          interpolated alpha is below 0.5.
vertex-alpha-blend.gltf   The same as BLEND: the floor stops that fraction of the rays.
Run: python3 make_vertex_colors.py
"""
import base64
import json
import struct
from pathlib import Path

HERE = Path(__file__).resolve().parent
CORNERS = [(-8.0, 0.0, 8.0), (8.0, 0.0, 8.0), (0.0, 0.0, -8.0)]


def write(name, colors=None, component_type=5126, rgba=False, alpha_mode=None):
    positions = b"".join(struct.pack("<3f", *c) for c in CORNERS)
    views = [positions]
    accessors = [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                  "min": [-8.0, 0.0, -8.0], "max": [8.0, 0.0, 8.0]}]
    attributes = {"POSITION": 0}
    if colors is not None:
        if component_type == 5126:
            data = b"".join(struct.pack(f"<{len(c)}f", *c) for c in colors)
        else:
            data = b"".join(struct.pack("<4B", *c) for c in colors)  # 4 bytes each: aligned
        views.append(data)
        accessor = {"bufferView": 1, "componentType": component_type, "count": 3, "type": "VEC4" if rgba else "VEC3"}
        if component_type != 5126:
            accessor["normalized"] = True
        accessors.append(accessor)
        attributes["COLOR_0"] = 1
    material = {"name": "Paint", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0,
                                                          "roughnessFactor": 1},
                "extensions": {"KHR_materials_ior": {"ior": 1.0}}}
    if alpha_mode is not None:
        material["alphaMode"] = alpha_mode
    data = b"".join(views)
    offsets = [sum(len(v) for v in views[:i]) for i in range(len(views))]
    gltf = {
        "asset": {"version": "2.0", "generator": "lightpath tests/render/data/gltf/make_vertex_colors.py"},
        "extensionsUsed": ["KHR_materials_ior"],
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "Floor"}],
        "meshes": [{"primitives": [{"attributes": attributes, "material": 0}]}],
        "materials": [material],
        "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": len(v)} for o, v in zip(offsets, views)],
        "accessors": accessors,
    }
    (HERE / name).write_text(json.dumps(gltf, indent=1) + "\n")


def main():
    write("vertex-colors-white.gltf")
    write("vertex-colors.gltf", [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)])
    write("vertex-colors-u8.gltf", [(255, 128, 0, 128), (0, 255, 64, 128), (32, 0, 255, 128)], 5121, rgba=True)
    write("vertex-colors-bad.gltf", [(1.0, 0.0, 0.0), (0.0, 1.5, 0.0), (0.0, 0.0, 1.0)])
    alphas = [(1.0, 1.0, 1.0, 0.0), (1.0, 1.0, 1.0, 0.0), (1.0, 1.0, 1.0, 1.0)]
    write("vertex-alpha-mask.gltf", alphas, rgba=True, alpha_mode="MASK")
    write("vertex-alpha-blend.gltf", alphas, rgba=True, alpha_mode="BLEND")


if __name__ == "__main__":
    main()
