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


def _legend_clear_of_data(fig, ax, legend):
    """True when no data point, nor any point along the lines between them, lies inside the
    legend's box (display pixels)."""
    import numpy as np
    fig.canvas.draw()
    box = legend.get_window_extent(fig.canvas.get_renderer())
    for line in ax.get_lines():
        x, y = (np.asarray(v, float) for v in line.get_data())
        if len(x) == 0:
            continue
        # along each segment, evenly in log space (the axes are log-log)
        t = np.linspace(0.0, 1.0, 20)[:, None]
        lx, ly = np.log(x), np.log(y)
        sx = np.exp(lx[:-1] + t * (lx[1:] - lx[:-1])).ravel() if len(x) > 1 else x
        sy = np.exp(ly[:-1] + t * (ly[1:] - ly[:-1])).ravel() if len(y) > 1 else y
        pts = ax.transData.transform(np.column_stack([np.concatenate([x, sx]),
                                                      np.concatenate([y, sy])]))
        if np.any((pts[:, 0] > box.x0) & (pts[:, 0] < box.x1) &
                  (pts[:, 1] > box.y0) & (pts[:, 1] < box.y1)):
            return False
    return True


def bench_error_plot(csv_path, png, width_px, height_px, extra=(), drop=()):
    """`lightpath bench error`'s CSV as the slide shows it: RMSE against CPU seconds, log-log,
    one panel per scene, one line per integrator and sampler (radiosity: per patch budget).

    extra: more rows (dicts with the CSV's keys) measured by the generator; drop: scenes of the
    CSV left out (replaced by extra). Each legend stands beside its axes; returns False when a
    legend covers data all the same (_legend_clear_of_data)."""
    import csv
    series = {}
    with open(csv_path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["scene"] not in drop] + list(extra)
    for row in rows:
        name = (f"{row['integrator']} {row['sampler']}"
                if row["integrator"] in ("path", "bdpt") else row["integrator"])
        key = (row["scene"], name)
        series.setdefault(key, []).append((float(row["seconds"]), float(row["rmse"])))
    scenes = sorted({s for s, _ in series})
    if not scenes:
        raise ValueError(f"{csv_path}: no rows")
    cols = min(len(scenes), 2)
    nrows = math.ceil(len(scenes) / cols)
    style = dict(SLIDE_STYLE, **{"font.size": 20, "lines.linewidth": 3})
    with plt.rc_context(style):
        fig, axes = plt.subplots(nrows, cols, figsize=(width_px / DPI, height_px / DPI), dpi=DPI,
                                 squeeze=False)
        for ax, scene in zip(axes.flat, scenes):
            for (s, name), points in sorted(series.items()):
                if s == scene:
                    points.sort()
                    ax.loglog([p[0] for p in points], [p[1] for p in points], "o-", ms=5,
                              label=name)
            ax.set_title(scene)
            ax.grid(alpha=0.3, which="both")
        for ax in axes[-1]:
            ax.set_xlabel("CPU seconds (one thread)")
        for ax in axes[:, 0]:
            ax.set_ylabel("RMSE")
        for ax in list(axes.flat)[len(scenes):]:
            ax.axis("off")
        # each legend beside its axes, never over data (the furnace's lines leave no room inside)
        for ax in list(axes.flat)[:len(scenes)]:
            ax.legend(fontsize=16, loc="upper left", bbox_to_anchor=(1.01, 1.0), framealpha=0.9)
        fig.tight_layout()
        clear = all(_legend_clear_of_data(fig, ax, ax.get_legend())
                    for ax in list(axes.flat)[:len(scenes)])
        fig.savefig(png)
        plt.close(fig)
    return clear


LPE_PT = 27  # 37.5 px at 100 dpi: the 36 px for LPE captions at 1080p
# One colour per path, in the order `explain` lists them (largest contribution first).
PATH_COLOURS = ["#e6194b", "#3cb44b", "#4363d8", "#f58231", "#911eb4", "#42d4f4", "#f032e6",
                "#bfef45", "#fabed4", "#469990"]


def _segments_2d(vertices, drop=None):
    """Consecutive pairs of a path's vertices in (x, z), skipping vertices with no position."""
    pts = [(v[0], v[2]) for v in vertices if v is not None]
    return list(zip(pts, pts[1:]))


PATH_LW = 6          # px/1.39 (points at 100 dpi): each path's line, thick enough to follow
PATH_SPACING = 9     # dots between the parallel lines of paths that share a segment
LABEL_BOX = dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.85)


