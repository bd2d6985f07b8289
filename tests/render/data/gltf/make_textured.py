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
clearcoat.png         64x64, linear: the left half a coat of weight 1 (R = 255) and roughness 0.2
                      (G = 51), the right half weight 0.4 (R = 102) and roughness 0.8 (G = 204).
clearcoat.gltf        the floor, blue (metallic 0, roughness 0.5), with KHR_materials_clearcoat's
                      clearcoatTexture and clearcoatRoughnessTexture clearcoat.png, factors 1;
                      clearcoat.toml: the two halves as two materials.
normal-map.png        4x4, linear: every texel the tangent-space normal (166, 179, 238) / 255 * 2 - 1,
                      leaning towards +u and +v (image up).
normal-map.gltf       the floor (metallic 0, roughness 0.5) with normalTexture normal-map.png, scale 0.5.
normal-tilted.gltf    the same floor without the map, its NORMAL the normal the map makes (worked out
                      here: x, y times the scale, in the frame tangent +x (u), bitangent -z (v up),
                      normal +y), which tests/render/test_gltf.cpp renders as the reference.
normal-map-tangent.gltf  normal-map.gltf with its uvs turned a quarter (u along +z), and TANGENT
                      (1, 0, 0, 1): the frame normal-tilted.gltf was worked out in, not the uvs'.
textured-texcoord1.gltf  textured.gltf with the floor's uvs as TEXCOORD_1, which its baseColorTexture
                      names (texCoord 1), and TEXCOORD_0 mirrored: it renders as textured.toml.
texcoord-missing.gltf a baseColorTexture naming texCoord 1 on a primitive without TEXCOORD_1 (the
                      located error).
textured-transform.gltf  the checker through KHR_texture_transform (offset, rotation, scale, and
                      texCoord 1 in place of 0); textured-transform-baked.gltf has the transformed uvs.
normal-tilted-quantized.gltf  normal-tilted.gltf under KHR_mesh_quantization: its normal (negative
                      components included) as normalized BYTE, its positions as SHORT.
textured-quantized.gltf  textured.gltf as gltfpack writes it under KHR_mesh_quantization (required):
                      SHORT positions 16384 times the floor's, scaled back by its node, normalized
                      BYTE normals and normalized SHORT uvs; it renders as textured.toml.
textured-uv8.gltf, textured-uv16.gltf  textured.gltf with its uvs as normalized UNSIGNED_BYTE and
                      UNSIGNED_SHORT (glTF 2.0, 3.7.2.1): they render as textured.toml.
