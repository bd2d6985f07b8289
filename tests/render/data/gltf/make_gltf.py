#!/usr/bin/env python3
"""Writes the small glTF 2.0 files of the glTF tests (JSON with base64 buffers), beside this script.

point.gltf     a floor and a metal panel (placed through a two-node hierarchy: translation,
               rotation, scale), a KHR_lights_punctual point light and a perspective camera;
               point.toml is the same scene written by hand.
emissive.gltf  the same without the lamp, lit by an emissive panel (emissiveFactor times
               KHR_materials_emissive_strength); emissive.toml by hand.
point.glb      point.gltf as binary glTF: its buffer in the BIN chunk.
spot.gltf      the same lit by a KHR_lights_punctual spot tilted by its node; spot.toml by hand.
directional.gltf  the same lit by a directional light tilted by its node; directional.toml by hand.
sparse.gltf    positions through sparse accessors (glTF 2.0, 3.6.2.3), one over a bufferView, one
               over zeros; bad_sparse.gltf with its substitution's indices out of order.
bad_index.gltf an index beyond the vertices (the located error).
volume.gltf    a unit cube of clear glass of index 1 (KHR_materials_transmission, KHR_materials_ior)
               bounding an absorbing medium (KHR_materials_volume: attenuationColor [0.8, 0.5, 1]
               after 0.5): seen through, white light leaves it as attenuationColor^(1 / 0.5).
Run: python3 make_gltf.py
"""
import base64
import json
import math
import struct
from pathlib import Path

HERE = Path(__file__).resolve().parent


class Builder:
    def __init__(self):
        self.data = bytearray()
        self.views, self.accessors, self.meshes = [], [], []

    def _view(self, raw):
        while len(self.data) % 4:
            self.data.append(0)
        self.views.append({"buffer": 0, "byteOffset": len(self.data), "byteLength": len(raw)})
        self.data += raw
        return len(self.views) - 1

    def vec3(self, points):
        raw = b"".join(struct.pack("<3f", *p) for p in points)
        lo = [min(p[i] for p in points) for i in range(3)]
        hi = [max(p[i] for p in points) for i in range(3)]
        self.accessors.append({"bufferView": self._view(raw), "componentType": 5126, "count": len(points),
                               "type": "VEC3", "min": lo, "max": hi})
        return len(self.accessors) - 1

    def sparse_vec3(self, count, base, replaced):
        """A VEC3 accessor of `count` elements: `base` (None: no bufferView, zeros) with the points of
        `replaced` ({index: point}) put in through a sparse substitution, indices as UNSIGNED_BYTE."""
        order = list(replaced)
        accessor = {"componentType": 5126, "count": count, "type": "VEC3",
                    "sparse": {"count": len(order),
                               "indices": {"bufferView": self._view(struct.pack("<%dB" % len(order), *order)),
                                           "componentType": 5121},
                               "values": {"bufferView": self._view(b"".join(struct.pack("<3f", *replaced[i])
                                                                            for i in order))}}}
        if base is not None:
            accessor["bufferView"] = self._view(b"".join(struct.pack("<3f", *p) for p in base))
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def indices(self, values, component):
        fmt = {5121: "B", 5123: "H", 5125: "I"}[component]
        raw = struct.pack("<%d%s" % (len(values), fmt), *values)
        self.accessors.append({"bufferView": self._view(raw), "componentType": component, "count": len(values),
                               "type": "SCALAR"})
        return len(self.accessors) - 1

    def mesh(self, name, points, normal, order, component, material):
        prim = {"attributes": {"POSITION": self.vec3(points), "NORMAL": self.vec3([normal] * len(points))},
                "indices": self.indices(order, component), "material": material}
        self.meshes.append({"name": name, "primitives": [prim]})
        return len(self.meshes) - 1

    def cube(self, name, half, material):
        """A cube of side 2 half about the origin, each face two triangles wound counter-clockwise seen
        from outside, with its outward normal."""
        points, normals, order = [], [], []
        # (normal, u, v) with u x v = normal: corners -u-v, u-v, u+v, -u+v turn counter-clockwise.
        faces = [((1, 0, 0), (0, 1, 0), (0, 0, 1)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
                 ((0, 1, 0), (0, 0, 1), (1, 0, 0)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
                 ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (0, 1, 0), (1, 0, 0))]
        for n, u, v in faces:
            first = len(points)
            for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                points.append(tuple(half * (n[i] + su * u[i] + sv * v[i]) for i in range(3)))
                normals.append(n)
            order += [first, first + 1, first + 2, first, first + 2, first + 3]
        prim = {"attributes": {"POSITION": self.vec3(points), "NORMAL": self.vec3(normals)},
                "indices": self.indices(order, 5121), "material": material}
        self.meshes.append({"name": name, "primitives": [prim]})
        return len(self.meshes) - 1

    def glb(self, **rest):
        doc = self.document(**rest)
        doc["buffers"] = [{"byteLength": len(self.data)}]
        text = json.dumps(doc).encode()
        text += b" " * (-len(text) % 4)
        binary = bytes(self.data) + b"\0" * (-len(self.data) % 4)
        chunks = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(binary), b"BIN\0") + binary
        return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks

    def document(self, **rest):
        uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.data)).decode()
        doc = {"asset": {"version": "2.0", "generator": "lightpath tests/render/data/gltf/make_gltf.py"},
               "buffers": [{"byteLength": len(self.data), "uri": uri}], "bufferViews": self.views,
               "accessors": self.accessors, "meshes": self.meshes}
        doc.update(rest)
        return doc