def _scene_top_view(ax, scene, bunny_points):
    """The scene seen from above (x right, z down the page, as serve's top view): walls and
    triangles as lines, balls as circles, meshes as their vertices, lights and the eye. Returns
    the markers drawn [(x, z, size in points)] and the labels [Text], for the collision check:
    each label stands beside its marker (balls: below the circle), never on it."""
    markers, labels = [], []
    for t in scene.get("triangles", []):
        v = t["vertices"] + [t["vertices"][0]]
        ax.plot([p[0] for p in v], [p[2] for p in v], color="#888", lw=3, zorder=1)
    for s in scene.get("spheres", []):
        x, z, r = s["center"][0], s["center"][2], s["radius"]
        ax.add_patch(plt.Circle((x, z), r, fill=False, color="#aaa", lw=3, zorder=1))
        labels.append(ax.text(x, z - r - 0.15, s["name"], ha="center", va="bottom", fontsize=18,
                              color="#444", bbox=LABEL_BOX, zorder=5))
    for pts in bunny_points:
        ax.plot(pts[:, 0], pts[:, 2], ",", color="#bbb", zorder=0)
    for light in scene.get("lights", []):
        x, z = light["position"][0], light["position"][2]
        ax.plot(x, z, "*", ms=28, color="#f5c518", mec="k", zorder=4)
        markers.append((x, z, 28))
        labels.append(ax.annotate(light["name"], (x, z), xytext=(20, 0), textcoords="offset points",
                                  fontsize=22, va="center", bbox=LABEL_BOX, zorder=5))
    eye = scene["camera"]["eye"]
    ax.plot(eye[0], eye[2], "s", ms=16, color="k", zorder=4)
    markers.append((eye[0], eye[2], 16))
    labels.append(ax.annotate("eye", (eye[0], eye[2]), xytext=(16, 0), textcoords="offset points",
                              fontsize=22, va="center", bbox=LABEL_BOX, zorder=5))
    return markers, labels