emissive-quadrants.png  256x256, linear greys 64 | 128 (bottom left, right) and 191 | 255 (top).
emissive-texture.gltf a quad x in [-0.5, 0.5], y in [0.3, 1.3] at z = 0 facing +z, emitting
                      emissive-quadrants.png (sRGB, as glTF's emissiveTexture is) times emissiveFactor
                      1 times strength 4; emissive-texture-gltf.toml places it, emissive-texture-srgb.toml
                      is the same as a TOML quad light.
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
CLEARCOAT = png(64, 64, [[(255, 51, 0)] * 32 + [(102, 204, 0)] * 32 for _ in range(64)])

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


QUANTUM = 16384  # textured-quantized.gltf: SHORT positions of the floor's corners times this, scaled back by its node


def document(material, images, wrap, normal=(0, 1, 0), uv_sets=(UVS,), tangent=None, uv_component=5126,
             quantized=False):
    data = bytearray()
    views, accessors = [], []

    def add(raw, count, kind, component, **extra):
        while len(data) % 4:
            data.append(0)
        views.append({"buffer": 0, "byteOffset": len(data), "byteLength": len(raw)})
        data.extend(raw)
        accessors.append({"bufferView": len(views) - 1, "componentType": component, "count": count, "type": kind, **extra})
        return len(accessors) - 1

    if quantized:
        # KHR_mesh_quantization as gltfpack writes it: SHORT positions (each element padded to 8
        # bytes), normalized BYTE normals (padded to 4), normalized SHORT uvs.
        pos = add(b"".join(struct.pack("<3hxx", *(c * QUANTUM for c in p)) for p in POSITIONS), 4, "VEC3", 5122,
                  min=[-QUANTUM, 0, -QUANTUM], max=[QUANTUM, 0, QUANTUM])
        views[-1]["byteStride"] = 8
        nrm = add(b"".join(struct.pack("<3bx", *(round(c * 127) for c in normal)) for _ in POSITIONS), 4, "VEC3", 5120,
                  normalized=True)
        views[-1]["byteStride"] = 4
    else:
        pos = add(b"".join(struct.pack("<3f", *p) for p in POSITIONS), 4, "VEC3", 5126,
                  min=[-1, 0, -1], max=[1, 0, 1])
        nrm = add(b"".join(struct.pack("<3f", *normal) for _ in POSITIONS), 4, "VEC3", 5126)
    attributes = {"POSITION": pos, "NORMAL": nrm}
    for n, uvs in enumerate(uv_sets):
        if quantized:
            attributes["TEXCOORD_%d" % n] = add(b"".join(struct.pack("<2h", *(round(c * 32767) for c in t)) for t in uvs),
                                                4, "VEC2", 5122, normalized=True)
        elif uv_component == 5126:
            attributes["TEXCOORD_%d" % n] = add(b"".join(struct.pack("<2f", *t) for t in uvs), 4, "VEC2", 5126)
        else:  # normalized UNSIGNED_BYTE (5121, each element padded to 4 bytes) or UNSIGNED_SHORT (5123)
            top, fmt = (255, "<2Bxx") if uv_component == 5121 else (65535, "<2H")
            raw = b"".join(struct.pack(fmt, *(round(c * top) for c in t)) for t in uvs)
            attributes["TEXCOORD_%d" % n] = add(raw, 4, "VEC2", uv_component, normalized=True)
            if uv_component == 5121:
                views[-1]["byteStride"] = 4
    if tangent is not None:
        attributes["TANGENT"] = add(b"".join(struct.pack("<4f", *tangent) for _ in POSITIONS), 4, "VEC4", 5126)
    idx = add(struct.pack("<6H", *ORDER), 6, "SCALAR", 5123)
    s = math.sqrt(0.5)
    return {
        "asset": {"version": "2.0", "generator": "make_textured.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"name": "Lamp", "type": "point", "intensity": 2 * math.pi * 683}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [
            {"name": "Floor", "mesh": 0},
            {"name": "Camera", "camera": 0, "translation": [0, 3, 0], "rotation": [-s, 0, 0, s]},
            {"name": "Lamp", "translation": [0.3, 2, 0.2], "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.9, "aspectRatio": 4 / 3, "znear": 0.1}}],
        "meshes": [{"name": "Floor", "primitives": [{"attributes": attributes, "indices": idx, "material": 0}]}],
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
    tilted = document(plain, [], 10497, mapped_normal(), quantized=True)
    for unused in ("textures", "samplers", "images"):
        del tilted[unused]
    tilted["extensionsUsed"].append("KHR_mesh_quantization")
    tilted["extensionsRequired"] = ["KHR_mesh_quantization"]
    tilted["nodes"][0]["scale"] = [1 / QUANTUM] * 3
    (HERE / "normal-tilted-quantized.gltf").write_text(json.dumps(tilted, indent=1) + "\n")
    metal = {"name": "MetalRough", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.6, 0.3, 1],
                                                            "metallicRoughnessTexture": {"index": 0}}}
    # CLAMP_TO_EDGE: the metal's edge must not blend with the dielectric's across the wrap.
    (HERE / "metal-rough.gltf").write_text(json.dumps(document(metal, [{"uri": "metal-rough.png"}], 33071), indent=1) + "\n")
    (HERE / "clearcoat.png").write_bytes(CLEARCOAT)
    lacquered = {"name": "Lacquered", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.3, 0.8, 1], "metallicFactor": 0,
                                                               "roughnessFactor": 0.5},
                 "extensions": {"KHR_materials_clearcoat": {
                     "clearcoatFactor": 1, "clearcoatTexture": {"index": 0},
                     "clearcoatRoughnessFactor": 1, "clearcoatRoughnessTexture": {"index": 0}}}}
    coated = document(lacquered, [{"uri": "clearcoat.png"}], 33071)
    coated["extensionsUsed"] = sorted(set(coated.get("extensionsUsed", [])) | {"KHR_materials_clearcoat"})
    (HERE / "clearcoat.gltf").write_text(json.dumps(coated, indent=1) + "\n")
    # A quarter turn of the uvs: u = (z + 1) / 2, v = (1 - x) / 2.
    turned = [((z + 1) / 2, (1 - x) / 2) for x, _, z in POSITIONS]
    (HERE / "normal-map-tangent.gltf").write_text(json.dumps(
        document(mapped, [{"uri": "normal-map.png"}], 10497, uv_sets=(turned,), tangent=(1, 0, 0, 1)), indent=1) + "\n")
    second = {"name": "Checker", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "texCoord": 1},
                                                          "metallicFactor": 0, "roughnessFactor": 1}}
    mirrored = [(1 - u, v) for u, v in UVS]
    (HERE / "textured-texcoord1.gltf").write_text(json.dumps(
        document(second, [{"uri": "checker4.png"}], 10497, uv_sets=(mirrored, UVS)), indent=1) + "\n")
    (HERE / "texcoord-missing.gltf").write_text(json.dumps(
        document(second, [{"uri": "checker4.png"}], 10497), indent=1) + "\n")
    # KHR_texture_transform on TEXCOORD_1 (its texCoord overrides the textureInfo's 0), against the
    # same transform applied here to the uvs, by the extension's matrix T(offset) R(rotation) S(scale).
    offset, rotation, scale = (0.25, 0.1), 0.3, (2.0, 1.5)
    c, s = math.cos(rotation), math.sin(rotation)
    baked = [(c * scale[0] * u + s * scale[1] * v + offset[0], -s * scale[0] * u + c * scale[1] * v + offset[1])
             for u, v in UVS]
    moved = {"name": "Checker", "pbrMetallicRoughness": {
        "baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {
            "offset": list(offset), "rotation": rotation, "scale": list(scale), "texCoord": 1}}},
        "metallicFactor": 0, "roughnessFactor": 1}}
    transformed = document(moved, [{"uri": "checker4.png"}], 10497, uv_sets=(mirrored, UVS))
    transformed["extensionsUsed"].append("KHR_texture_transform")
    (HERE / "textured-transform.gltf").write_text(json.dumps(transformed, indent=1) + "\n")
    (HERE / "textured-transform-baked.gltf").write_text(json.dumps(
        document(base, [{"uri": "checker4.png"}], 10497, uv_sets=(baked,)), indent=1) + "\n")
    for name, component in (("textured-uv8.gltf", 5121), ("textured-uv16.gltf", 5123)):
        (HERE / name).write_text(json.dumps(
            document(base, [{"uri": "checker4.png"}], 10497, uv_component=component), indent=1) + "\n")
    quantized = document(base, [{"uri": "checker4.png"}], 10497, quantized=True)
    quantized["extensionsUsed"].append("KHR_mesh_quantization")
    quantized["extensionsRequired"] = ["KHR_mesh_quantization"]
    quantized["nodes"][0]["scale"] = [1 / QUANTUM] * 3
    (HERE / "textured-quantized.gltf").write_text(json.dumps(quantized, indent=1) + "\n")
    emissive()


