#!/usr/bin/env python3
"""Writes the textured glTF files of tests/render/test_gltf.cpp (issue #26), beside this script.

checker4.png          a 4x4 8-bit RGB image of 16 distinct colours (sRGB, as glTF's base colour is).
textured.gltf         a floor quad with TEXCOORD_0 whose baseColorTexture is checker4.png (a file
                      beside it), lit by a point light, seen from above; textured.toml and
                      textured-floor.obj are the same scene written by hand (TOML texture key).
textured-embedded.gltf  the same with the image embedded as a data URI.
textured.glb          the same as binary glTF, the image in a bufferView of the BIN chunk.
metal-rough.png       64x64, linear: the left half metal (B = 255) with roughness 0.2 (G = 51), the
                      right half dielectric (B = 0) with roughness 0.8 (G = 204).
metal-rough.gltf      the floor with metallicRoughnessTexture metal-rough.png, base colour 0.9,
                      0.6, 0.3; metal-rough.toml: the two halves as two materials.
normal-map.png        4x4, linear: every texel the tangent-space normal (166, 179, 238) / 255 * 2 - 1,
                      leaning towards +u and +v (image up).
normal-map.gltf       the floor (metallic 0, roughness 0.5) with normalTexture normal-map.png, scale 0.5.
normal-tilted.gltf    the same floor without the map, its NORMAL the normal the map makes (worked out
                      here: x, y times the scale, in the frame tangent +x (u), bitangent -z (v up),
                      normal +y), which tests/render/test_gltf.cpp renders as the reference.
Run: python3 make_textured.py
"""
import base64
import json
import math
import struct
import zlib
from pathlib import Path

HERE = Path(__file__).resolve().parent


def png(width, height, rows):
    """An 8-bit RGB PNG; rows: lists of (r, g, b) from the top row down."""
    raw = b"".join(b"\0" + bytes(c for px in row for c in px) for row in rows)
    chunk = lambda kind, data: (struct.pack(">I", len(data)) + kind + data +
                                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


CHECKER = png(4, 4, [[((x * 60 + 20) % 256, (y * 60 + 40) % 256, ((x + y) * 30 + 10) % 256) for x in range(4)]
                     for y in range(4)])
METAL_ROUGH = png(64, 64, [[(0, 51, 255)] * 32 + [(0, 204, 0)] * 32 for _ in range(64)])

# The floor: x and z in [-1, 1] at y = 0, facing +y. glTF's uv has v down the image from its top
# row: the corner (-1, 0, -1), farthest from the camera's bottom edge, reads the image's top left.
POSITIONS = [(-1, 0, -1), (1, 0, -1), (1, 0, 1), (-1, 0, 1)]
UVS = [(0, 0), (1, 0), (1, 1), (0, 1)]
ORDER = [0, 2, 1, 0, 3, 2]


NORMAL_TEXEL = (166, 179, 238)
NORMAL_MAP = png(4, 4, [[NORMAL_TEXEL] * 4 for _ in range(4)])
NORMAL_SCALE = 0.5


def mapped_normal():
    """The world normal normal-map.png makes on the floor (glTF 2.0, 3.9.3: x and y times scale)."""
    x, y, z = (2 * c / 255 - 1 for c in NORMAL_TEXEL)
    x, y = x * NORMAL_SCALE, y * NORMAL_SCALE
    world = (x, z, -y)  # tangent +x, normal +y, bitangent -z (glTF's v grows along +z, image up is -z)
    length = math.sqrt(sum(c * c for c in world))
    return tuple(c / length for c in world)


def document(material, images, wrap, normal=(0, 1, 0)):
    data = bytearray()
    views, accessors = [], []

    def add(raw, count, kind, component, **extra):
        while len(data) % 4:
            data.append(0)
        views.append({"buffer": 0, "byteOffset": len(data), "byteLength": len(raw)})
        data.extend(raw)
        accessors.append({"bufferView": len(views) - 1, "componentType": component, "count": count, "type": kind, **extra})
        return len(accessors) - 1

    pos = add(b"".join(struct.pack("<3f", *p) for p in POSITIONS), 4, "VEC3", 5126,
              min=[-1, 0, -1], max=[1, 0, 1])
    nrm = add(b"".join(struct.pack("<3f", *normal) for _ in POSITIONS), 4, "VEC3", 5126)
    uv = add(b"".join(struct.pack("<2f", *t) for t in UVS), 4, "VEC2", 5126)
    idx = add(struct.pack("<6H", *ORDER), 6, "SCALAR", 5123)
    s = math.sqrt(0.5)
    return {
        "asset": {"version": "2.0", "generator": "make_textured.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"name": "Lamp", "type": "point", "intensity": 2 * math.pi}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [
            {"name": "Floor", "mesh": 0},
            {"name": "Camera", "camera": 0, "translation": [0, 3, 0], "rotation": [-s, 0, 0, s]},
            {"name": "Lamp", "translation": [0.3, 2, 0.2], "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.9, "aspectRatio": 4 / 3, "znear": 0.1}}],
        "meshes": [{"name": "Floor", "primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm, "TEXCOORD_0": uv},
                                                     "indices": idx, "material": 0}]}],
        "materials": [material],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"wrapS": wrap, "wrapT": wrap}],
        "images": images,
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(data)).decode()}],
        "bufferViews": views,
        "accessors": accessors,
    }


