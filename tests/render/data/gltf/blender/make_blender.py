"""Writes the Blender-exported glTF files of the Cycles comparison (tests/render/test_gltf.cpp), and
Cycles' renders of the same scenes as 8x8-block means (<light>-cycles.txt), the test's reference.

Each file holds one light of one Blender kind (a point lamp of 500 W, a sun of 2 W/m^2, an
emissive square of strength 5) over a floor and a box, seen by a camera (orthographic: the sun's
scene seen by an orthographic camera of Orthographic Scale 14; cutout-mask and
cutout-blend: a sun through a black card cut out by its alpha; vertex-colors: the floor painted by a
colour attribute; see below); Blender's glTF exporter
writes it in its default Lighting Mode, "Standard" (candela and lux at 683 lm/W), and the
emission unconverted. Cycles renders
the scene as Blender holds it, with a Lambertian (Diffuse BSDF) material of albedo 0.8, a black
world and a box pixel filter; the test renders the exported file in lightpath with the same
material and compares block by block. No spot: Cycles 3.4 dims a spot's light towards the edge of
its cone (measured 1.01 to 1.15 of lightpath's across a 30-degree cone, about 1 / cos of the angle
off its axis), which glTF's spot does not.

Run (Blender 3.4, Debian's `blender`), from this folder:
  for light in point sun emissive cutout-mask cutout-blend vertex-colors orthographic; do blender -b --python make_blender.py -- $light; done
"""
import math
import os
import sys

import bpy
import numpy as np

WIDTH, HEIGHT, BLOCK, SPP = 96, 64, 8, 4096
HERE = os.path.dirname(os.path.abspath(__file__))
light = sys.argv[sys.argv.index("--") + 1]

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = WIDTH, HEIGHT, 100



def matte(name, base_color):
    """A Principled material of roughness 1 and specular 0 (F0 = 0 in lightpath: its base alone), and its BSDF."""
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    bsdf = material.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = base_color
    bsdf.inputs["Roughness"].default_value = 1.0
    bsdf.inputs["Specular"].default_value = 0.0
    return material, bsdf


white, principled = matte("White", (0.8, 0.8, 0.8, 1))
bpy.ops.mesh.primitive_plane_add(size=20, location=(0, 0, 0))
bpy.context.object.data.materials.append(white)
bpy.ops.mesh.primitive_cube_add(size=2, location=(0, 0, 1), rotation=(0, 0, 0.5))
bpy.context.object.data.materials.append(white)

if light == "point":
    bpy.ops.object.light_add(type="POINT", location=(3, -2, 4))
    bpy.context.object.data.energy = 500
    bpy.context.object.data.shadow_soft_size = 0
elif light in ("sun", "orthographic"):
    bpy.ops.object.light_add(type="SUN", location=(0, 0, 5), rotation=(0.6, 0.3, 0))
    bpy.context.object.data.energy = 2
    bpy.context.object.data.angle = 0
elif light == "emissive":
    # A 2 m square lamp facing down, emission strength 5: the floor sees its front, the camera its
    # back (Cycles' mesh lights emit from both sides; Blender writes the material doubleSided).
    lamp = bpy.data.materials.new("Lamp")
    lamp.use_nodes = True
    bsdf = lamp.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (0, 0, 0, 1)
    bsdf.inputs["Specular"].default_value = 0.0
    bsdf.inputs["Emission"].default_value = (1, 0.9, 0.8, 1)
    bsdf.inputs["Emission Strength"].default_value = 5
    bpy.ops.mesh.primitive_plane_add(size=2, location=(2, -1, 3.5), rotation=(math.pi, 0, 0))
    bpy.context.object.data.materials.append(lamp)
elif light in ("cutout-mask", "cutout-blend"):
    # A 4 m card 3 m above the floor (1 m above the box) under a sun, black (no light back from it), cut out by its
    # alpha as Blender holds it: "cutout-mask" an image's alpha in 2-texel stripes (8 x 8 texels,
    # Closest, blend mode Alpha Clip at 0.5: glTF's MASK), "cutout-blend" a constant alpha of 0.4
    # (blend mode Alpha Blend: glTF's BLEND). Cycles renders alpha as transparency either way.
    bpy.ops.object.light_add(type="SUN", location=(0, 0, 5), rotation=(0.35, 0.25, 0))
    bpy.context.object.data.energy = 2
    bpy.context.object.data.angle = 0
    card, bsdf = matte("Card", (0, 0, 0, 1))
    if light == "cutout-mask":
        stripes = bpy.data.images.new("stripes", 8, 8, alpha=True)
        stripes.pixels[:] = [v for _ in range(8) for x in range(8) for v in (0, 0, 0, 1.0 if x % 4 < 2 else 0.0)]
        stripes.pack()
        image = card.node_tree.nodes.new("ShaderNodeTexImage")
        image.image = stripes
        image.interpolation = "Closest"
        card.node_tree.links.new(image.outputs["Color"], bsdf.inputs["Base Color"])
        card.node_tree.links.new(image.outputs["Alpha"], bsdf.inputs["Alpha"])
        card.blend_method = "CLIP"
        card.alpha_threshold = 0.5
    else:
        bsdf.inputs["Alpha"].default_value = 0.4
        card.blend_method = "BLEND"
    bpy.ops.mesh.primitive_plane_add(size=4, location=(0.5, 0, 3))
    bpy.context.object.data.materials.append(card)