def quaternion(axis, degrees):
    s = math.sin(math.radians(degrees) / 2)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(math.radians(degrees) / 2)]


FLOOR = [(-2, 0, -2), (2, 0, -2), (2, 0, 2), (-2, 0, 2)]
UNIT_QUAD = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
MATERIALS = [
    # A name with a space: its label is Floor_Paint.
    {"name": "Floor Paint", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.6, 0.4, 1], "metallicFactor": 0,
                                                     "roughnessFactor": 0.6}},
    {"name": "Panel", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1], "metallicFactor": 1,
                                               "roughnessFactor": 0.3}},
]
CAMERA = {"name": "Cam", "type": "perspective",
          "perspective": {"yfov": 0.7, "aspectRatio": 4 / 3, "znear": 0.1}}
# Looks down by 20 degrees from (0, 2, 5).
CAMERA_NODE = {"name": "Cam", "camera": 0, "translation": [0, 2, 5], "rotation": quaternion((1, 0, 0), -20)}


def scene_with_panel(builder):
    floor = builder.mesh("Floor", FLOOR, (0, 1, 0), [0, 2, 1, 0, 3, 2], 5123, 0)
    panel = builder.mesh("PanelMesh", UNIT_QUAD, (0, 0, 1), [0, 1, 2, 0, 2, 3], 5121, 1)
    nodes = [
        {"name": "Floor", "mesh": floor},
        {"name": "Group", "translation": [0, 1, -1], "children": [2]},
        # Half size, turned 90 degrees about y, moved by x = 1: the panel ends at x = 1 facing +x.
        {"name": "Panel", "mesh": panel, "scale": [0.5, 0.5, 0.5], "rotation": quaternion((0, 1, 0), 90),
         "translation": [1, 0, 0]},
        CAMERA_NODE,
    ]
    return nodes


def write(name, doc):
    (HERE / name).write_text(json.dumps(doc, indent=1) + "\n")


def point():
    b = Builder()
    nodes = scene_with_panel(b)
    nodes.append({"name": "Lamp", "translation": [-0.5, 2.5, 0.5], "extensions": {"KHR_lights_punctual": {"light": 0}}})
    rest = dict(materials=MATERIALS, nodes=nodes, cameras=[CAMERA], scenes=[{"nodes": [0, 1, 3, 4]}], scene=0,
                extensionsUsed=["KHR_lights_punctual"],
                extensions={"KHR_lights_punctual": {"lights": [{"name": "Lamp", "type": "point", "intensity": 20 * 683,
                                                                "color": [1, 1, 1]}]}})
    write("point.gltf", b.document(**rest))
    (HERE / "point.glb").write_bytes(b.glb(**rest))


def punctual(name, light, node):
    b = Builder()
    nodes = scene_with_panel(b)
    nodes.append(dict(node, extensions={"KHR_lights_punctual": {"light": 0}}))
    write(name + ".gltf", b.document(
        materials=MATERIALS, nodes=nodes, cameras=[CAMERA], scenes=[{"nodes": [0, 1, 3, 4]}], scene=0,
        extensionsUsed=["KHR_lights_punctual"], extensions={"KHR_lights_punctual": {"lights": [light]}}))