def main():
    (HERE / "checker4.png").write_bytes(CHECKER)
    (HERE / "metal-rough.png").write_bytes(METAL_ROUGH)
    base = {"name": "Checker", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0,
                                                        "roughnessFactor": 1}}
    uri = "data:image/png;base64," + base64.b64encode(CHECKER).decode()
    for name, images in (("textured.gltf", [{"uri": "checker4.png"}]), ("textured-embedded.gltf", [{"uri": uri}])):
        # REPEAT, as the TOML texture key wraps (the filter blends the edges alike).
        (HERE / name).write_text(json.dumps(document(base, images, 10497), indent=1) + "\n")
    glb = document(base, [], 10497)
    data = base64.b64decode(glb["buffers"][0]["uri"].split(",", 1)[1])
    while len(data) % 4:
        data += b"\0"
    glb["bufferViews"].append({"buffer": 0, "byteOffset": len(data), "byteLength": len(CHECKER)})
    data += CHECKER
    while len(data) % 4:
        data += b"\0"
    glb["images"] = [{"bufferView": len(glb["bufferViews"]) - 1, "mimeType": "image/png"}]
    glb["buffers"] = [{"byteLength": len(data)}]
    text = json.dumps(glb).encode()
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(data), b"BIN\0") + data
    (HERE / "textured.glb").write_bytes(struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks)
    (HERE / "normal-map.png").write_bytes(NORMAL_MAP)
    plain = {"name": "Plastic", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1], "metallicFactor": 0,
                                                         "roughnessFactor": 0.5}}
    mapped = dict(plain, normalTexture={"index": 0, "scale": NORMAL_SCALE})
    (HERE / "normal-map.gltf").write_text(json.dumps(document(mapped, [{"uri": "normal-map.png"}], 10497), indent=1) + "\n")
    tilted = document(plain, [], 10497, mapped_normal())
    for unused in ("textures", "samplers", "images"):
        del tilted[unused]
    (HERE / "normal-tilted.gltf").write_text(json.dumps(tilted, indent=1) + "\n")
    metal = {"name": "MetalRough", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.6, 0.3, 1],
                                                            "metallicRoughnessTexture": {"index": 0}}}
    # CLAMP_TO_EDGE: the metal's edge must not blend with the dielectric's across the wrap.
    (HERE / "metal-rough.gltf").write_text(json.dumps(document(metal, [{"uri": "metal-rough.png"}], 33071), indent=1) + "\n")


main()
