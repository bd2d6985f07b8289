#!/usr/bin/env python3
"""Plots `lightpath bench error`'s CSV: RMSE against CPU seconds, log-log, one panel per scene.

Radiosity's rows (sampler "radiosity") share their scene's panel, each point labelled with its patch count.
Every budget is drawn, `--quick`'s included: a series of one point is a marker, a scene without the
independent sampler takes its slope guide from its first series, and points that a log axis cannot
show (zero error or time) are left out.

Exit codes: 0 plotted; 3 python3-matplotlib is missing (the caller says so); 1 anything else,
with this script's own message: a failure here is this script's, not matplotlib's."""
import csv
import sys
import traceback
from collections import defaultdict

EXIT_NO_MATPLOTLIB = 3
NAME = "plot_error.py"


def read_curves(csv_path: str):
    """{scene: {label: [(seconds, rmse, patches)]}}, only points a log-log axis can show."""
    curves = defaultdict(lambda: defaultdict(list))
    with open(csv_path, newline="") as f:
        for row in csv.DictReader(f):
            # Sampler curves are the path tracer's (radiosity's rows name it as their sampler); the
            # integrator comparison names its method.
            integrator = row["integrator"]
            label = row["sampler"] if integrator in ("path", "radiosity") else f'{integrator} {row["sampler"]}'
            seconds, rmse = float(row["seconds"]), float(row["rmse"])
            if seconds > 0 and rmse > 0:
                curves[row["scene"]][label].append((seconds, rmse, int(row.get("patches") or 0)))
    return curves


def plot(curves, png_path: str, plt) -> None:
    scenes = sorted(scene for scene, series in curves.items() if any(series.values()))
    if not scenes:
        raise ValueError("no row with a positive time and error to plot")
    fig, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        series = {label: sorted(points) for label, points in curves[scene].items() if points}
        for label, points in sorted(series.items()):
            seconds, rmse, patches = zip(*points)
            ax.loglog(seconds, rmse, marker="s" if label == "radiosity" else "o", label=label)
            if label == "radiosity":
                for x, y, n in zip(seconds, rmse, patches):
                    ax.annotate(f"{n}", (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7)
        # The Monte Carlo slope, from the cheapest point of independent sampling (else of the first series).
        guide = series.get("independent") or series[sorted(series)[0]]
        x0, y0 = guide[0][:2]
        ax.loglog([x0, x0 * 100], [y0, y0 * 0.1], "k:", label="slope -1/2")
        ax.set_title(scene)
        ax.set_xlabel("CPU seconds (1 thread)")
        ax.set_ylabel("RMSE")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


def main(csv_path: str, png_path: str) -> int:
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        print(f"{NAME}: python3-matplotlib is missing ({e})", file=sys.stderr)
        return EXIT_NO_MATPLOTLIB
    try:
        plot(read_curves(csv_path), png_path, plt)
    except Exception as e:  # noqa: BLE001 - every failure gets this script's name and the CSV's
        traceback.print_exc()
        print(f"{NAME}: cannot plot {csv_path} into {png_path}: {type(e).__name__}: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(f"usage: {NAME} BENCH-ERROR.csv PLOT.png", file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
