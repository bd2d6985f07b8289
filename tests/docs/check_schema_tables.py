#!/usr/bin/env python3
"""scenes/README.md's parameter tables are what `lightpath types FAMILY NAME --markdown` prints:
each type's table must appear in the README verbatim, so docs and schema cannot disagree."""
import argparse
import pathlib
import subprocess
import sys

# The types whose tables scenes/README.md shows.
TABLES = [("material", "phong"), ("material", "modified-phong"), ("material", "microfacet"), ("material", "conductor"), ("material", "dielectric"),
          ("medium", "homogeneous"),
          ("light", "point"), ("light", "quad"), ("light", "sphere"), ("light", "spot"), ("light", "directional"),
          ("shape", "sphere"), ("shape", "plane"), ("shape", "disk"),
          ("shape", "triangle"), ("shape", "mesh"), ("shape", "gltf")]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--lightpath", required=True)
    parser.add_argument("--readme", required=True)
    args = parser.parse_args()
    readme = pathlib.Path(args.readme).read_text(encoding="utf-8")
    failures = 0
    for family, name in TABLES:
        table = subprocess.run([args.lightpath, "types", family, name, "--markdown"], check=True,
                               capture_output=True, text=True, encoding="utf-8").stdout
        if table not in readme:
            failures += 1
            print(f"{args.readme}: the table of {family} \"{name}\" differs from "
                  f"`lightpath types {family} {name} --markdown`, which prints:\n{table}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
