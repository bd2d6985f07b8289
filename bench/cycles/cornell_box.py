# Runs inside Blender (`blender -b --factory-startup -P bench/cycles/cornell_box.py -- ARGS`):
# McGuire's CornellBox-Original lit by its lamp alone, rendered by Cycles on the CPU at each of the
# given sample counts, each render timed and written as a 32-bit float EXR. bench/vs_cycles.py
# drives it; the scene matches bench/cycles/cornell-lamp.toml:
#   - geometry read from the OBJ here (no importer: its axis conversion and quad splitting would
#     differ), quads split as fans, y up kept: the camera at (0, 1, 3.9) looks down -z with +y up,
#     which is a Blender camera's unrotated pose; 37 degrees of vertical field of view;
#   - every material a Diffuse BSDF of the MTL's Kd; the lamp adds an Emission of its Ke on its
#     front face only (lightpath's triangles emit on their winding's side);
#   - lightpath's --max-depth 5 is five scattering events, i.e. Cycles' 4 bounces (Cycles' 0
#     bounces is direct light alone); both use Russian roulette;
#   - no clamping (Cycles' default clamps indirect light at 10), no glossy filter, no denoising, no
#     adaptive sampling, Cycles' default pixel filter (Blackman-Harris, 1.5 px) and sampling pattern.
#   - `metal=NAME:ROUGHNESS` (repeatable, before the budgets) makes MTL material NAME a Principled
#     BSDF with metallic 1, GGX (not multiscatter), the roughness given (alpha = roughness^2, as
#     lightpath's `microfacet`) and base colour its Kd: F0 = Kd with Schlick-like Fresnel, as
#     lightpath's `microfacet` with metallic = 1 (bench/cycles/cornell-glossy.toml).
# Arguments: OBJ OUT_DIR SIZE THREADS SEED [metal=NAME:ROUGHNESS ...] SPP [SPP ...]. Prints one
# line per render, its wall time and the process's CPU time during it:
#   cycles spp N seconds T cpu C file PATH
import math
import os
import sys
import time

import bpy


def parse_obj(path):
    """Vertices and (material, triangle) faces of an OBJ, negative indices resolved. A face on the
    same corners as an earlier one is dropped: CornellBox-Original's tall box "Bottom Face" is
    `f -8 -7 -6 -5`, the front face again, and Cycles' rays leaving one copy hit the other, so
    the face renders black. lightpath renders it as one face."""
    vertices, faces, material, seen = [], [], None, set()
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                vertices.append(tuple(float(w) for w in words[1:4]))
            elif words[0] == "usemtl":
                material = words[1]
            elif words[0] == "f":
                idx = []
                for w in words[1:]:
                    i = int(w.split("/")[0])
                    idx.append(i - 1 if i > 0 else len(vertices) + i)
                corners = frozenset(vertices[i] for i in idx)
                if corners in seen:
                    continue
                seen.add(corners)
                for k in range(1, len(idx) - 1):
                    faces.append((material, (idx[0], idx[k], idx[k + 1])))
    return vertices, faces


def parse_mtl(path):
    materials, name = {}, None
    with open(path) as f:
        for line in f:
            words = line.split("#")[0].split()
            if not words:
                continue
            if words[0] == "newmtl":
                name = words[1]
                materials[name] = {}
            elif name and words[0] in ("Kd", "Ke"):
                materials[name][words[0]] = tuple(float(w) for w in words[1:4])
    return materials


def make_material(name, kd, ke, metal_roughness=None):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    if metal_roughness is None:
        bsdf = nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Color"].default_value = (*kd, 1.0)
        bsdf.inputs["Roughness"].default_value = 0.0  # Lambert, not Oren-Nayar
    else:
        bsdf = nodes.new("ShaderNodeBsdfPrincipled")
        bsdf.distribution = "GGX"
        bsdf.inputs["Base Color"].default_value = (*kd, 1.0)
        bsdf.inputs["Metallic"].default_value = 1.0
        bsdf.inputs["Roughness"].default_value = metal_roughness
    shader = bsdf.outputs["BSDF"]
    if ke and max(ke) > 0.0:
        emission = nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = (*ke, 1.0)
        # Strength 1 - backfacing: the front face emits Ke, the back face nothing.
        geometry = nodes.new("ShaderNodeNewGeometry")
        front = nodes.new("ShaderNodeMath")
        front.operation = "SUBTRACT"
        front.inputs[0].default_value = 1.0
        links.new(geometry.outputs["Backfacing"], front.inputs[1])
        links.new(front.outputs["Value"], emission.inputs["Strength"])
        add = nodes.new("ShaderNodeAddShader")
        links.new(bsdf.outputs["BSDF"], add.inputs[0])
        links.new(emission.outputs["Emission"], add.inputs[1])
        shader = add.outputs["Shader"]
    links.new(shader, out.inputs["Surface"])
    return mat


