#!/usr/bin/env python3
"""Plots `lightpath bench error`'s CSV: RMSE against CPU seconds, log-log, one panel per scene.

Radiosity's rows (sampler "radiosity") share their scene's panel, each point labelled with its patch count."""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path: str, png_path: str) -> None:
    curves = defaultdict(lambda: defaultdict(list))
    with open(csv_path, newline="") as f:
        for row in csv.DictReader(f):
            # Sampler curves are the path tracer's (radiosity's rows name it as their sampler); the
            # integrator comparison names its method.
            integrator = row["integrator"]
            label = row["sampler"] if integrator in ("path", "radiosity") else f'{integrator} {row["sampler"]}'
            curves[row["scene"]][label].append(
                (float(row["seconds"]), float(row["rmse"]), int(row.get("patches") or 0)))
    scenes = sorted(curves)
    fig, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for sampler, points in sorted(curves[scene].items()):
            seconds, rmse, patches = zip(*sorted(points))
            ax.loglog(seconds, rmse, marker="s" if sampler == "radiosity" else "o", label=sampler)
            if sampler == "radiosity":
                for x, y, n in zip(seconds, rmse, patches):
                    ax.annotate(f"{n}", (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7)
        first = sorted(curves[scene]["independent"])[0]
        first = first[:2]
        xs = [first[0], first[0] * 100]
        ax.loglog(xs, [first[1], first[1] * 0.1], "k:", label="slope -1/2")
        ax.set_title(scene)
        ax.set_xlabel("CPU seconds (1 thread)")
        ax.set_ylabel("RMSE")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
