#!/usr/bin/env python3
"""Radiosity against the path tracer, bounce by bounce, on every shipped scene (issue 27).

For each scenes/*.toml that radiosity renders, both integrators write EDL, EDDL, EDDDL and
ED{4,}L (L: the lights radiosity solves, below) at 64x64 (max depth 6). The path tracer's reference
is several independent renders (Sobol, one seed each; cached in the output folder): their mean is
the reference and their spread its standard error. Per bounce it prints radiosity's mean over
path's (the image's luminance) with the reference's standard error, and the worst ratio over the
4x4 regions it can judge: regions with at least a twentieth of an average region's light (as
tests/render/test_radiosity.cpp's bounceErrors) whose reference is known to --resolve. At 1024
spp the later bounces' dim regions differ by up to 48% between two seeds of the path tracer
alone, so a region the reference cannot resolve is counted ("open"), not judged. Radiosity runs
at default settings; its process's CPU seconds are printed (user + system, both threads).

Usage: bench/radiosity_bounces.py [--build build] [--out out/radiosity-bounces] [--spp 16384] [--seeds 8]
                                  [--scenes a,b] [-- extra radiosity options]
"""
import argparse
import os
import resource
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

# Radiosity's lights: every light but the ambient term, and emitting objects; the background lights
# nothing in radiosity (docs/integrators.md), so the path tracer's sky and ambient light are left out.
LIGHTS = "(<L.[^'ambient']>|O)"
BOUNCES = [("b1", "ED" + LIGHTS), ("b2", "EDD" + LIGHTS), ("b3", "EDDD" + LIGHTS), ("b4", "ED{4,}" + LIGHTS)]


def luminance(image):
    return 0.2126 * image[..., 0] + 0.7152 * image[..., 1] + 0.0722 * image[..., 2]


def regions(path, layer):
    """The 4x4 box sums of one layer's luminance, as a 4x4 array."""
    buf = oiio.ImageBuf(path)
    names = list(buf.spec().channelnames)
    pixels = buf.get_pixels(oiio.FLOAT)
    image = luminance(pixels[:, :, [names.index(f"{layer}.{c}") for c in "RGB"]])
    h, w = image.shape
    return image.reshape(4, h // 4, 4, w // 4).sum(axis=(1, 3))


def render(lightpath, scene, integrator, image, extra, spp, seed=0):
    lpes = [arg for name, expression in BOUNCES for arg in ("--lpe", f"{name}={expression}")]
    command = [lightpath, "render", scene, "--integrator", integrator, "--resolution", "64x64", "--max-depth", "6",
               "--spp", str(spp), "--seed", str(seed), "--sampler", "sobol", "--threads", "2", "--no-beauty", "--quiet", "-o", image,
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
    parser.add_argument("--spp", type=int, default=16384, help="the path tracer's samples per pixel, over all seeds")
    parser.add_argument("--radiosity-spp", type=int, default=256,
                        help="radiosity's samples per pixel (its final gather's noise falls with them)")
    parser.add_argument("--seeds", type=int, default=8, help="independent path references the samples are split into")
    parser.add_argument("--resolve", type=float, default=0.0125,
                        help="judge a region only where the reference's standard error is below this (relative)")
    parser.add_argument("--scenes", default="")
    parser.add_argument("extra", nargs="*")
    args = parser.parse_args()
    if args.seeds < 2 or args.spp % args.seeds:
        parser.error("--seeds must be at least 2 and divide --spp")
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    lightpath = os.path.join(args.build, "lightpath")
    os.makedirs(args.out, exist_ok=True)
    scenes = sorted(f[:-5] for f in os.listdir(os.path.join(root, "scenes")) if f.endswith(".toml"))
    if args.scenes:
        scenes = [s for s in scenes if s in args.scenes.split(",")]
    each = args.spp // args.seeds
    print(f"path reference: {args.spp} spp as {args.seeds} seeds of {each}; a region is judged where it holds at least"
          f" 1/20 of an average region's light and the reference's standard error is below {args.resolve:.2%}")
    print(f"{'scene':24} {'cpu_s':>6}  " + "  ".join(f"{n + ' mean':>13} {n + ' worst':>8} {'open':>4}" for n, _ in BOUNCES))
    for scene in scenes:
        path = os.path.join(root, "scenes", scene + ".toml")
        radiosity = os.path.join(args.out, scene + "-radiosity.exr")
        code, text, cpu = render(lightpath, path, "radiosity", radiosity, args.extra, args.radiosity_spp)
        if code != 0:
            print(f"{scene:24} refused: {text.strip().splitlines()[-1] if text.strip() else code}")
            continue
        references = []
        for seed in range(args.seeds):
            reference = os.path.join(args.out, f"{scene}-path-{each}-seed{seed}.exr")
            if not os.path.exists(reference):
                code, text, _ = render(lightpath, path, "path", reference, [], each, seed)
                if code != 0:
                    print(f"{scene:24} path failed: {text.strip()}")
                    break
            references.append(reference)
        if len(references) != args.seeds:
            continue
        cells = []
        for name, _ in BOUNCES:
            ours = regions(radiosity, name)
            runs = np.stack([regions(r, name) for r in references])  # seeds x 4 x 4
            theirs = runs.mean(axis=0)
            # The reference's own error: the spread of the independent seeds (standard error of their mean).
            error = runs.std(axis=0, ddof=1) / np.sqrt(args.seeds)
            total = theirs.sum()
            if not total > 0.0:
                cells.append(f"{'-':>13} {'-':>8} {'-':>4}")
                continue
            totalError = runs.sum(axis=(1, 2)).std(ddof=1) / np.sqrt(args.seeds) / total
            lit = theirs > total / 16.0 / 20.0
            judged = lit & (error < args.resolve * theirs)
            worst = float(np.max(np.abs(ours[judged] / theirs[judged] - 1.0), initial=0.0))
            mean = f"{ours.sum() / total:.3f}±{totalError:.3f}"
            cells.append(f"{mean:>13} {worst:8.1%} {int((lit & ~judged).sum()):4d}")
        print(f"{scene:24} {cpu:6.1f}  " + "  ".join(cells), flush=True)


if __name__ == "__main__":
    sys.exit(main())