def build_scene(obj_path, size, threads, seed, metals):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    vertices, faces = parse_obj(obj_path)
    mtl = parse_mtl(os.path.join(os.path.dirname(obj_path), os.path.splitext(os.path.basename(obj_path))[0] + ".mtl"))
    names = sorted({m for m, _ in faces})
    mesh = bpy.data.meshes.new("cornell")
    mesh.from_pydata(vertices, [], [tri for _, tri in faces])
    for name in names:
        mesh.materials.append(make_material(name, mtl[name].get("Kd", (0.0, 0.0, 0.0)), mtl[name].get("Ke"),
                                            metals.get(name)))
    for polygon, (name, _) in zip(mesh.polygons, faces):
        polygon.material_index = names.index(name)
    mesh.update()
    scene.collection.objects.link(bpy.data.objects.new("cornell", mesh))

    camera = bpy.data.cameras.new("camera")
    camera.sensor_fit = "VERTICAL"
    camera.angle_y = math.radians(37.0)
    camera_object = bpy.data.objects.new("camera", camera)
    camera_object.location = (0.0, 1.0, 3.9)
    camera_object.rotation_euler = (0.0, 0.0, 0.0)  # looks down -z, +y up
    scene.collection.objects.link(camera_object)
    scene.camera = camera_object
    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.world = world

    render = scene.render
    render.engine = "CYCLES"
    render.resolution_x = render.resolution_y = size
    render.resolution_percentage = 100
    render.threads_mode = "FIXED"
    render.threads = threads
    render.image_settings.file_format = "OPEN_EXR"
    render.image_settings.color_depth = "32"
    render.image_settings.exr_codec = "ZIP"
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.max_bounces = cycles.diffuse_bounces = 4
    cycles.glossy_bounces = cycles.transmission_bounces = cycles.transparent_max_bounces = 4
    cycles.caustics_reflective = cycles.caustics_refractive = True
    # Filter Glossy off: its default (1) widens glossy lobes after a diffuse bounce, a biased
    # shortcut that made the glossy box's short block up to 1.8x brighter than both lightpath's
    # path tracer and Cycles' own unbiased estimate (which agree within 1% per block).
    cycles.blur_glossy = 0.0
    cycles.seed = seed
    cycles.use_animated_seed = False
    return scene


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    obj_path, out_dir, size, threads, seed = args[0], args[1], int(args[2]), int(args[3]), int(args[4])
    metals = {}
    for a in args[5:]:
        if a.startswith("metal="):
            name, roughness = a[len("metal="):].split(":")
            metals[name] = float(roughness)
    spps = [int(a) for a in args[5:] if not a.startswith("metal=")]
    scene = build_scene(obj_path, size, threads, seed, metals)
    print(f"cycles pattern {scene.cycles.sampling_pattern} filter {scene.cycles.pixel_filter_type} "
          f"{scene.cycles.filter_width} bounces {scene.cycles.max_bounces}", flush=True)
    scene.cycles.samples = 1
    bpy.ops.render.render()  # warm-up: loads the kernels
    for spp in spps:
        scene.cycles.samples = spp
        start, cpu_start = time.perf_counter(), time.process_time()
        bpy.ops.render.render()
        seconds, cpu = time.perf_counter() - start, time.process_time() - cpu_start
        path = os.path.join(out_dir, f"cycles-{spp}-seed{seed}.exr")
        bpy.data.images["Render Result"].save_render(path)
        print(f"cycles spp {spp} seconds {seconds:.4f} cpu {cpu:.4f} file {path}", flush=True)


main()