QUADRANTS = png(256, 256, [[(191,) * 3] * 128 + [(255,) * 3] * 128 for _ in range(128)] +
                [[(64,) * 3] * 128 + [(128,) * 3] * 128 for _ in range(128)])


def emissive():
    """The emitting quad alone (no camera, no light): a TOML scene places it with [[gltf]]."""
    (HERE / "emissive-quadrants.png").write_bytes(QUADRANTS)
    data = bytearray()
    # Counter-clockwise seen from +z; glTF's uv (0, 0) is the image's top left, at the top left corner.
    positions = [(-0.5, 0.3, 0), (0.5, 0.3, 0), (0.5, 1.3, 0), (-0.5, 1.3, 0)]
    uvs = [(0, 1), (1, 1), (1, 0), (0, 0)]
    views, accessors = [], []
    for raw, kind, component, count in ((b"".join(struct.pack("<3f", *p) for p in positions), "VEC3", 5126, 4),
                                        (b"".join(struct.pack("<2f", *t) for t in uvs), "VEC2", 5126, 4),
                                        (struct.pack("<6H", 0, 1, 2, 0, 2, 3), "SCALAR", 5123, 6)):
        while len(data) % 4:
            data.append(0)
        views.append({"buffer": 0, "byteOffset": len(data), "byteLength": len(raw)})
        data.extend(raw)
        accessors.append({"bufferView": len(views) - 1, "componentType": component, "count": count, "type": kind})
    accessors[0].update(min=[-0.5, 0.3, 0], max=[0.5, 1.3, 0])
    glow = {"name": "Glow", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1]},
            "emissiveFactor": [1, 1, 1], "emissiveTexture": {"index": 0},
            "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}}
    doc = {
        "asset": {"version": "2.0", "generator": "make_textured.py"},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"name": "Panel", "mesh": 0}],
        "meshes": [{"name": "Panel", "primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2,
                                                     "material": 0}]}],
        "materials": [glow],
        "textures": [{"source": 0, "sampler": 0}], "samplers": [{"wrapS": 10497, "wrapT": 10497}],
        "images": [{"uri": "emissive-quadrants.png"}],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(data)).decode()}],
        "bufferViews": views, "accessors": accessors,
    }
    (HERE / "emissive-texture.gltf").write_text(json.dumps(doc, indent=1) + "\n")


main()