def spot():
    # Turned -70 degrees about x: its -z points to (0, -sin 70, -cos 70), down and away from the camera.
    punctual("spot", {"name": "Spot", "type": "spot", "intensity": 30 * 683, "color": [1, 0.9, 0.8],
                      "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}},
             {"name": "Spot", "translation": [-0.3, 2.5, 0.8], "rotation": quaternion((1, 0, 0), -70)})


def directional():
    # Turned -50 degrees about x, then 30 about y (the node's rotation is one quaternion: y after x).
    q = quaternion_product(quaternion((0, 1, 0), 30), quaternion((1, 0, 0), -50))
    punctual("directional", {"name": "Sun", "type": "directional", "intensity": 3 * 683, "color": [1, 1, 0.9]},
             {"name": "Sun", "translation": [5, 5, 5], "rotation": q})


def quaternion_product(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz]


def emissive():
    b = Builder()
    nodes = scene_with_panel(b)
    glow = {"name": "Glow", "emissiveFactor": [1, 0.9, 0.8],
            "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 5}}}
    lamp = b.mesh("LampMesh", UNIT_QUAD, (0, 0, 1), [0, 1, 2, 0, 2, 3], 5125, 2)
    # Half size, turned 90 degrees about x (its normal +z becomes -y), at height 2.5: facing down.
    nodes.append({"name": "Lightpanel", "mesh": lamp, "scale": [0.5, 0.5, 0.5],
                  "rotation": quaternion((1, 0, 0), 90), "translation": [0, 2.5, 0]})
    write("emissive.gltf", b.document(
        materials=MATERIALS + [glow], nodes=nodes, cameras=[CAMERA], scenes=[{"nodes": [0, 1, 3, 4]}], scene=0,
        extensionsUsed=["KHR_materials_emissive_strength"]))


def sparse():
    # The quad from (-1, -1) to (1, 1) whose corner 2 the sparse substitution moves to (2, 2, 0), and a
    # triangle from zeros (no bufferView) with corners 1 and 2 put in: (1, 0, 0) and (0, 1, 0).
    # bad_sparse.gltf gives the substitution's indices out of order.
    for name, order in (("sparse.gltf", {2: (2, 2, 0)}), ("bad_sparse.gltf", {3: (0, 2, 0), 2: (2, 2, 0)})):
        b = Builder()
        kite = b.sparse_vec3(4, UNIT_QUAD, order)
        b.meshes.append({"name": "Kite", "primitives": [{"attributes": {"POSITION": kite},
                                                         "indices": b.indices([0, 1, 2, 0, 2, 3], 5121)}]})
        corner = b.sparse_vec3(3, None, {1: (1, 0, 0), 2: (0, 1, 0)})
        b.meshes.append({"name": "Corner", "primitives": [{"attributes": {"POSITION": corner}}]})
        write(name, b.document(nodes=[{"mesh": 0}, {"mesh": 1, "translation": [0, 0, -1]}], scenes=[{"nodes": [0, 1]}]))


def bad_index():
    b = Builder()
    b.mesh("Broken", UNIT_QUAD, (0, 0, 1), [0, 1, 2, 0, 2, 7], 5123, 0)
    write("bad_index.gltf", b.document(materials=MATERIALS[:1], nodes=[{"mesh": 0}], scenes=[{"nodes": [0]}]))


def volume():
    b = Builder()
    b.cube("Cube", 0.5, 0)
    glass = {"name": "Tinted Glass",
             "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0, "roughnessFactor": 0},
             "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_ior": {"ior": 1},
                            "KHR_materials_volume": {"thicknessFactor": 1, "attenuationDistance": 0.5,
                                                     "attenuationColor": [0.8, 0.5, 1]}}}
    write("volume.gltf", b.document(
        materials=[glass], nodes=[{"name": "Cube", "mesh": 0}], scenes=[{"nodes": [0]}], scene=0,
        extensionsUsed=["KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume"]))


point()
spot()
directional()
emissive()
sparse()
bad_index()
volume()
