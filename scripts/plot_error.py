#!/usr/bin/env python3
"""Plots `lightpath bench error`'s CSV: RMSE against CPU seconds, log-log, one panel per scene."""
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
            # Sampler curves are the path tracer's; the integrator comparison names its method.
            label = row["sampler"] if row["integrator"] == "path" else f'{row["integrator"]} {row["sampler"]}'
            curves[row["scene"]][label].append((float(row["seconds"]), float(row["rmse"])))
    scenes = sorted(curves)
    fig, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for sampler, points in sorted(curves[scene].items()):
            seconds, rmse = zip(*sorted(points))
            ax.loglog(seconds, rmse, marker="o", label=sampler)
        first = sorted(curves[scene]["independent"])[0]
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
