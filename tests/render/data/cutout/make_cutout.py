#!/usr/bin/env python3
"""Writes the cut-out (alpha) test files of tests/render/test_cutout.cpp, beside this script.

stripes-rgba.png   8x8 8-bit RGBA, white; alpha 255 in texel columns 0, 1, 4, 5 and 0 in 2, 3, 6, 7.
                   Read bilinearly at its finest level with wrap, alpha crosses 0.5 exactly on the
                   texel boundaries u = 2/8, 4/8, 6/8 and 0: half of every period is covered (MASK,
                   cutoff 0.5), and alpha's mean over a period is 0.5 (BLEND).
stripes-grey.png   the same pattern as an 8-bit grey image without alpha (a mask's only channel).
white-rgb.png      2x2 8-bit RGB white: a base colour texture without an alpha channel.
card.obj, card.mtl an 8 m square card at y = 1 facing down (-y), x and z in [-4, 4], its u = 4 (x + 4)
                   (32 repeats: stripes 0.25 m wide along x), v = (z + 4) / 8; its MTL material
                   "leaf" has map_d stripes-grey.png (the OBJ dissolve map).
card-*.gltf        the same card as glTF 2.0 (uvs in glTF's v-down convention), one material each:
                   card-mask.gltf      alphaMode MASK, baseColorTexture stripes-rgba.png (data URI);
                   card-blend.gltf     alphaMode BLEND, baseColorFactor alpha 0.3, no texture;
                   card-mask-low.gltf  MASK with baseColorFactor alpha 0.3 and alphaCutoff 0.2 (covered);
                   card-mask-rgb.gltf  MASK, baseColorFactor alpha 0.3, a texture without alpha: alpha
                                       is the factor alone, below the default cutoff (cut out everywhere);
                   card-opaque.gltf    alphaMode OPAQUE with the striped texture: alpha ignored.
Run: python3 make_cutout.py
"""
import base64
import json
import struct
import zlib
from pathlib import Path

HERE = Path(__file__).resolve().parent


def png(width, height, rows, colour_type):
    """An 8-bit PNG; rows: lists of pixels (tuples) from the top row down; colour type 0 grey,
    2 RGB, 6 RGBA."""
    raw = b"".join(b"\0" + bytes(c for px in row for c in px) for row in rows)
    chunk = lambda kind, data: (struct.pack(">I", len(data)) + kind + data +
                                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def covered(column):
    return column % 4 < 2


STRIPES_RGBA = png(8, 8, [[(255, 255, 255, 255 if covered(x) else 0) for x in range(8)] for _ in range(8)], 6)
STRIPES_GREY = png(8, 8, [[(255 if covered(x) else 0,) for x in range(8)] for _ in range(8)], 0)
WHITE_RGB = png(2, 2, [[(255, 255, 255)] * 2 for _ in range(2)], 2)

# The card's corners (x, z) at y = 1, wound so that its normal is -y, and their uvs.
CORNERS = [(-4.0, -4.0), (4.0, -4.0), (4.0, 4.0), (-4.0, 4.0)]


def uv(x, z):
    return 4.0 * (x + 4.0), (z + 4.0) / 8.0


def write_obj():
    lines = ["# The cut-out card of make_cutout.py", "mtllib card.mtl"]
    lines += [f"v {x:g} 1 {z:g}" for x, z in CORNERS]
    lines += ["vt {:g} {:g}".format(*uv(x, z)) for x, z in CORNERS]
    lines += ["usemtl leaf", "f 1/1 2/2 3/3", "f 1/1 3/3 4/4"]
    (HERE / "card.obj").write_text("\n".join(lines) + "\n")
    (HERE / "card.mtl").write_text("newmtl leaf\nKd 0.5 0.5 0.5\nmap_d stripes-grey.png\n")


def write_gltf(name, material, image=None):
    # Triangles (0, 1, 2), (0, 2, 3) of CORNERS; glTF's v runs down the image: v_gltf = 1 - v.
    positions = b"".join(struct.pack("<3f", x, 1.0, z) for x, z in CORNERS)
    uvs = b"".join(struct.pack("<2f", uv(x, z)[0], 1.0 - uv(x, z)[1]) for x, z in CORNERS)
    indices = struct.pack("<6H", 0, 1, 2, 0, 2, 3)
    data = positions + uvs + indices
    gltf = {
        "asset": {"version": "2.0", "generator": "lightpath tests/render/data/cutout/make_cutout.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "card"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
        "materials": [dict(material, name="leaf", doubleSided=True)],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions)},
                        {"buffer": 0, "byteOffset": len(positions), "byteLength": len(uvs)},
                        {"buffer": 0, "byteOffset": len(positions) + len(uvs), "byteLength": len(indices)}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-4.0, 1.0, -4.0], "max": [4.0, 1.0, 4.0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
    }
    if image is not None:
        gltf["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(image).decode()}]
        gltf["samplers"] = [{"wrapS": 10497, "wrapT": 10497}]
        gltf["textures"] = [{"source": 0, "sampler": 0}]
    (HERE / name).write_text(json.dumps(gltf, indent=1) + "\n")


def pbr(alpha=1.0, textured=False):
    values = {"baseColorFactor": [0.5, 0.5, 0.5, alpha], "metallicFactor": 0.0, "roughnessFactor": 1.0}
    if textured:
        values["baseColorTexture"] = {"index": 0}
    return values


def main():
    (HERE / "stripes-rgba.png").write_bytes(STRIPES_RGBA)
    (HERE / "stripes-grey.png").write_bytes(STRIPES_GREY)
    (HERE / "white-rgb.png").write_bytes(WHITE_RGB)
    write_obj()
    write_gltf("card-mask.gltf", {"alphaMode": "MASK", "pbrMetallicRoughness": pbr(textured=True)}, STRIPES_RGBA)
    write_gltf("card-blend.gltf", {"alphaMode": "BLEND", "pbrMetallicRoughness": pbr(0.3)})
    write_gltf("card-mask-low.gltf", {"alphaMode": "MASK", "alphaCutoff": 0.2, "pbrMetallicRoughness": pbr(0.3)})
    write_gltf("card-mask-rgb.gltf", {"alphaMode": "MASK", "pbrMetallicRoughness": pbr(0.3, textured=True)}, WHITE_RGB)
    write_gltf("card-opaque.gltf", {"alphaMode": "OPAQUE", "pbrMetallicRoughness": pbr(textured=True)}, STRIPES_RGBA)


if __name__ == "__main__":
    main()
