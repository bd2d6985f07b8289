#!/usr/bin/env python3
"""Radiosity against the path tracer, bounce by bounce, on every shipped scene (issue 27).

For each scenes/*.toml that radiosity renders, both integrators write EDL, EDDL, EDDDL and
ED{4,}L (L: the lights radiosity solves, below) at 64x64 (max depth 6); the path tracer's images (1024 spp, Sobol) are cached in the
output folder. Per bounce it prints radiosity's mean over path's (the image's luminance) and the
worst ratio over the 4x4 regions, leaving out regions with less than a twentieth of an average
region's light (the path tracer's noise is the whole difference there), as
tests/render/test_radiosity.cpp's bounceErrors does. Radiosity runs at default settings; its
process's CPU seconds are printed (user + system, both threads).

Usage: bench/radiosity_bounces.py [--build build] [--out out/radiosity-bounces] [--spp 1024]
                                  [--scenes a,b] [-- extra radiosity options]
"""
import argparse
import os
import re
import resource
import subprocess
import sys

# Radiosity's lights: every light but the ambient term, and emitting objects; the background lights
# nothing in radiosity (docs/integrators.md), so the path tracer's sky and ambient light are left out.
LIGHTS = "(<L.[^'ambient']>|O)"
BOUNCES = [("b1", "ED" + LIGHTS), ("b2", "EDD" + LIGHTS), ("b3", "EDDD" + LIGHTS), ("b4", "ED{4,}" + LIGHTS)]


def luminance(r, g, b):
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def regions(image, layer):
    """The 4x4 box averages of one layer's luminance, row by row."""
    small = image[:-4] + f"-{layer}-4x4.exr"
    subprocess.run(["oiiotool", image, "--ch", f"{layer}.R,{layer}.G,{layer}.B", "--resize:filter=box", "4x4", "-o", small],
                   check=True)
    out = subprocess.run(["oiiotool", "--dumpdata", small], check=True, capture_output=True, text=True).stdout
    os.remove(small)
    values = []
    for line in out.splitlines():
        match = re.match(r"\s*Pixel \(\d+, \d+\):\s*(.*)", line)
        if match:
            r, g, b = (float(v) for v in match.group(1).split()[:3])
            values.append(luminance(r, g, b))
    if len(values) != 16:
        raise RuntimeError(f"{image}: expected 16 regions of {layer}, got {len(values)}")
    return values


def render(lightpath, scene, integrator, image, extra, spp):
    lpes = [arg for name, expression in BOUNCES for arg in ("--lpe", f"{name}={expression}")]
    command = [lightpath, "render", scene, "--integrator", integrator, "--resolution", "64x64", "--max-depth", "6",
               "--spp", str(spp), "--sampler", "sobol", "--threads", "2", "--no-beauty", "--quiet", "-o", image,
               *lpes, *extra]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run(command, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return done.returncode, done.stderr + done.stdout, cpu


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default="build")
    parser.add_argument("--out", default="out/radiosity-bounces")
    parser.add_argument("--spp", type=int, default=1024)
    parser.add_argument("--scenes", default="")
    parser.add_argument("extra", nargs="*")
    args = parser.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    lightpath = os.path.join(args.build, "lightpath")
    os.makedirs(args.out, exist_ok=True)
    scenes = sorted(f[:-5] for f in os.listdir(os.path.join(root, "scenes")) if f.endswith(".toml"))
    if args.scenes:
        scenes = [s for s in scenes if s in args.scenes.split(",")]
    print(f"{'scene':24} {'cpu_s':>6}  " + "  ".join(f"{n + ' mean':>8} {n + ' worst':>8}" for n, _ in BOUNCES))
    for scene in scenes:
        path = os.path.join(root, "scenes", scene + ".toml")
        radiosity = os.path.join(args.out, scene + "-radiosity.exr")
        code, text, cpu = render(lightpath, path, "radiosity", radiosity, args.extra, 16)
        if code != 0:
            print(f"{scene:24} refused: {text.strip().splitlines()[-1] if text.strip() else code}")
            continue
        reference = os.path.join(args.out, f"{scene}-path-lights-{args.spp}.exr")
        if not os.path.exists(reference):
            code, text, _ = render(lightpath, path, "path", reference, [], args.spp)
            if code != 0:
                print(f"{scene:24} path failed: {text.strip()}")
                continue
        cells = []
        for name, _ in BOUNCES:
            a, b = regions(radiosity, name), regions(reference, name)
            total_a, total_b = sum(a), sum(b)
            if not total_b > 0.0:
                cells.append(f"{'-':>8} {'-':>8}")
                continue
            worst = max((abs(x / y - 1.0) for x, y in zip(a, b) if y > total_b / 16.0 / 20.0), default=0.0)
            cells.append(f"{total_a / total_b:8.3f} {worst:8.1%}")
        print(f"{scene:24} {cpu:6.1f}  " + "  ".join(cells), flush=True)


if __name__ == "__main__":
    sys.exit(main())
