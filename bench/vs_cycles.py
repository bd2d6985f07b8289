#!/usr/bin/python3
"""lightpath's path tracer against Blender's Cycles (CPU) on the Cornell box under its lamp.

Two scenes (--scene): `cornell`, every material Lambertian (bench/cycles/cornell-lamp.toml), and
`glossy`, the same box with a rough metal floor (bench/cycles/cornell-glossy.toml: GGX, roughness
0.3, in Cycles a Principled BSDF with metallic 1).

For each of Cycles' budgets (16, 64, 256 spp) the script measures Cycles' RMSE against Cycles' own
converged image, then the render time lightpath needs to reach that same RMSE against its own
converged image (the two converged images agree; the script prints by how much), interpolated
log-log between lightpath's budgets. The ratio lightpath time / Cycles time is reported for all
pixels and with the lamp's pixels (and a one-pixel ring around them) left out.

Times are each renderer's own render time: Cycles' bpy.ops.render.render() after a warm-up render
in the same process, lightpath's `--stats` rendering time; start-up and image writing excluded.
Both the CPU time (Blender's whole process during the render; lightpath's worker threads) and
the wall time are reported; on a machine other processes load, CPU time is the steadier clock.
Runs alternate between the renderers; times are medians over runs, squared errors are averaged
over runs (each run has its own seed). The machine is named in the output.

  /usr/bin/python3 bench/vs_cycles.py [--scene cornell|glossy] [--runs 3] [--size 128] [--threads 2]
      [--variant SAMPLER:FILTER ...] [--reference-spp 2048] [--cache out/bench-cycles]

Needs Blender (a benchmark peer, not a dependency of lightpath: `sudo apt-get install blender`)
and the python3-openimageio and python3-numpy packages of scripts/setup. Without Blender it says so
and exits 0. Environment: LIGHTPATH (default build/lightpath), BLENDER (default blender).
"""
import argparse
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
# Per scene: lightpath's scene file and the materials Blender makes rough metals (cornell_box.py's
# metal=NAME:ROUGHNESS), matching the file's [materials] tables.
SCENES = {
    "cornell": (os.path.join(HERE, "cycles", "cornell-lamp.toml"), []),
    "glossy": (os.path.join(HERE, "cycles", "cornell-glossy.toml"), ["metal=floor:0.3"]),
}
OBJ = os.path.join(ROOT, "scenes", "meshes", "cornell-box", "CornellBox-Original.obj")
CYCLES_SPP = [16, 64, 256]
# The lamp's radiance is (17, 12, 4); no wall comes near this luminance, so a pixel above it sees
# some of the lamp.
LAMP_LUMINANCE = 1.5


def read_rgb(path):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        sys.exit(f"vs_cycles: cannot read {path}: {buf.geterror()}")
    return buf.get_pixels(oiio.FLOAT)[:, :, :3].astype(np.float64)


def luminance(img):
    return img @ np.array([0.2126, 0.7152, 0.0722])


def machine():
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            model = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    return f"{platform.node()}, {os.cpu_count()} cores, {model}, load average {os.getloadavg()[0]:.1f}"


def run_cycles(blender, scene, out, size, threads, seed, spps):
    cmd = [blender, "-b", "--factory-startup", "-P", os.path.join(HERE, "cycles", "cornell_box.py"), "--",
           OBJ, out, str(size), str(threads), str(seed)] + SCENES[scene][1] + [str(s) for s in spps]
    log = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    results = {}
    for m in re.finditer(r"^cycles spp (\d+) seconds ([0-9.]+) cpu ([0-9.]+) file (\S+)$", log, re.M):
        results[int(m.group(1))] = (float(m.group(2)), float(m.group(3)), m.group(4))
    if len(results) != len(spps):
        sys.exit("vs_cycles: Blender did not render every budget:\n" + log)
    return results


def run_lightpath(lightpath, scene, out, size, threads, seed, spp, sampler, pixel_filter):
    path = os.path.join(out, f"lightpath-{sampler}-{pixel_filter}-{spp}-seed{seed}.exr")
    cmd = [lightpath, "render", SCENES[scene][0], "--integrator", "path", "--spp", str(spp), "--threads", str(threads),
           "--seed", str(seed), "--sampler", sampler, "--resolution", f"{size}x{size}", "--aovs", "none",
           "-o", path, "--quiet", "--stats"]
    if pixel_filter != "default":
        cmd += ["--filter", pixel_filter]
    log = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    m = re.search(r"^time\s+([0-9.]+) s on \d+ threads? \(([0-9.]+) s CPU\)", log, re.M)
    if not m:
        sys.exit("vs_cycles: no rendering time in lightpath's --stats:\n" + log)
    return float(m.group(1)), float(m.group(2)), path


