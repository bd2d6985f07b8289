"""The figures' plots and diagrams, drawn with Debian's matplotlib at the size they take on the
slide (so their text keeps the slide's text size: 28 pt at 100 dpi is 39 px)."""

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the non-interactive backend)

DPI = 100
SLIDE_STYLE = {"font.family": "DejaVu Sans", "font.size": 28, "axes.linewidth": 2,
               "lines.linewidth": 4, "figure.facecolor": "white"}


def exponent_plot(png, exponents, width_px, height_px):
    """(H.N)^n = cos^n(angle) against the angle between H and N, one curve per n."""
    with plt.rc_context(SLIDE_STYLE):
        fig, ax = plt.subplots(figsize=(width_px / DPI, height_px / DPI), dpi=DPI)
        angles = [i * 0.1 for i in range(0, 901)]
        for n in exponents:
            ax.plot(angles, [math.cos(math.radians(a)) ** n for a in angles], label=f"n = {n}")
        ax.set_xlabel("angle between H and N (degrees)")
        ax.set_ylabel("(H.N)^n")
        ax.set_xlim(0, 90)
        ax.set_ylim(0, 1.02)
        ax.grid(alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(png)
        plt.close(fig)


def ray_sphere_diagram(png, cases, width_px, height_px):
    """One small diagram per case: the ray from the origin along +x, the circle, the first hit
    the renderer reported (red) and the quadratic's other root (grey ring).

    cases: [(name, centre, radius, hit, t)] with t the renderer's first-hit distance or None."""
    with plt.rc_context(SLIDE_STYLE):
        cols = math.ceil(len(cases) / 2)  # two rows: each diagram as large as the slide allows
        fig, axes = plt.subplots(2, cols, figsize=(width_px / DPI, height_px / DPI), dpi=DPI)
        for ax in axes.flat[len(cases):]:
            ax.axis("off")
        for ax, (name, c, r, hit, t) in zip(axes.flat, cases):
            ax.set_aspect("equal")
            ax.set_xlim(-3.7, 5.2)
            ax.set_ylim(-2.4, 2.6)
            ax.axis("off")
            ax.add_patch(plt.Circle((c[0], c[1]), r, fill=False, lw=4, color="tab:blue"))
            ax.annotate("", xy=(5.0, 0), xytext=(0, 0),
                        arrowprops=dict(arrowstyle="->", lw=3, color="k"))
            ax.plot([0], [0], "ko", ms=10)
            # the roots along the ray (direction +x): t = c.x -+ sqrt(r^2 - c.y^2)
            h2 = r * r - c[1] * c[1]
            roots = [] if h2 < 0 else sorted({c[0] - math.sqrt(h2), c[0] + math.sqrt(h2)})
            for x in roots:
                if x > 0 and (t is None or abs(x - t) > 1e-3):
                    ax.plot([x], [0], "o", ms=16, mfc="none", mec="gray", mew=3)
            if t is not None:
                ax.plot([t], [0], "o", ms=18, color="tab:red")
            verdict = f"t = {t:.3f}" if (hit and t is not None) else ("hit" if hit else "miss")
            ax.set_title(f"{name}\n{verdict}", fontsize=30)
        fig.tight_layout()
        if len(cases) < axes.size:  # the key in the free cell
            axes.flat[-1].text(0.5, 0.5, "red: the first hit\nlightpath reports\n\ngrey ring:\nthe other root",
                               ha="center", va="center", fontsize=28,
                               transform=axes.flat[-1].transAxes)
        fig.savefig(png)
        plt.close(fig)


def bench_error_plot(csv_path, png, width_px, height_px):
    """`lightpath bench error`'s CSV as the slide shows it: RMSE against CPU seconds, log-log,
    one panel per scene, one line per integrator and sampler (radiosity: per patch budget)."""
    import csv
    series = {}
    with open(csv_path, newline="") as f:
        for row in csv.DictReader(f):
            name = (f"{row['integrator']} {row['sampler']}"
                    if row["integrator"] in ("path", "bdpt") else row["integrator"])
            key = (row["scene"], name)
            series.setdefault(key, []).append((float(row["seconds"]), float(row["rmse"])))
    scenes = sorted({s for s, _ in series})
    if not scenes:
        raise ValueError(f"{csv_path}: no rows")
    cols = min(len(scenes), 2)
    rows = math.ceil(len(scenes) / cols)
    style = dict(SLIDE_STYLE, **{"font.size": 20, "lines.linewidth": 3})
    with plt.rc_context(style):
        fig, axes = plt.subplots(rows, cols, figsize=(width_px / DPI, height_px / DPI), dpi=DPI,
                                 squeeze=False)
        for ax, scene in zip(axes.flat, scenes):
            for (s, name), points in sorted(series.items()):
                if s == scene:
                    points.sort()
                    ax.loglog([p[0] for p in points], [p[1] for p in points], "o-", ms=5,
                              label=name)
            ax.set_title(scene)
            ax.grid(alpha=0.3, which="both")
            ax.legend(fontsize=16, ncol=2)
        for ax in axes[-1]:
            ax.set_xlabel("CPU seconds (one thread)")
        for ax in axes[:, 0]:
            ax.set_ylabel("RMSE")
        for ax in list(axes.flat)[len(scenes):]:
            ax.axis("off")
        fig.tight_layout()
        fig.savefig(png)
        plt.close(fig)
