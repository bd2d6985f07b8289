#!/usr/bin/python3
"""Prints the nesting table of the README: for each scene, the mean radiance of one AOV under the
path tracer divided by the same AOV under ray casting or Whitted (1.000 = the same light).

    scripts/nesting_table.py [--lightpath build/lightpath] [scene ...]

Settings as in the issue that introduced the shared light transport: 96x72 pixels, raycast and
whitted at 64 spp, path at 1024 spp, Sobol sampling. Reads the EXRs with OpenImageIO's Python
bindings (Debian's python3-openimageio, installed by scripts/setup)."""
import argparse
import pathlib
import subprocess
import tempfile

import OpenImageIO as oiio

REPO = pathlib.Path(__file__).resolve().parent.parent
LIGHTS = "<L[^'ambient']>"
COLUMNS = [  # (classic integrator, expression)
    ("raycast", f"E(D|G){LIGHTS}"),
    ("whitted", f"ES+(D|G){LIGHTS}"),
    ("whitted", "ES+L"),
]


def mean_of(lightpath, scene, integrator, spp, expression, folder):
    out = pathlib.Path(folder) / f"{integrator}.exr"
    subprocess.run([lightpath, "render", str(scene), "--integrator", integrator, "--resolution", "96x72",
                    "--spp", str(spp), "--sampler", "sobol", "--lpe", f"a={expression}", "--no-beauty",
                    "--quiet", "-o", str(out)], check=True, capture_output=True)
    image = oiio.ImageBuf(str(out))
    names = list(image.spec().channelnames)
    pixels = image.get_pixels(oiio.FLOAT)
    return float(pixels[:, :, [names.index(f"a.{c}") for c in "RGB"]].mean())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lightpath", default=str(REPO / "build/lightpath"))
    ap.add_argument("scenes", nargs="*", default=["lecture-room", "taxonomy", "szymczak-one-light", "glass-sphere"])
    args = ap.parse_args()
    print("| scene | path / raycast on `E(D\\|G)<L[^'ambient']>` | path / whitted on `ES+(D\\|G)<L[^'ambient']>`"
          " | path / whitted on `ES+L` |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as folder:
        for name in args.scenes:
            scene = REPO / "scenes" / f"{name}.toml"
            cells = []
            for classic, expression in COLUMNS:
                reference = mean_of(args.lightpath, scene, classic, 64, expression, folder)
                path = mean_of(args.lightpath, scene, "path", 1024, expression, folder)
                cells.append(f"{path / reference:.3f}" if reference > 0 else "no such light")
            print(f"| {name} | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()