def _label_collisions(fig, ax, markers, labels):
    """Pairs (label, what it overlaps) among the top view's labels and markers, in display
    pixels after drawing: a marker is the square of its size around its centre."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in labels]
    found = []
    for i, (name, box) in enumerate(boxes):
        for x, z, size in markers:
            cx, cy = ax.transData.transform((x, z))
            half = size * fig.dpi / 72 / 2
            if box.x0 < cx + half and cx - half < box.x1 and box.y0 < cy + half and cy - half < box.y1:
                found.append((name, f"the marker at ({x:g}, {z:g})"))
        for other, obox in boxes[i + 1:]:
            if box.overlaps(obox):
                found.append((name, f"the label '{other}'"))
    return found


def _offset(fig, ax, segment, k):
    """A transform that shifts a segment k * PATH_SPACING dots sideways (perpendicular to it on
    the page), so that paths sharing a segment are drawn as parallel lines, each visible."""
    from matplotlib.transforms import offset_copy
    (x0, y0), (x1, y1) = ax.transData.transform(segment[0]), ax.transData.transform(segment[1])
    length = math.hypot(x1 - x0, y1 - y0) or 1.0
    nx, ny = -(y1 - y0) / length, (x1 - x0) / length
    return offset_copy(ax.transData, fig=fig, x=nx * k * PATH_SPACING, y=ny * k * PATH_SPACING,
                       units="dots")


def pixel_paths_plot(png, image, pixel, paths, scene, bunny_points, width_px, height_px):
    """Left: the rendered image with every path's segments drawn over it (projected with the
    scene's camera by `explain --json`); right: the same paths seen from above. Each path in its
    colour, sideways from the others where they share a segment, and its LPE in the legend below
    in the same colour.

    paths: [(lpe, vertices [[x, y, z] | None], segments [[x0, y0, x1, y1] | None])].
    Returns {"collisions": the top view's overlapping labels (_label_collisions),
    "colour_pixels": for each path, the pixels of the saved PNG in its colour}."""
    import numpy as np
    h, w = image.shape[:2]
    with plt.rc_context(SLIDE_STYLE):
        fig = plt.figure(figsize=(width_px / DPI, height_px / DPI), dpi=DPI)
        legend_h = (LPE_PT * 1.45 / 72 * DPI) * len(paths) / height_px + 0.02
        image_ax = fig.add_axes((0.01, legend_h + 0.02, 0.56, 0.97 - legend_h))
        top_ax = fig.add_axes((0.60, legend_h + 0.04, 0.39, 0.95 - legend_h))
        image_ax.imshow(image, extent=(0, w, h, 0), interpolation="nearest")
        image_ax.set_xlim(0, w)
        image_ax.set_ylim(h, 0)
        image_ax.axis("off")
        markers, labels = _scene_top_view(top_ax, scene, bunny_points)
        top_ax.set_aspect("equal")
        top_ax.invert_yaxis()  # z grows down the page, toward the eye
        fig.canvas.draw()  # the axes' final limits, for the sideways offsets in dots
        handles = []
        for i, (lpe, vertices, segments) in enumerate(paths):
            colour = PATH_COLOURS[i % len(PATH_COLOURS)]
            k = i - (len(paths) - 1) / 2  # a fan of parallel lines, each visible
            for s in segments:
                if s is not None:
                    seg = ((s[0], s[1]), (s[2], s[3]))
                    t = _offset(fig, image_ax, seg, k)
                    image_ax.plot([s[0], s[2]], [s[1], s[3]], color=colour, lw=PATH_LW,
                                  solid_capstyle="round", transform=t, zorder=3)
                    image_ax.plot([s[2]], [s[3]], "o", ms=11, color=colour, transform=t, zorder=3)
            for a, b in _segments_2d(vertices):
                t = _offset(fig, top_ax, (a, b), k)
                top_ax.plot([a[0], b[0]], [a[1], b[1]], color=colour, lw=PATH_LW - 1,
                            transform=t, zorder=3)
                top_ax.plot([b[0]], [b[1]], "o", ms=9, color=colour, transform=t, zorder=3)
            handles.append(plt.Line2D([], [], color=colour, lw=10, label=lpe))
        image_ax.add_patch(plt.Circle((pixel[0] + 0.5, pixel[1] + 0.5), w / 40, fill=False,
                                      ec="white", lw=3))
        top_ax.set_xlabel("x")
        top_ax.set_ylabel("z")
        top_ax.set_title("from above", fontsize=26)
        legend = fig.legend(handles=handles, loc="lower center", ncol=1, fontsize=LPE_PT,
                            frameon=False, bbox_to_anchor=(0.5, 0.0), handlelength=1.5,
                            borderpad=0.1, labelspacing=0.25)
        for text, handle in zip(legend.get_texts(), handles):
            text.set_color(handle.get_color())  # the legend linked to its line by colour
        collisions = _label_collisions(fig, top_ax, markers, labels)
        views = [ax.get_window_extent() for ax in (image_ax, top_ax)]
        fig.savefig(png, facecolor="white")
        plt.close(fig)
    import matplotlib.image as mpimg
    saved = mpimg.imread(png)[..., :3]
    rows = saved.shape[0]
    colour_pixels = []  # per path, the fewest of its pixels in either view (the legend aside)
    for i in range(len(paths)):
        rgb = np.array(matplotlib.colors.to_rgb(PATH_COLOURS[i % len(PATH_COLOURS)]))
        near = np.abs(saved - rgb).max(axis=2) < 0.06
        colour_pixels.append(min(int(near[rows - int(v.y1):rows - int(v.y0), int(v.x0):int(v.x1)].sum())
                                 for v in views))
    return {"collisions": collisions, "colour_pixels": colour_pixels}


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


REACH_PT = 26  # 36 px at 100 dpi: the slide's smallest text (slide.MIN_TEXT_PX)


def reach_table(png, integrators, classes, cells, width_px, height_px, marked_class=None,
                marked_integrators=()):
    """`lightpath lpe reach` as a table: a row per integrator, a column per path class (rotated
    headers), each cell split into point lights (left) and area lights (right), a tick on green
    where the tool says yes, a cross on grey where it says no. cells[(integrator, class)] =
    (point, area) as the tool printed them; marked_class's column and marked_integrators' rows
    are framed in orange (the slide's AOV and the methods it renders)."""
    from matplotlib.patches import Rectangle
    with plt.rc_context(SLIDE_STYLE):
        fig = plt.figure(figsize=(width_px / DPI, height_px / DPI), dpi=DPI)
        ax = fig.add_axes((0, 0, 1, 1))
        ax.set_xlim(0, width_px)
        ax.set_ylim(height_px, 0)
        ax.axis("off")
        name_w, header_h = 190, 345
        col_w = (width_px - name_w - 10) / len(classes)
        row_h = (height_px - header_h - 10) / len(integrators)
        for j, c in enumerate(classes):
            x = name_w + (j + 0.5) * col_w
            ax.text(x, header_h - 12, c, rotation=90, ha="center", va="bottom", fontsize=REACH_PT,
                    color="#d95f02" if c == marked_class else "black")
        for i, integ in enumerate(integrators):
            y = header_h + i * row_h
            ax.text(name_w - 12, y + row_h / 2, integ, ha="right", va="center", fontsize=REACH_PT,
                    fontweight="bold" if integ in marked_integrators else "normal")
            for j, c in enumerate(classes):
                for k, yes in enumerate(cells[(integ, c)]):
                    x = name_w + j * col_w + k * col_w / 2
                    ax.add_patch(Rectangle((x + 2, y + 2), col_w / 2 - 4, row_h - 4,
                                           color="#2ca02c" if yes else "#d9d9d9"))
                    ax.text(x + col_w / 4, y + row_h / 2, "\u2713" if yes else "\u2717",
                            ha="center", va="center", fontsize=REACH_PT,
                            color="white" if yes else "#777777")
        if marked_class in classes:
            j = classes.index(marked_class)
            ax.add_patch(Rectangle((name_w + j * col_w, 4), col_w, height_px - 8, fill=False,
                                   edgecolor="#ff7f0e", linewidth=5))
        for i, integ in enumerate(integrators):
            if integ in marked_integrators:
                ax.add_patch(Rectangle((4, header_h + i * row_h), width_px - 8, row_h, fill=False,
                                       edgecolor="#ff7f0e", linewidth=3))
        fig.savefig(png, facecolor="white")
        plt.close(fig)