elif light == "vertex-colors":
    # The floor painted by a colour attribute (red, green, blue and white corners, float, per
    # vertex) that its material's base colour reads, under a sun: the exporter writes COLOR_0.
    bpy.ops.object.light_add(type="SUN", location=(0, 0, 5), rotation=(0.35, 0.25, 0))
    bpy.context.object.data.energy = 2
    bpy.context.object.data.angle = 0
    floor = bpy.data.objects["Plane"]
    colors = floor.data.color_attributes.new("Paint", "FLOAT_COLOR", "POINT")
    corners = {(-1, -1): (1, 0, 0, 1), (1, -1): (0, 1, 0, 1), (1, 1): (0, 0, 1, 1), (-1, 1): (1, 1, 1, 1)}
    for vertex in floor.data.vertices:
        colors.data[vertex.index].color = corners[(round(vertex.co.x / 10), round(vertex.co.y / 10))]
    painted, bsdf = matte("Painted", (1, 1, 1, 1))
    attribute = painted.node_tree.nodes.new("ShaderNodeVertexColor")
    attribute.layer_name = "Paint"
    painted.node_tree.links.new(attribute.outputs["Color"], bsdf.inputs["Base Color"])
    floor.data.materials.clear()
    floor.data.materials.append(painted)
else:
    raise SystemExit("expected point, sun, emissive, cutout-mask, cutout-blend, vertex-colors or orthographic, got " +
                     light)
bpy.ops.object.camera_add(location=(0, -10, 6), rotation=(math.radians(60), 0, 0))
scene.camera = bpy.context.object
if light == "orthographic":
    # 14 m across the image's width (Blender's Orthographic Scale spans its longer side): the exporter
    # writes xmag 7 and ymag 7 * 64 / 96.
    scene.camera.data.type = "ORTHO"
    scene.camera.data.ortho_scale = 14

bpy.ops.export_scene.gltf(filepath=os.path.join(HERE, light + ".glb"), export_format="GLB", export_lights=True,
                          export_cameras=True, export_apply=True)

tree = white.node_tree
diffuse = tree.nodes.new("ShaderNodeBsdfDiffuse")
diffuse.inputs["Color"].default_value = (0.8, 0.8, 0.8, 1)
tree.links.new(diffuse.outputs["BSDF"], tree.nodes["Material Output"].inputs["Surface"])
if light == "vertex-colors":
    # Lambertian too, its colour the attribute's (lightpath reads the exported Principled with
    # specular 0 as F0 = 0: a Lambertian base alone).
    tree = painted.node_tree
    diffuse = tree.nodes.new("ShaderNodeBsdfDiffuse")
    tree.links.new(attribute.outputs["Color"], diffuse.inputs["Color"])
    tree.links.new(diffuse.outputs["BSDF"], tree.nodes["Material Output"].inputs["Surface"])
world = bpy.data.worlds.new("black")
scene.world = world
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = SPP
scene.cycles.use_denoising = False
scene.cycles.use_adaptive_sampling = False
scene.cycles.seed = 1
scene.cycles.max_bounces = scene.cycles.diffuse_bounces = 8
scene.cycles.sample_clamp_direct = scene.cycles.sample_clamp_indirect = 0
scene.cycles.filter_type = "BOX"
scene.cycles.filter_width = 1.0
scene.view_settings.view_transform = "Standard"
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.filepath = os.path.join("/tmp", "cycles-" + light + ".exr")
bpy.ops.render.render(write_still=True)

image = bpy.data.images.load(scene.render.filepath)
pixels = np.array(image.pixels[:], dtype=np.float64).reshape(HEIGHT, WIDTH, 4)[::-1, :, :3]  # top row first
blocks = pixels.mean(axis=2).reshape(HEIGHT // BLOCK, BLOCK, WIDTH // BLOCK, BLOCK).mean(axis=(1, 3))
with open(os.path.join(HERE, light + "-cycles.txt"), "w") as out:
    out.write(f"# Cycles (Blender {bpy.app.version_string}), {SPP} spp: the mean of R, G and B over each {BLOCK}x{BLOCK}"
              f" block of a {WIDTH}x{HEIGHT} render, top row first\n")
    for row in blocks:
        out.write(" ".join(f"{v:.6f}" for v in row) + "\n")
