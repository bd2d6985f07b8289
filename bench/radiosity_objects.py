#!/usr/bin/env python3
"""Radiosity against the path tracer per object and bounce (issue 27): bench/radiosity_bounces.py's
measure, split by the object the camera sees, so errors of opposite sign on two objects do not hide
in a scene's mean.

For each object, both integrators write E<.D'object'>D{k-1}L for k = 1, 2, 3 and E<.D'object'>D{3,}L
(L: the lights radiosity solves, as bench/radiosity_bounces.py) at 64x64 (max depth 6); the path
tracer's images (1024 spp, Sobol) are cached in the output folder. Per object and bounce it prints
radiosity's sum over path's (the luminance over the object's pixels) and the worst ratio over the
4x4 regions holding at least a twentieth of an average region's light of that object.

Usage: bench/radiosity_objects.py --scene scenes/lecture-room.toml --objects floor,bunny,...
                                  [--build build] [--out out/radiosity-objects] [--spp 1024] [-- extra radiosity options]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from radiosity_bounces import LIGHTS, regions  # noqa: E402


def bounces(obj):
    seen = f"E<.D'{obj}'>"
    return [("b1", seen + LIGHTS), ("b2", seen + "D" + LIGHTS), ("b3", seen + "DD" + LIGHTS), ("b4", seen + "D{3,}" + LIGHTS)]


def layer(obj, bounce):
    return obj.replace("-", "_") + "_" + bounce


def render(lightpath, scene, integrator, image, objects, extra, spp):
    import subprocess
    lpes = [arg for obj in objects for name, expression in bounces(obj) for arg in ("--lpe", f"{layer(obj, name)}={expression}")]
    command = [lightpath, "render", scene, "--integrator", integrator, "--resolution", "64x64", "--max-depth", "6",
               "--spp", str(spp), "--sampler", "sobol", "--threads", "2", "--no-beauty", "--quiet", "-o", image,
               *lpes, *extra]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(command)}: {done.stderr}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default="build")
    parser.add_argument("--out", default="out/radiosity-objects")
    parser.add_argument("--spp", type=int, default=1024)
    parser.add_argument("--scene", required=True)
    parser.add_argument("--objects", required=True)
    parser.add_argument("extra", nargs="*")
    args = parser.parse_args()
    lightpath = os.path.join(args.build, "lightpath")
    os.makedirs(args.out, exist_ok=True)
    objects = args.objects.split(",")
    name = os.path.splitext(os.path.basename(args.scene))[0]
    radiosity = os.path.join(args.out, name + "-objects-radiosity.exr")
    render(lightpath, args.scene, "radiosity", radiosity, objects, args.extra, 16)
    reference = os.path.join(args.out, f"{name}-objects-{'_'.join(objects)}-path-{args.spp}.exr")
    if not os.path.exists(reference):
        render(lightpath, args.scene, "path", reference, objects, [], args.spp)
    print(f"{'object':16} " + "  ".join(f"{n + ' mean':>8} {n + ' worst':>8}" for n, _ in bounces("x")))
    for obj in objects:
        cells = []
        for bounce, _ in bounces(obj):
            a, b = regions(radiosity, layer(obj, bounce)), regions(reference, layer(obj, bounce))
            total_a, total_b = sum(a), sum(b)
            if not total_b > 0.0:
                cells.append(f"{'-':>8} {'-':>8}")
                continue
            worst = max((x / y for x, y in zip(a, b) if y > total_b / 16.0 / 20.0), key=lambda r: abs(r - 1.0))
            cells.append(f"{total_a / total_b:8.3f} {worst:8.3f}")
        print(f"{obj:16} " + "  ".join(cells), flush=True)


if __name__ == "__main__":
    sys.exit(main())
