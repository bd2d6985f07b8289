#!/usr/bin/env python3
"""layers/hot-path-layout: the render's per-sample functions lie together in the binary.

src/util/hot_path.h's LIGHTPATH_HOT_PATH puts them in one section, which the linker lays out
contiguously; scattered, they overfilled a few sets of the 32 KiB L1 instruction cache (2.4 M
misses in a 256x256 Whitted render against 55 k together: docs/performance.md, Shading share,
third pass). This reads the marked functions from the sources and the binary's symbols (nm), and
fails when a function the render runs per sample is missing from the block of marked functions,
or when anything unmarked lies inside that block.

    hot_path_layout.py SOURCE_DIR BINARY
"""
import pathlib
import re
import subprocess
import sys

# Run per sample by raycast, Whitted and the path tracer on the Cornell box (callgrind): each must
# be marked and so inside the block. External functions only: a file-local one may be inlined
# whole by another compiler (clang's sanitizer build) and leave no symbol.
REQUIRED = [
    "Renderer::renderPixel", "Sampler::next1D", "Sampler::next2D",
    "Camera::generateRay", "SceneGeometry::intersectSurface", "SceneGeometry::occluded",
    "makeShadingPoint", "addLocalIllumination", "addDirectLight", "AreaLightSource::sample",
    "PointLightSource::sample", "PhongMaterial::eval", "WhittedIntegrator::trace",
    "PathIntegrator::traceCameraRay", "spawnShadowRay", "WatertightRay::WatertightRay",
]


def marked_functions(source_dir):
    names = set()
    for path in pathlib.Path(source_dir, "src").rglob("*.cpp"):
        lines = path.read_text(encoding="utf-8").splitlines()
        for i, line in enumerate(lines[:-1]):
            if line.strip() == "LIGHTPATH_HOT_PATH":
                match = re.search(r"([A-Za-z_][\w:]*)\(", lines[i + 1])
                if match:
                    names.add(match.group(1))
    return names


def plain_name(demangled):
    if "{lambda" in demangled:  # a lambda inside a marked function has a section of its own
        return demangled
    name = demangled.replace("(anonymous namespace)::", "")
    name = name.split("(")[0]
    return name.removeprefix("lightpath::")


def main():
    source_dir, binary = sys.argv[1], sys.argv[2]
    marked = marked_functions(source_dir)
    missing = [name for name in REQUIRED if name not in marked]
    if missing:
        print("not marked LIGHTPATH_HOT_PATH in src/:", ", ".join(missing))
        return 1
    listing = subprocess.run(["nm", "-C", "-n", "--defined-only", binary], check=True, capture_output=True,
                             text=True).stdout
    symbols = []  # (address, plain name) of code, in address order
    for line in listing.splitlines():
        parts = line.split(" ", 2)
        if len(parts) == 3 and parts[1] in ("t", "T"):
            symbols.append((int(parts[0], 16), plain_name(parts[2])))
    hot = [i for i, (_, name) in enumerate(symbols) if name in marked]
    found = {symbols[i][1] for i in hot}
    absent = [name for name in REQUIRED if name not in found]
    if absent:
        print("no symbol in", binary, "for:", ", ".join(absent))
        return 1
    first, last = min(hot), max(hot)
    intruders = [f"{name[:100]} at {address:#x}" for address, name in symbols[first:last + 1] if name not in marked]
    span = symbols[last][0] - symbols[first][0]
    print(f"{len(hot)} marked symbols in {span} bytes from {symbols[first][0]:#x}")
    if intruders:
        print("unmarked code inside the hot block (it is not one block):")
        print("\n".join("  " + text for text in intruders[:20]))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