def seconds_to_reach(curve, error):
    """curve: [(seconds, rmse)] by increasing budget; log-log interpolation, extrapolated along the
    last two points' slope outside."""
    for (t0, e0), (t1, e1) in zip(curve, curve[1:]):
        if (e0 - error) * (e1 - error) <= 0 and e0 != e1:
            f = (np.log(error) - np.log(e0)) / (np.log(e1) - np.log(e0))
            return float(np.exp(np.log(t0) + f * (np.log(t1) - np.log(t0))))
    (t0, e0), (t1, e1) = (curve[0], curve[1]) if error > curve[0][1] else (curve[-2], curve[-1])
    slope = (np.log(e1) - np.log(e0)) / (np.log(t1) - np.log(t0))
    return float(np.exp(np.log(t1) + (np.log(error) - np.log(e1)) / slope))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scene", choices=sorted(SCENES), default="cornell")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--size", type=int, default=128)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--variant", action="append",
                    help="lightpath's SAMPLER:FILTER, repeatable (FILTER 'default': no --filter option)")
    ap.add_argument("--lightpath-spp", default="8,16,32,64,128,256,512")
    ap.add_argument("--reference-spp", type=int, default=2048, help="of each of the two renders per reference")
    ap.add_argument("--cache", default=os.path.join(ROOT, "out", "bench-cycles"))
    args = ap.parse_args()
    variants = [tuple(v.split(":")) for v in (args.variant or ["sobol:default"])]
    lp_spps = [int(s) for s in args.lightpath_spp.split(",")]

    blender = os.environ.get("BLENDER", "blender")
    if shutil.which(blender) is None:
        print("vs_cycles: Blender is not installed, skipped (Debian: sudo apt-get install blender)", file=sys.stderr)
        return 0
    lightpath = os.environ.get("LIGHTPATH", os.path.join(ROOT, "build", "lightpath"))
    if not os.access(lightpath, os.X_OK):
        print(f"vs_cycles: no lightpath binary at {lightpath} (build it first)", file=sys.stderr)
        return 2
    os.makedirs(args.cache, exist_ok=True)
    # The Lambertian box keeps the folder names it had before there were two scenes.
    prefix = "" if args.scene == "cornell" else f"{args.scene}-"
    work = os.path.join(args.cache, f"{prefix}runs")
    os.makedirs(work, exist_ok=True)

    # Converged references, cached: Cycles', and lightpath's per pixel filter (the filter changes
    # the converged image; the sampler does not). Each is the mean of two renders with different
    # seeds; half their squared difference, halved again, estimates the reference's own squared
    # error, which is subtracted from every measured one (the reference is independent of them).
    refs_dir = os.path.join(args.cache, f"{prefix}references-{args.size}-{args.reference_spp}")
    os.makedirs(refs_dir, exist_ok=True)

    def reference(render, name):
        halves = []
        for seed in (98, 99):
            path = os.path.join(refs_dir, f"{name}-{args.reference_spp}-seed{seed}.exr")
            if not os.path.exists(path):
                print(f"rendering the reference {name} ({args.reference_spp} spp, seed {seed}) ...", file=sys.stderr, flush=True)
                render(seed)
            halves.append(read_rgb(path))
        difference = (halves[0] - halves[1]) ** 2
        return (halves[0] + halves[1]) / 2, difference / 4

    cycles_ref, cycles_ref_sq = reference(
        lambda seed: run_cycles(blender, args.scene, refs_dir, args.size, args.threads, seed, [args.reference_spp]), "cycles")
    lp_refs, lp_refs_sq = {}, {}
    for _, pixel_filter in variants:
        if pixel_filter not in lp_refs:
            lp_refs[pixel_filter], lp_refs_sq[pixel_filter] = reference(
                lambda seed: run_lightpath(lightpath, args.scene, refs_dir, args.size, args.threads, seed, args.reference_spp,
                                           "sobol", pixel_filter), f"lightpath-sobol-{pixel_filter}")

    lamp = (luminance(cycles_ref) > LAMP_LUMINANCE)
    for ref in lp_refs.values():
        lamp |= luminance(ref) > LAMP_LUMINANCE
    ring = lamp.copy()  # one pixel around the lamp: its edge pixels
    ring[1:, :] |= lamp[:-1, :]
    ring[:-1, :] |= lamp[1:, :]
    ring[:, 1:] |= lamp[:, :-1]
    ring[:, :-1] |= lamp[:, 1:]
    keep = ~ring

    # Per budget, every run's (wall seconds, CPU seconds) and (squared error, without the lamp).
    cycles_times = {s: [] for s in CYCLES_SPP}
    cycles_sq = {s: [] for s in CYCLES_SPP}
    lp_times = {(v, s): [] for v in variants for s in lp_spps}
    lp_sq = {(v, s): [] for v in variants for s in lp_spps}

    def squared(img, ref, ref_sq):
        d = (img - ref) ** 2 - ref_sq
        return d.mean(), d[keep].mean()

    for run in range(args.runs):
        seed = 1000 + run
        for spp, (seconds, cpu, path) in run_cycles(blender, args.scene, work, args.size, args.threads, seed, CYCLES_SPP).items():
            cycles_times[spp].append((seconds, cpu))
            cycles_sq[spp].append(squared(read_rgb(path), cycles_ref, cycles_ref_sq))
        for v in variants:
            for spp in lp_spps:
                seconds, cpu, path = run_lightpath(lightpath, args.scene, work, args.size, args.threads, seed, spp, *v)
                lp_times[(v, spp)].append((seconds, cpu))
                lp_sq[(v, spp)].append(squared(read_rgb(path), lp_refs[v[1]], lp_refs_sq[v[1]]))
        print(f"run {run + 1}/{args.runs} done", file=sys.stderr, flush=True)

    print(f"machine: {machine()}")
    print(f"scene: {os.path.relpath(SCENES[args.scene][0], ROOT)} at {args.size}x{args.size}, {args.threads} threads, "
          f"{args.runs} runs; references 2 x {args.reference_spp} spp, their own error subtracted; "
          f"lamp and its ring: {int(ring.sum())} of {ring.size} pixels")
    for pixel_filter, ref in lp_refs.items():
        region = lambda img: img[keep].mean(axis=0)
        print(f"converged means without the lamp, lightpath ({pixel_filter}) / Cycles: "
              + " ".join(f"{a / b:.4f}" for a, b in zip(region(ref), region(cycles_ref))))

    def rmse(samples, which):
        return float(np.sqrt(max(0.0, np.mean([s[which] for s in samples]))))

    def median(times, clock):
        return statistics.median(t[clock] for t in times)

    print(f"\n{'renderer':<30}{'spp':>6}{'wall s':>9}{'CPU s':>9}{'rmse':>10}{'rmse no lamp':>14}")
    for spp in CYCLES_SPP:
        print(f"{'cycles':<30}{spp:>6}{median(cycles_times[spp], 0):>9.3f}{median(cycles_times[spp], 1):>9.3f}"
              f"{rmse(cycles_sq[spp], 0):>10.5f}{rmse(cycles_sq[spp], 1):>14.5f}")
    for v in variants:
        for spp in lp_spps:
            t = lp_times[(v, spp)]
            print(f"{'lightpath ' + ':'.join(v):<30}{spp:>6}{median(t, 0):>9.3f}{median(t, 1):>9.3f}"
                  f"{rmse(lp_sq[(v, spp)], 0):>10.5f}{rmse(lp_sq[(v, spp)], 1):>14.5f}")

    for clock, name in ((1, "CPU"), (0, "wall")):
        print(f"\nlightpath's {name} time to Cycles' RMSE / Cycles' {name} time (at most 1: lightpath is faster)")
        print(f"{'variant':<30}" + "".join(f"{f'{s} spp':>12}" for s in CYCLES_SPP)
              + "".join(f"{f'{s} no lamp':>12}" for s in CYCLES_SPP))
        for v in variants:
            ratios = []
            for which in (0, 1):
                curve = [(median(lp_times[(v, s)], clock), rmse(lp_sq[(v, s)], which)) for s in lp_spps]
                for spp in CYCLES_SPP:
                    target = rmse(cycles_sq[spp], which)
                    ratios.append(seconds_to_reach(curve, target) / median(cycles_times[spp], clock))
            print(f"{':'.join(v):<30}" + "".join(f"{r:>12.2f}" for r in ratios))
    return 0


if __name__ == "__main__":
    sys.exit(main())
