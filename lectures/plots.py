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


RAY_SPHERE_XLIM = (-3.7, 5.2)  # the drawn area of each case (world units); the recipe checks
RAY_SPHERE_YLIM = (-2.7, 2.9)  # every circle lies inside it


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
            ax.set_xlim(*RAY_SPHERE_XLIM)
            ax.set_ylim(*RAY_SPHERE_YLIM)
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
            verdict = f"hit, t = {t:.3f}" if (hit and t is not None) else ("hit" if hit else "miss")
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


LPE_PT = 27  # 37.5 px at 100 dpi: the 36 px for LPE captions at 1080p
# One colour per path, in the order `explain` lists them (largest contribution first).
PATH_COLOURS = ["#e6194b", "#3cb44b", "#4363d8", "#f58231", "#911eb4", "#42d4f4", "#f032e6",
                "#bfef45", "#fabed4", "#469990"]


def _segments_2d(vertices, drop=None):
    """Consecutive pairs of a path's vertices in (x, z), skipping vertices with no position."""
    pts = [(v[0], v[2]) for v in vertices if v is not None]
    return list(zip(pts, pts[1:]))


def _scene_top_view(ax, scene, bunny_points):
    """The scene seen from above (x right, z down the page, as serve's top view): walls and
    triangles as lines, balls as circles, meshes as their vertices, lights and the eye."""
    for t in scene.get("triangles", []):
        v = t["vertices"] + [t["vertices"][0]]
        ax.plot([p[0] for p in v], [p[2] for p in v], color="#888", lw=3, zorder=1)
    for s in scene.get("spheres", []):
        ax.add_patch(plt.Circle((s["center"][0], s["center"][2]), s["radius"], fill=False,
                                color="#aaa", lw=3, zorder=1))
        ax.text(s["center"][0], s["center"][2], s["name"], ha="center", va="center",
                fontsize=16, color="#555")
    for pts in bunny_points:
        ax.plot(pts[:, 0], pts[:, 2], ",", color="#bbb", zorder=0)
    for light in scene.get("lights", []):
        ax.plot(light["position"][0], light["position"][2], "*", ms=28, color="#f5c518",
                mec="k", zorder=4)
        ax.text(light["position"][0] + 0.15, light["position"][2], light["name"], fontsize=18,
                va="center")
    eye = scene["camera"]["eye"]
    ax.plot(eye[0], eye[2], "s", ms=16, color="k", zorder=4)
    ax.text(eye[0] + 0.15, eye[2], "eye", fontsize=18, va="center")


def pixel_paths_plot(png, image, pixel, paths, scene, bunny_points, width_px, height_px):
    """Left: the rendered image with every path's segments drawn over it (projected with the
    scene's camera by `explain --json`); right: the same paths seen from above. Each path in its
    colour, labelled with its LPE in the legend below.

    paths: [(lpe, vertices [[x, y, z] | None], segments [[x0, y0, x1, y1] | None])]."""
    h, w = image.shape[:2]
    with plt.rc_context(SLIDE_STYLE):
        fig = plt.figure(figsize=(width_px / DPI, height_px / DPI), dpi=DPI)
        legend_h = (LPE_PT * 1.45 / 72 * DPI) * len(paths) / height_px + 0.02
        image_ax = fig.add_axes((0.01, legend_h + 0.02, 0.56, 0.97 - legend_h))
        top_ax = fig.add_axes((0.60, legend_h + 0.06, 0.39, 0.86 - legend_h))
        image_ax.imshow(image, extent=(0, w, h, 0), interpolation="nearest")
        image_ax.set_xlim(0, w)
        image_ax.set_ylim(h, 0)
        image_ax.axis("off")
        _scene_top_view(top_ax, scene, bunny_points)
        handles = []
        for i, (lpe, vertices, segments) in enumerate(paths):
            colour = PATH_COLOURS[i % len(PATH_COLOURS)]
            offset = (i - (len(paths) - 1) / 2) * 0.6  # a fan of parallel lines, each visible
            for s in segments:
                if s is not None:
                    image_ax.plot([s[0] + offset, s[2] + offset], [s[1], s[3]], color=colour,
                                  lw=4, solid_capstyle="round")
                    image_ax.plot([s[2] + offset], [s[3]], "o", ms=9, color=colour)
            for a, b in _segments_2d(vertices):
                top_ax.plot([a[0], b[0]], [a[1], b[1]], color=colour, lw=3, zorder=3)
                top_ax.plot([b[0]], [b[1]], "o", ms=8, color=colour, zorder=3)
            handles.append(plt.Line2D([], [], color=colour, lw=6, label=lpe))
        image_ax.add_patch(plt.Circle((pixel[0] + 0.5, pixel[1] + 0.5), w / 40, fill=False,
                                      ec="white", lw=3))
        top_ax.set_aspect("equal")
        top_ax.invert_yaxis()  # z grows down the page, toward the eye
        top_ax.set_xlabel("x")
        top_ax.set_ylabel("z")
        top_ax.set_title("from above", fontsize=26)
        fig.legend(handles=handles, loc="lower center", ncol=1, fontsize=LPE_PT, frameon=False,
                   bbox_to_anchor=(0.5, 0.0), handlelength=1.5, borderpad=0.1, labelspacing=0.25)
        fig.savefig(png, facecolor="white")
        plt.close(fig)


def automaton_with_states(png, automaton_png, rows, width_px, height_px):
    """The automaton drawn by Graphviz above the paths of one pixel, each with the states it
    passes through and the AOV it ends in: rows [(lpe, states, aovs)], LPEs at caption size."""
    import matplotlib.image as mpimg
    line = LPE_PT * 1.45 / 72 * DPI / height_px  # one text line, as a fraction of the figure
    list_h = line * len(rows) + 0.02
    with plt.rc_context(SLIDE_STYLE):
        fig = plt.figure(figsize=(width_px / DPI, height_px / DPI), dpi=DPI)
        ax = fig.add_axes((0.0, list_h + 0.01, 1.0, 0.99 - list_h))
        ax.imshow(mpimg.imread(automaton_png), interpolation="antialiased")
        ax.axis("off")
        for i, (lpe, states, aovs) in enumerate(rows):
            y = list_h - 0.01 - i * line
            colour = PATH_COLOURS[i % len(PATH_COLOURS)]
            fig.text(0.01, y, lpe, fontsize=LPE_PT, color=colour, va="top")
            fig.text(0.66, y, " \u2192 ".join(str(s) for s in states) + f"  {aovs}",
                     fontsize=LPE_PT, va="top")
        fig.savefig(png, facecolor="white")
        plt.close(fig)
