"""The figure recipes: one function per figure of lectures/figures.toml (its `recipe` key).

A recipe gets a Figure (the run's settings, the figure's folder, title and scenes from
figures.toml), renders with the lightpath CLI, checks on the EXRs what the slide will claim
(checks.py: each failing check stops the generator), and composes the slide (slide.py). It
returns notes for the gallery: what the checks measured.

One LPE spelling everywhere, the README's: no spaces, `<L.'name'>` for a light's label.
"""

import itertools
import re
import tomllib
from pathlib import Path

import numpy as np

import checks
import plots
import slide
from slide import Panel, SLIDE_H, SLIDE_W, MARGIN, TOP, LABEL_H, BELOW_H
from steps import FigureError, cached_render, explain, render, scene_variant, sh

# The `classes` AOVs (docs/lpe.md): every path of every integrator is in exactly one.
CLASSES = [("raycast", "E(D|G)L"), ("raytrace", "ES+(D|G)L"), ("mirror", "ES+L"),
           ("emission", "EL"), ("indirect", "ES*(D|G)(D|G|S)+L")]
CLASS_NAMES = [n for n, _ in CLASSES]
AMBIENT = "ambient=E.*<L.'ambient'>"      # the classic methods' ka Ia, all of it
BOUNCED = "bounced=ES*D(D|G|S)+L"          # what ambient stands in for, in the path tracer
CAUSTIC = "caustic=E(D|G)S+<L.>"           # light from lights through S onto D or G (no sky)
# The taxonomy, one expression per method, as the `taxonomy` preset writes it (src/film/
# taxonomy_preset.cpp); Whitted's beauty also holds the lamp seen in the mirror, ES+L, so its
# label says so beside the preset's E[S*](D|G)L. check_panel_lpes holds each to its image.
METHODS = [("raycast", "ray casting", "E(D|G)L"),
           ("whitted", "Whitted ray tracing", "E[S*](D|G)L|ES+L"),
           ("path", "path tracing", "E(D|G|S)*L"),
           ("radiosity", "radiosity", "ED*L")]
LABEL_LPE = re.compile(r"E\S*")  # a panel's text below that is one LPE (no spaces, from E)


def full_slide_px():
    """The size of the one cell of a one-panel slide, for plots drawn to fill it."""
    return SLIDE_W - 2 * MARGIN, SLIDE_H - TOP - MARGIN - LABEL_H - BELOW_H


def method_renders(fig):
    """The taxonomy scene under raycast, Whitted, path tracing, radiosity and bdpt.

    Shared by the four-methods, nest and ambient figures (each lists the same
    commands; the EXRs are made once, in taxonomy/). Every render has the classes AOVs; the
    classic methods add their ambient term, the path tracer what ambient stands for and its
    caustics, bdpt only the caustics (its beauty is not shown)."""
    run, scene = fig.run, fig.scene(0)
    common = ["--resolution", run.res(640, 360), "--sampler", "sobol", "--aovs", "classes"]
    exrs = {}
    for integ, spp, extra in (("raycast", run.spp_direct, [AMBIENT]),
                              ("whitted", run.spp_direct, [AMBIENT]),
                              ("path", run.spp_path_taxonomy, [BOUNCED, CAUSTIC]),
                              # each bdpt sample also traces and joins light walks, and only
                              # its caustics are shown
                              ("bdpt", run.spp_bdpt_taxonomy, [CAUSTIC]),
                              ("radiosity", run.spp_radiosity, [])):
        opts = ["--integrator", integ, "--spp", spp, *common]
        if integ == "radiosity":
            opts += ["--patches", run.patches]
        for e in extra:
            opts += ["--lpe", e]
        level = {}
        if integ == "bdpt":
            level = dict(noise_level=BDPT_TAXONOMY_LEVEL, noise_why=BDPT_TAXONOMY_WHY)
        exrs[integ] = render(run, "taxonomy", integ, scene, *opts, **level)
    return exrs


# bdpt's taxonomy render shows only its caustic AOV (x4 on slide 2), a focused spot checked
# non-zero; its beauty, on no slide, holds the fireflies of the caustics seen in and through the
# balls, which only the eye's walk finds: 0.31 at 24 spp (steps.Run.spp_bdpt_taxonomy), so 0.1
# would take about 230 spp, some 100 CPU seconds.
BDPT_TAXONOMY_LEVEL = 0.4
BDPT_TAXONOMY_WHY = ("its beauty is on no slide; only its caustic AOV is, a focused spot checked "
                     "non-zero (0.1 would cost ~230 spp, 100 CPU s)")


def check_panel_lpes(fig, panels):
    """Every panel whose text below is one LPE: parsed by `lightpath lpe match` and matched
    against what the panel shows (checks.check_label): a layer of the taxonomy renders against
    its own expression, a beauty against the classes of light it holds."""
    own = dict(CLASSES)
    own.update(e.split("=", 1) for e in (AMBIENT, BOUNCED, CAUSTIC))
    for p in panels:
        if p.source is None or not LABEL_LPE.fullmatch(p.below):
            continue
        layer_expr = own[p.layer] if p.layer else None
        checks.check_label(fig.run.lightpath, p.below, p.source, p.layer, layer_expr, CLASSES)
    return "every printed LPE parsed by lpe match and matched against its panel's AOV"


def four_methods(fig):
    exrs = method_renders(fig)
    notes = []
    for integ in ("raycast", "whitted", "path", "radiosity", "bdpt"):
        worst = checks.check_sum(exrs[integ], CLASS_NAMES)
        notes.append(f"{integ}: classes sum to the beauty (worst pixel {worst:.2g})")
    for integ, name, what in (("radiosity", "", "radiosity's image"),
                              ("path", "indirect", "the path tracer's indirect light"),
                              ("bdpt", "caustic", "bdpt's caustics")):
        mean = checks.check_nonzero(exrs[integ], name, what)
        notes.append(f"{what}: mean luminance {mean:.3g} (non-zero)")
    # radiosity follows ED*L only: nothing in the classes that need S
    for name in ("raytrace", "mirror"):
        checks.check_zero(exrs["radiosity"], name, "radiosity's specular paths")
    notes.append("radiosity's raytrace and mirror AOVs are exactly zero")
    panels = [Panel(exrs[integ], label, lpe) for integ, label, lpe in METHODS[:3]]
    panels += [Panel(exrs["radiosity"], "radiosity", "ED*L"),
               Panel(exrs["path"], "path tracing: indirect", "ES*(D|G)(D|G|S)+L", layer="indirect"),
               Panel(exrs["bdpt"], "bdpt: caustics, x4", "E(D|G)S+<L.>", layer="caustic",
                     exposure=4.0)]
    notes.append(check_panel_lpes(fig, panels))
    fig.compose(panels, cols=3)
    return notes


def nest(fig):
    exrs = method_renders(fig)
    ray, whitted, path = (checks.read_layers(exrs[i]) for i in ("raycast", "whitted", "path"))
    # What Whitted adds, from the two beauties, against Whitted's own AOVs: the same sampler
    # and seed give both integrators the same direct-light samples, so this holds per pixel.
    whitted_adds = whitted[""] - ray[""]
    from_aovs = whitted["raytrace"] + whitted["mirror"]
    worst = float((np.abs(whitted_adds - from_aovs) / np.maximum(np.abs(whitted[""]), 1.0)).max())
    if not worst <= 1e-4:
        raise FigureError(f"whitted - raycast differs from ES+(D|G)L + ES+L by {worst:.3g} "
                          "(relative, worst pixel): 'what Whitted adds' would lie")
    # What path tracing adds: its estimate has its own samples, so the means agree, not pixels.
    path_adds = path[""] - whitted[""]
    path_from_aovs = path["indirect"] - whitted["ambient"]
    rtol = 0.05 if fig.run.quick else 0.02
    diff = checks.check_close(path_adds, path_from_aovs, rtol,
                              "path - whitted against indirect - ambient",
                              scale=float(checks.luminance(path[""]).mean()))
    d = fig.dir
    # Both signed differences on one diverging scale, median-filtered over NEST_SMOOTH_RADIUS
    # pixels around each so that the sign reads through the path tracer's noise and fireflies
    # (the check above is on the unfiltered means).
    (adds_exr, aovs_exr), scale = checks.diverging_exrs(
        [path_adds, path_from_aovs], [d / "path-adds.exr", d / "path-adds-aovs.exr"],
        radius=NEST_SMOOTH_RADIUS)
    panels = [Panel(exrs[i], label, lpe) for i, label, lpe in METHODS[:3]]
    panels += [Panel(checks.write_exr(whitted_adds, d / "whitted-adds.exr"),
                     "Whitted - ray casting", "ES+(D|G)L + ES+L"),
               Panel(adds_exr, "path - Whitted", "red +, blue -, white 0"),
               Panel(aovs_exr, "indirect - ambient", "the same from the AOVs")]
    notes = [check_panel_lpes(fig, panels)]
    fig.compose(panels, cols=3)
    return notes + [
        f"whitted - raycast = raytrace + mirror in every pixel (worst {worst:.2g})",
        f"path - whitted against indirect - ambient: means differ by {diff:.3g} of the "
        f"beauty's mean (bound {rtol})",
        f"signed differences: full red or blue at +-{scale:.3g} (99th percentile of |luminance|), "
        f"each pixel the median of {2 * NEST_SMOOTH_RADIUS + 1}x{2 * NEST_SMOOTH_RADIUS + 1}"]


NEST_SMOOTH_RADIUS = 2


def decomposition(fig):
    # Its own scene (the taxonomy's with a sky and the lamp in view), so that all five panels
    # show light: in the taxonomy scene emission is black and mirror one spot.
    run, scene = fig.run, fig.scene(0)
    common = ["--resolution", run.res(640, 360), "--sampler", "sobol", "--aovs", "classes"]
    exrs = {integ: render(run, fig.id, integ, scene, "--integrator", integ, "--spp", spp, *common)
            for integ, spp in (("whitted", run.spp_direct), ("path", run.spp_decomposition))}
    notes = []
    for integ in ("whitted", "path"):
        worst = checks.check_sum(exrs[integ], CLASS_NAMES)
        notes.append(f"{integ}: max relative |sum - beauty| = {worst:.2g}")
    checks.check_zero(exrs["whitted"], "indirect", "Whitted's indirect light")
    notes.append("whitted: indirect is exactly zero")
    for n, lpe in CLASSES:  # the slide promises each AOV: none may be a black panel
        mean = checks.check_nonzero(exrs["path"], n, f"the {n} panel, {lpe}")
        notes.append(f"path: {n} {lpe} mean luminance {mean:.3g} (non-black)")
    panels = [Panel(exrs["path"], "beauty", "= the sum of the five")]
    panels += [Panel(exrs["path"], n, lpe, layer=n) for n, lpe in CLASSES]
    notes.append(check_panel_lpes(fig, panels))
    fig.compose(panels, cols=3)
    return notes


def szymczak(fig):
    run = fig.run
    exr = render(run, fig.id, "szymczak", fig.scene(0), "--integrator", "raycast",
                 "--resolution", run.res_for(slide.cell_aspect(6, 3)), "--spp", run.spp_direct,
                 "--lpe", "ambient=ED<L.'ambient'>", "--lpe", "diffuse=ED<L.'lamp'>",
                 "--lpe", "specular=EG<L.'lamp'>", "--lpe", "background=EB",
                 "--lpe", "lamp=E(D|G)<L.'lamp'>")
    worst = checks.check_sum(exr, ["ambient", "diffuse", "specular", "background"])
    # the sixth panel, the lamp's whole term, is the diffuse and specular panels together
    lamp_worst = checks.check_sum(exr, ["diffuse", "specular"], total="lamp")
    panels = [Panel(exr, "ambient ka Ia", "ED<L.'ambient'>", layer="ambient"),
              Panel(exr, "diffuse kd N.L I/att", "ED<L.'lamp'>", layer="diffuse"),
              Panel(exr, "specular ks (H.N)^n", "EG<L.'lamp'>", layer="specular"),
              Panel(exr, "background", "EB", layer="background"),
              Panel(exr, "the lamp: diffuse + specular", "E(D|G)<L.'lamp'>", layer="lamp"),
              Panel(exr, "total: the beauty", "= the sum of the four")]
    fig.compose(panels, cols=3)
    return [f"ambient + diffuse + specular + background = beauty (worst pixel {worst:.2g})",
            f"diffuse + specular = the lamp's E(D|G)<L.'lamp'> (worst pixel {lamp_worst:.2g})"]


def exponent(fig):
    run = fig.run
    exponents = [1, 10, 100, 1000]
    panels = []
    for n in exponents:
        scene = scene_variant(fig.dir, fig.scene(0).name, f"exponent-n{n}", n=n)
        exr = render(run, fig.id, f"n{n}", scene, "--integrator", "raycast",
                     "--resolution", run.res(400, 300), "--spp", run.spp_direct)
        panels.append(Panel(exr, f"n = {n}", "E(D|G)L"))
    # the four balls 2x2 on the left, the plot as tall as the slide on the right
    grid_w = 2 * 462 + slide.GAP
    plot = fig.dir / "plot.png"
    plots.exponent_plot(plot, exponents, *slide.side_size(grid_w))
    fig.note_command("python3 lectures/plots.py: exponent_plot, cos(angle)^n for each n")
    fig.compose(panels, cols=2, side=Panel(plot, "(H.N)^n against the angle", "ks (H.N)^n = ks cos^n"),
                grid_w=grid_w)


def attenuation(fig):
    run = fig.run
    # The nearest ball is about 2.5 from the lamp: intensities make it receive about 1.
    cases = [("1/d^2", "[0, 0, 1]", 6.0, "c2 = 1: physical"),
             ("1/(c1 d)", "[0, 1, 0]", 2.5, "c1 = 1: the compromise"),
             ("constant", "[1, 0, 0]", 1.0, "c0 = 1: none")]
    panels = []
    for i, (label, att, intensity, note) in enumerate(cases):
        scene = scene_variant(fig.dir, fig.scene(0).name, f"attenuation-{i}",
                              intensity=intensity, attenuation=att)
        # three tall panels side by side: the row of balls receding, as high as the frame
        exr = render(run, fig.id, f"attenuation-{i}", scene, "--integrator", "raycast",
                     "--resolution", run.res_for(slide.cell_aspect(3, 3), 640),
                     "--spp", run.spp_direct)
        panels.append(Panel(exr, f"{label}: {att}", note))
    fig.compose(panels)


def shadow_scene(fig, s):
    """The shadow scene with every length multiplied by s."""
    return scene_variant(fig.dir, fig.scene(0).name, f"shadow-scale-{s:g}", s=f"{s:g}",
                         eye_y=1.2 * s, eye_z=4.0 * s, look_y=0.3 * s, r=0.5 * s,
                         light_x=-6.0 * s, light_y=1.2 * s)


# The zoomed part of each shadow panel (fractions of the image): the ball's lit side and the
# floor left of it, where acne shows, and the contact, where a detached shadow shows.
ACNE_CROP = (0.2, 0.3, 0.6, 0.7)  # 16:9, as the panels
ACNE_MIN_FRACTION = 0.01  # of the inset's pixels darker than the robust render's: acne shows
ACNE_SPP = 4              # the samples per pixel of the shadow renders (4: the slides' before)
ACNE_DARKER = 0.8          # "darker": below this fraction of the robust render's luminance


def acne_fraction(exr, reference, crop):
    """The fraction of the crop's pixels whose luminance is below ACNE_DARKER of reference's:
    the shadow rays that hit their own surface (the picture is the same at every scale)."""
    a, b = (checks.luminance(checks.layer(e, "")) for e in (exr, reference))
    h, w = a.shape
    x0, y0, x1, y1 = crop
    cut = (slice(round(y0 * h), round(y1 * h)), slice(round(x0 * w), round(x1 * w)))
    return float((a[cut] < ACNE_DARKER * b[cut]).mean())


def shadow_acne(fig):
    run = fig.run
    cases = [(1.0, ["--ray-offset", "none"], "no offset", "scale 1: acne", True),
             (1e3, ["--ray-offset", "epsilon", "--epsilon", "1e-4"], "eps 1e-4",
              "scale 1e3: acne", True),
             (2e-4, ["--ray-offset", "epsilon", "--epsilon", "1e-4"], "eps 1e-4",
              "scale 2e-4: detached", False),
             (1e3, [], "robust offset", "scale 1e3: right", False)]
    # at most ACNE_SPP samples: more anti-aliasing averages the acne's speckles into a tone
    exrs = [render(run, fig.id, f"shadow-{i}", shadow_scene(fig, s), *opts,
                   "--resolution", run.res_for(slide.cell_aspect(8, 4)),
                   "--spp", min(run.spp_direct, ACNE_SPP))
            for i, (s, opts, _, _, _) in enumerate(cases)]
    # the insets must show what their labels say: acne where there is, none from the robust offset
    notes = []
    for exr, (_, _, label, note, acne) in zip(exrs, cases):
        f = acne_fraction(exr, exrs[-1], ACNE_CROP)
        if acne and not f >= ACNE_MIN_FRACTION:
            raise FigureError(f"{exr}: '{label}, {note}': only {f:.2%} of the inset's pixels are "
                              f"acne (< {ACNE_MIN_FRACTION:.0%}): the zoom would show none")
        notes.append(f"{label}, {note}: {f:.1%} of the inset darker than the robust offset's")
    panels = [Panel(exr, label, note) for exr, (_, _, label, note, _) in zip(exrs, cases)]
    zoom = round(1 / (ACNE_CROP[2] - ACNE_CROP[0]), 1)
    panels += [Panel(exr, f"zoom x{zoom:g}", "", crop=ACNE_CROP) for exr in exrs]
    fig.compose(panels, cols=4)
    return notes


RAY_SPHERE_CASES = [
    # name, sphere centre, radius; the ray starts at the origin along +x
    ("no hit", (3, 1.6, 0), 1.0),
    ("tangent", (3, 1.0, 0), 1.0),
    ("two hits", (3, 0.0, 0), 1.0),
    ("origin inside", (0.5, 0.0, 0), 1.5),
    ("sphere behind", (-2.5, 0.0, 0), 1.0),
]


def first_hit(fig, i, centre, r):
    """The renderer's answer for one ray: does it hit the ball, and the first hit's t.

    From `explain --json` of the 1x1 image whose one ray is the drawn ray: a hit is a path
    touching 'ball', and t the distance from the eye to the hit vertex explain reports. Where
    N.L = 1 (a ray through the centre; eye lamp, attenuation 1/d, kd = 1) the diffuse layer is
    1/t too, and must agree."""
    scene = scene_variant(fig.dir, fig.scene(0).name, f"case-{i}", dir_x=1, dir_y=0, dir_z=0,
                          cx=centre[0], cy=centre[1], cz=centre[2], r=r)
    doc = explain(fig.run, scene, 0, 0, "--integrator", "raycast",
                  "--lpe", "diffuse=ED<L.'eye-lamp'>", "--lpe", "ambient=ED<L.'ambient'>")
    ball_paths = [p for p in doc["paths"]
                  if any(e.get("touched") == "ball" or e.get("label") == "ball" for e in p["events"])]
    if not ball_paths:
        return False, None
    eye, first = (np.array(v) for v in ball_paths[0]["contributions"][0]["vertices"][:2])
    t = float(np.linalg.norm(first - eye))
    diffuse = next(l["rgb"][0] for l in doc["layers"] if l["name"] == "diffuse")
    if centre[1] == 0 and diffuse > 0 and abs(1.0 / diffuse - t) > 1e-3 * t:
        raise FigureError(f"ray-sphere case {i}: the hit vertex is at t = {t}, the diffuse term "
                          f"says 1/{diffuse} = {1.0 / diffuse}")
    return True, t


def check_ray_sphere_diagram(results):
    """What the diagram must show: a first-hit marker and its t for every hit the renderer
    reports, and every circle whole inside the drawn area (none clipped)."""
    (x0, x1), (y0, y1) = plots.RAY_SPHERE_XLIM, plots.RAY_SPHERE_YLIM
    for name, c, r, hit, t in results:
        if hit and t is None:
            raise FigureError(f"ray-sphere '{name}': a hit without t: no first-hit marker to draw")
        if not (x0 < c[0] - r and c[0] + r < x1 and y0 < c[1] - r and c[1] + r < y1):
            raise FigureError(f"ray-sphere '{name}': the circle (centre {c[:2]}, r {r}) is "
                              f"clipped by the diagram's area x {x0}..{x1}, y {y0}..{y1}")


def ray_sphere(fig):
    results = []
    for i, (name, c, r) in enumerate(RAY_SPHERE_CASES):
        hit, t = first_hit(fig, i, c, r)
        results.append((name, c, r, hit, t))
    # Against the closed form: t = c.x - sqrt(r^2 - c.y^2) for a ball in front (the origin
    # outside), c.x + sqrt(...) from inside; no hit when the ray misses or the ball is behind;
    # the tangent's double root c.x, if the renderer's rounding makes it a hit.
    for name, c, r, hit, t in results:
        h2 = r * r - c[1] ** 2
        roots = [] if h2 < 0 else [c[0] - h2 ** 0.5, c[0] + h2 ** 0.5]
        ahead = [x for x in roots if x > 1e-9]
        expected = min(ahead) if ahead and (h2 > 1e-12 or hit) else None
        if expected is not None and (t is None or abs(t - expected) > 1e-3 * expected):
            raise FigureError(f"ray-sphere '{name}': lightpath's t = {t}, the formula's {expected}")
        if expected is None and name != "tangent" and hit:
            raise FigureError(f"ray-sphere '{name}': lightpath reports a hit, the formula none")
    check_ray_sphere_diagram(results)
    png = fig.dir / "diagram.png"
    w, h = full_slide_px()
    plots.ray_sphere_diagram(png, results, w, h)
    fig.note_command("python3 lectures/plots.py: ray_sphere_diagram, the cases and the hits")
    fig.compose([Panel(png, "one ray per case, from the dot to the right",
                       "hit or miss and t: lightpath explain --json")])
    return [f"{n}: {'hit' if hit else 'miss'}" + (f", t = {t:.4f}" if t else "")
            for n, _, _, hit, t in results]


def automaton(fig):
    run = fig.run
    dot, png = fig.dir / "automaton.dot", fig.dir / "automaton.png"
    dot.write_text(sh(run, [run.lightpath, "lpe", "dot", "E[S*](D|G)L"], capture=True))
    # Laid out to the slide's one cell (ratio=fill spreads the states over it; the size in
    # inches at DOT_DPI is the cell's pixels), so that the graph fills the frame
    w, h = full_slide_px()
    sh(run, ["dot", "-Tpng", f"-Gdpi={DOT_DPI}", f"-Gsize={w / DOT_DPI:.3f},{h / DOT_DPI:.3f}!",
             "-Gratio=fill", "-Gfontname=DejaVu Sans", "-Nfontname=DejaVu Sans",
             "-Efontname=DejaVu Sans", "-o", png, dot])
    fig.compose([Panel(png, "E[S*](D|G)L, minimised", "lightpath lpe dot | dot -Tpng")])


DOT_DPI = 200  # Graphviz's 14 pt labels at 200 dpi: 39 px on the slide (MIN_TEXT_PX 36)


# The mirror caustic measured here, on the beauty: budgets of 1 to 256 spp on one thread, each
# against bdpt at reference_spp (its own seed), a converged image that holds the caustic.
CAUSTIC_BUDGETS = [1 << k for k in range(9)]
REFERENCE_SPP = 4096
# --quick (CI): a quarter, three quarters of a cold run's CPU. Its noise adds to bdpt's error at
# 256 spp by sqrt(1 + 256/1024) = 1.12x, against a bar (BIAS_ABOVE) the slide clears 3x over.
QUICK_REFERENCE_SPP = 1024
BIAS_FLAT = 0.8    # the path tracer's error at 256 spp keeps this share of its error at 32 spp
BIAS_ABOVE = 1.5   # and ends this many times above bdpt's: its error is bias, bdpt's noise


def caustic_error_rows(fig):
    """RMSE of the beauty against seconds for path and bdpt on the mirror caustic: rows as
    bench error's CSV has them. The reference is bdpt at reference_spp with another seed; the
    seconds are each budget's samples at the rate of the largest budget's render on one thread
    (render_seconds: its workers' CPU time, without loading the scene, the image module or
    starting the process)."""
    run, scene = fig.run, fig.scene(0)
    reference_spp = reference_spp_of(run)
    # another seed than the budgets' (render() fixes seed 1); the same every run: cached
    reference = cached_render(run, scene, "--integrator", "bdpt", "--spp", reference_spp,
                              "--aovs", "none")
    truth = checks.layer(reference, "")
    rows = []
    for integ in ("path", "bdpt"):
        exrs = [render(run, fig.id, f"{integ}-{spp}", scene, "--integrator", integ,
                       "--spp", spp, "--threads", 1, "--aovs", "none", noise_level=float("inf"),
                       noise_why="a budget of the plot, whose lesson is its error against bdpt "
                       f"at {reference_spp} spp")
                for spp in CAUSTIC_BUDGETS]
        # seconds per sample from the largest budget: the small renders' times are their
        # set-up's (a constant share) and the machine's noise
        per_sample = render_seconds(exrs[-1]) / CAUSTIC_BUDGETS[-1]
        for spp, exr in zip(CAUSTIC_BUDGETS, exrs):
            rmse = float(np.sqrt(((checks.layer(exr, "") - truth) ** 2).mean()))
            rows.append({"scene": "mirror-caustic (beauty)", "integrator": integ,
                         "sampler": "sobol", "spp": spp, "seconds": spp * per_sample,
                         "rmse": rmse})
    return rows


def reference_spp_of(run):
    return QUICK_REFERENCE_SPP if run.quick else REFERENCE_SPP


def render_seconds(exr):
    """The CPU seconds of the render's workers, as lightpath writes them into the EXR's header:
    not its wall seconds, which on one thread include loading the image module (0.25 s, more
    than a 256-spp path-traced render of the mirror caustic itself)."""
    import OpenImageIO as oiio
    inp = oiio.ImageInput.open(str(exr))
    if inp is None:
        raise FigureError(f"{exr}: cannot open: {oiio.geterror()}")
    value = inp.spec().getattribute("lightpath:cpu_seconds")
    inp.close()
    if value is None:
        raise FigureError(f"{exr}: no lightpath:cpu_seconds in its header")
    return max(float(value), 1e-4)


def check_bias(rows):
    """The lesson of the caustic panel: the path tracer's error is its bias (it stops falling,
    at a level above bdpt's), bdpt's is noise (it falls)."""
    err = {(r["integrator"], r["spp"]): r["rmse"] for r in rows}
    last, mid = CAUSTIC_BUDGETS[-1], CAUSTIC_BUDGETS[-4]
    flat = err[("path", last)] / err[("path", mid)]
    above = err[("path", last)] / err[("bdpt", last)]
    if not flat >= BIAS_FLAT:
        raise FigureError(f"mirror caustic: the path tracer's error falls to {flat:.2f} of itself "
                          f"from {mid} to {last} spp (< {BIAS_FLAT}): it is not bias")
    if not above >= BIAS_ABOVE:
        raise FigureError(f"mirror caustic: the path tracer's error at {last} spp is {above:.2f} "
                          f"times bdpt's (< {BIAS_ABOVE}): the slide would not show its bias")
    return flat, above


def run_time_error(fig):
    run = fig.run
    csv, png = fig.dir / "bench-error.csv", fig.dir / "bench-error.png"
    # The full benchmark renders a 4096-spp reference; both modes use --quick (closed-form
    # scenes, budgets up to 32 spp) so that the figures stay within minutes. Its mirror caustic
    # measures the caustic's AOV alone; the slide measures the beauty instead (below).
    sh(run, [run.lightpath, "bench", "error", "--quick", "--csv", csv, "--cache", fig.dir / "cache"])
    caustic = caustic_error_rows(fig)
    flat, above = check_bias(caustic)
    clear = plots.bench_error_plot(csv, png, *full_slide_px(), extra=caustic,
                                   drop={"mirror-caustic"})
    fig.note_command("python3 lectures/plots.py: bench_error_plot of bench-error.csv and the "
                     f"mirror caustic's beauty against bdpt at {reference_spp_of(run)} spp")
    if not clear:
        raise FigureError(f"{png}: a legend covers data in every place tried")
    fig.compose([Panel(png, "RMSE against CPU seconds, log-log", "lightpath bench error --quick")])
    return [f"mirror caustic: the path tracer's error from {CAUSTIC_BUDGETS[-4]} to "
            f"{CAUSTIC_BUDGETS[-1]} spp keeps {flat:.0%} of itself (bar {BIAS_FLAT:.0%}) and ends "
            f"{above:.1f} x bdpt's (bar {BIAS_ABOVE:g}): its bias",
            "no legend covers a data point or line"]


def light_groups(fig):
    run = fig.run
    groups = [("red", "red-lamp"), ("green", "green-lamp"), ("blue", "blue-lamp"),
              ("ambient", "ambient")]
    exr = render(run, fig.id, "groups", fig.scene(0),
                 "--resolution", run.res_for(slide.cell_aspect(6, 3)),
                 "--spp", run.spp_direct,
                 *sum((["--lpe", f"{n}=E.*<L.'{l}'>"] for n, l in groups), []),
                 "--lpe", "background=E.*B")
    worst = checks.check_sum(exr, [n for n, _ in groups] + ["background"])
    panels = [Panel(exr, n, f"E.*<L.'{l}'>", layer=n) for n, l in groups]
    panels += [Panel(exr, "background", "E.*B", layer="background"),
               Panel(exr, "beauty", "= the sum of the five")]
    fig.compose(panels, cols=3)
    return [f"four groups + background = beauty (worst pixel {worst:.2g})"]


def ambient(fig):
    exrs = method_renders(fig)
    w, p = exrs["whitted"], exrs["path"]
    checks.check_nonzero(p, "bounced", "what ambient stands for")
    checks.check_caption_objects(fig.caption, fig.scene(0))
    # Right column: where the guess is wrong, signed (the nest's diverging scale and median)
    wl, pl = checks.read_layers(w), checks.read_layers(p)
    (beauty_diff, term_diff), scale = checks.diverging_exrs(
        [pl[""] - wl[""], pl["bounced"] - wl["ambient"]],
        [fig.dir / "path-minus-whitted.exr", fig.dir / "bounced-minus-ambient.exr"],
        radius=NEST_SMOOTH_RADIUS)
    panels = [Panel(w, "Whitted: beauty", METHODS[1][2]),
              Panel(p, "path tracer: beauty", METHODS[2][2]),
              Panel(beauty_diff, "path - Whitted", "red +, blue -, white 0"),
              Panel(w, "ambient term ka Ia", "E.*<L.'ambient'>", layer="ambient"),
              Panel(p, "what it stands for", "ES*D(D|G|S)+L", layer="bounced"),
              Panel(term_diff, "bounced - ambient", "where the guess is wrong")]
    notes = [check_panel_lpes(fig, panels),
             "every object the caption names is in the scene, as often as it says",
             f"signed differences: full red or blue at +-{scale:.3g}, each pixel the median of "
             f"{2 * NEST_SMOOTH_RADIUS + 1}x{2 * NEST_SMOOTH_RADIUS + 1}"]
    fig.compose(panels, cols=3)
    return notes


BOUNCES = [("b1", "EDL"), ("b2", "EDDL"), ("b3", "EDDDL"), ("b4", "ED{4,}L")]


BOUNCE_LPES = sum((["--lpe", f"{n}={e}"] for n, e in BOUNCES), []) + ["--lpe", "e=EL"]


def bounce_by_bounce(fig):
    run = fig.run
    rad = render(run, fig.id, "radiosity", fig.scene(0), "--integrator", "radiosity",
                 "--patches", run.patches, "--spp", run.spp_radiosity,
                 "--resolution", run.res(512, 512), "--aovs", "none", *BOUNCE_LPES)
    path = render(run, fig.id, "path", fig.scene(0), "--integrator", "path", "--sampler", "sobol",
                  "--spp", run.spp_bounces, "--resolution", run.res(512, 512), "--aovs", "none",
                  *BOUNCE_LPES)
    names = [n for n, _ in BOUNCES] + ["e"]
    notes = []
    for integ, exr in (("radiosity", rad), ("path", path)):
        worst = checks.check_sum(exr, names)
        notes.append(f"{integ}: EL + the four bounces = beauty (worst pixel {worst:.2g})")
    r, p = checks.read_layers(rad), checks.read_layers(path)
    # Each bounce's mean against the path tracer's (of that bounce): radiosity's discretisation
    # error at these budgets is about 1-2% (README, "Radiosity"), the path tracer's noise less.
    rtol = 0.05
    for n, e in BOUNCES:
        checks.check_nonzero(rad, n, f"radiosity's {e}")
        diff = checks.check_close(r[n], p[n], rtol, f"{e}: radiosity against the path tracer")
        notes.append(f"{e}: radiosity's mean differs from the path tracer's by {diff:.3g} of it "
                     f"(bound {rtol})")
    panels = []
    for method, exr in (("radiosity", rad), ("path", path)):
        panels += [Panel(exr, f"{method} {k}", e, layer=n)
                   for k, (n, e) in zip(("1", "2", "3", "4+"), BOUNCES)]
        panels.append(Panel(exr, f"{method}: sum", "EL + the four"))
    fig.compose(panels, cols=5)
    return notes


def patch_mesh(fig):
    run = fig.run
    # five budgets, doubling up to half the one the other radiosity figures use (256 to 4096 at full
    # quality): square panels in five columns fill the frame (flat above, smooth below). Uniform meshes (--refine 0): each
    # panel has the budget its label says; refinement would cut up to 4x as many patches where the
    # light changes, and the label would not be true. No final gather: every bounce is read from
    # the patches, so the mesh is what the panels show.
    budgets = [run.patches >> k for k in range(5, 0, -1)]
    flat_panels, smooth_panels, notes = [], [], []
    for budget in budgets:
        exrs = {}
        for display in ("flat", "smooth"):
            exrs[display] = render(run, fig.id, f"{display}-{budget}", fig.scene(0),
                                   "--integrator", "radiosity", "--patches", budget, "--refine", 0,
                                   "--radiosity-display", display, "--final-gather", 0,
                                   "--resolution", run.res(512, 512),
                                   "--spp", run.spp_radiosity, "--aovs", "none")
            checks.check_nonzero(exrs[display], "", f"radiosity, {display}, {budget} patches")
        flat, smooth = (checks.layer(exrs[k], "") for k in ("flat", "smooth"))
        diff = checks.check_close(smooth, flat, 0.1, f"{budget} patches: smooth against flat")
        notes.append(f"{budget} patches: smooth and flat means differ by {diff:.3g}")
        # the budget, as the option says it: the mesh has at most that many (256 gives 252)
        flat_panels.append(Panel(exrs["flat"], f"--patches {budget}", "flat"))
        smooth_panels.append(Panel(exrs["smooth"], f"--patches {budget}", "smooth"))
    fig.compose(flat_panels + smooth_panels, cols=len(budgets))
    return notes


CAUSTIC_ZOOM = 3          # the insets: a third of the image's width and height, around the focus
CAUSTIC_SHARE = 0.5       # of the caustic's light inside the inset: focused, not spread
CAUSTIC_CONTRAST = 2.0    # its peak against the brightest tenth of the path tracer's image


def check_caustic_in_view(caustic_exr, path_exr):
    """The caustic is seen and focused: the inset centred on the caustic's light holds at least
    CAUSTIC_SHARE of it, and its peak (median of 3x3, so no single firefly) outshines the lit
    floor, the 90th percentile of the path tracer's luminance, CAUSTIC_CONTRAST times. Returns
    (crop, share, contrast)."""
    c = checks.median_filter(checks.luminance(checks.layer(caustic_exr, "caustic")), 1)
    h, w = c.shape
    ys, xs = np.mgrid[0:h, 0:w]
    total = float(c.sum())
    if total <= 0.0:
        raise FigureError(f"{caustic_exr}: no caustic light to centre the inset on")
    cx, cy = float((xs * c).sum() / total) / w, float((ys * c).sum() / total) / h
    half = 0.5 / CAUSTIC_ZOOM
    x0, y0 = min(max(cx - half, 0.0), 1.0 - 2 * half), min(max(cy - half, 0.0), 1.0 - 2 * half)
    crop = (x0, y0, x0 + 2 * half, y0 + 2 * half)
    cut = (slice(round(crop[1] * h), round(crop[3] * h)), slice(round(crop[0] * w), round(crop[2] * w)))
    share = float(c[cut].sum()) / total
    floor = float(np.percentile(checks.luminance(checks.layer(path_exr, "")), 90))
    contrast = float(c.max()) / max(floor, 1e-6)
    if not share >= CAUSTIC_SHARE:
        raise FigureError(f"{caustic_exr}: the inset around the caustic holds {share:.0%} of its "
                          f"light (< {CAUSTIC_SHARE:.0%}): the caustic is spread or out of view")
    if not contrast >= CAUSTIC_CONTRAST:
        raise FigureError(f"{caustic_exr}: the caustic's peak is {contrast:.2g} times the lit "
                          f"floor (< {CAUSTIC_CONTRAST:g}): it is not focused where it can be seen")
    return crop, share, contrast


def caustics(fig):
    run = fig.run
    res = run.res_for(slide.cell_aspect(6, 3))
    exrs = {}
    for integ, spp in (("path", run.spp_caustic_path), ("bdpt", run.spp_caustic)):
        exrs[integ] = render(run, fig.id, integ, fig.scene(0), "--integrator", integ,
                             "--spp", spp, "--resolution", res,
                             "--aovs", "classes", "--lpe", CAUSTIC)
        checks.check_sum(exrs[integ], CLASS_NAMES)
    # a small bright spot: its image mean is small, so the bar is low (but far above zero)
    mean = checks.check_nonzero(exrs["bdpt"], "caustic", "bdpt's caustic", min_mean=1e-4)
    checks.check_zero(exrs["path"], "caustic", "the path tracer's caustic under a point light")
    strategies = check_caustic_strategy(run, fig.scene(0), exrs["bdpt"], res)
    crop, share, contrast = check_caustic_in_view(exrs["bdpt"], exrs["path"])
    panels = [Panel(exrs["path"], "path tracing", "caustic: E(D|G)S+<L.> = 0"),
              Panel(exrs["bdpt"], "bidirectional (bdpt)", "the same light transport"),
              Panel(exrs["bdpt"], "bdpt: the caustic", "E(D|G)S+<L.>", layer="caustic")]
    panels += [Panel(p.source, f"zoom x{CAUSTIC_ZOOM}", p.below if i == 2 else "",
                     layer=p.layer, crop=crop) for i, p in enumerate(panels)]
    fig.compose(panels, cols=3)
    return [f"bdpt ({run.spp_caustic} spp): the caustic's mean luminance {mean:.3g}; the path "
            "tracer's: exactly 0",
            "both: classes sum to the beauty",
            f"the inset holds {share:.0%} of the caustic's light (bar {CAUSTIC_SHARE:.0%}); its "
            f"peak is {contrast:.1f} x the lit floor (bar {CAUSTIC_CONTRAST:g})",
            f"the caustic's brightest pixel: {strategies}"]


def check_caustic_strategy(run, scene, exr, resolution):
    """The README's reading of the caustic: through a specular vertex no join can pass, so only
    light tracing (t = 1, s = every other vertex) makes it. Explain the caustic's brightest pixel
    under bdpt and fail unless every caustic contribution there came from that one strategy."""
    caustic = checks.luminance(checks.layer(exr, "caustic"))
    y, x = np.unravel_index(int(np.argmax(caustic)), caustic.shape)
    # Explaining one pixel of light tracing traces the whole image's light walks (any of them may
    # splat there): 4 spp finds the brightest pixel's caustic at half of 8's 4.5 CPU s.
    doc = explain(run, scene, x, y, "--integrator", "bdpt", "--spp", 4, "--resolution", resolution,
                  "--lpe", CAUSTIC, "--aovs", "none", "--quiet")
    found = {}
    for path in doc["paths"]:
        if "caustic" not in path["aovs"]:
            continue
        for c in path["contributions"]:
            st = c["strategy"]
            vertices = len(path["events"])
            if st is None or st["t"] != 1 or not st["splatted"] or st["s"] != vertices - 1:
                raise FigureError(f"caustic at pixel {x},{y}: {path['path']} came from strategy {st}, "
                                  f"expected s={vertices - 1} t=1 (light tracing)")
            found[path["compact"]] = found.get(path["compact"], 0) + 1
    if not found:
        raise FigureError(f"caustic at pixel {x},{y}: explain found no caustic contribution")
    return ", ".join(f"{p} x{n} all from s={len(p) - 1} t=1" for p, n in found.items())


def fill_caption(fig, **values):
    """The caption of figures.toml with the values the recipe measured put into its {names}:
    a number stated on the slide is computed, never typed in."""
    try:
        fig.caption = fig.caption.format(**values)
    except (KeyError, IndexError, ValueError) as e:
        raise FigureError(f"caption of {fig.id}: cannot fill in {e}") from e


# Materials of the object-id render: object k (in file order) reflects ka = k / ID_SCALE of the
# ambient light, red only; a power of two, so ka Ia (Ia = 1) is exact in the EXR.
ID_SCALE = 1024
OBJECT_SECTIONS = ("[[spheres]]", "[[planes]]", "[[triangles]]", "[[meshes]]")


def object_id_scene(src, dst):
    """A copy of scene src whose render by ray casting shows, in every pixel, which object the
    pixel centre's ray hits first: the lights off, the ambient light 1, the background 0, and
    object k in its own material ka = [k / ID_SCALE, 0, 0]. Returns (path, number of objects)."""
    out, section, count = [], None, 0
    for line in src.read_text().splitlines():
        s = line.strip()
        if s.startswith("["):
            section = s.split("#")[0].strip()
        key = s.split("=")[0].strip() if "=" in s and not s.startswith("#") else None
        if section in OBJECT_SECTIONS and key == "material":
            count += 1
            line = f'material = "object-id-{count}"'
        elif section == "[world]" and key in ("ambient", "background"):
            continue
        elif section == "[[lights]]" and key == "intensity":
            line = "intensity = 0"
        elif section == "[[meshes]]" and key == "file":
            # relative to the scene file, which the copy is not beside
            mesh = (src.parent / s.split("=", 1)[1].split("#")[0].strip().strip('"')).resolve()
            line = f'file = "{mesh}"'
        out.append(line)
        if section == "[world]" and s == "[world]":
            out += ["ambient = 1", "background = 0"]
    if "[world]" not in (l.strip() for l in out):
        out += ["[world]", "ambient = 1", "background = 0"]
    for k in range(1, count + 1):
        out += [f"[materials.object-id-{k}]", f"ka = [{k / ID_SCALE!r}, 0, 0]"]
    dst.write_text("\n".join(out) + "\n")
    return dst, count


def edge_pixels(ids):
    """Pixels one of whose 8 neighbours (or which itself, at the border) sees another object."""
    h, w = ids.shape
    padded = np.pad(ids, 1, mode="edge")
    edge = np.zeros((h, w), bool)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            edge |= padded[1 + dy:1 + dy + h, 1 + dx:1 + dx + w] != ids
    return edge


RASTER_TOLERANCE = 1e-4  # relative: rounding of two formulas for one point (tests/render/test_raster.cpp)


def raster_vs_raycast(fig):
    run = fig.run
    scene = fig.scene(0)
    res = run.res_for(slide.cell_aspect(6, 3))  # six panels, three columns: filling the frame
    common = ["--resolution", res, "--spp", 1, "--aovs", "classes"]
    raster = render(run, fig.id, "raster", scene, "--integrator", "raster", *common)
    rays = render(run, fig.id, "raycast-no-shadows", scene, "--integrator", "raycast",
                  "--shadows", "off", *common)
    shadowed = render(run, fig.id, "raycast", scene, "--integrator", "raycast", *common)
    id_scene, objects = object_id_scene(scene, fig.dir / "object-ids.toml")
    ids_exr = render(run, fig.id, "object-ids", id_scene, "--integrator", "raycast",
                     "--resolution", res, "--spp", 1, "--aovs", "none")
    ids = np.rint(checks.layer(ids_exr, "")[..., 0] * ID_SCALE).astype(int)
    if not 1 < len(np.unique(ids)) <= objects + 1:
        raise FigureError(f"{ids_exr}: {len(np.unique(ids))} object ids for {objects} objects")
    edge = edge_pixels(ids)

    a, b, s = (checks.read_layers(e) for e in (raster, rays, shadowed))
    names = sorted(set(a) & set(b))
    diff = np.max([np.abs(a[n] - b[n]).max(axis=2) for n in names], axis=0)
    scale = np.maximum(1.0, np.max([np.abs(a[n]).max(axis=2) for n in names], axis=0))
    relative = diff / scale
    worst = float(relative[~edge].max())
    edge_differing = int((relative[edge] > RASTER_TOLERANCE).sum())
    if not worst <= RASTER_TOLERANCE:
        raise FigureError(f"rasteriser against ray casting without shadows: {worst:.3g} (relative) "
                          f"off the edges > {RASTER_TOLERANCE}: 'the same image' would lie")
    shadow_gain = s[""] - b[""]
    shadow_relative = np.abs(shadow_gain).max(axis=2) / np.maximum(1.0, np.abs(b[""]).max(axis=2))
    shadowed_share = float((shadow_relative[~edge] > RASTER_TOLERANCE).mean())
    if not shadowed_share > 0.01:
        raise FigureError(f"shadow rays change only {shadowed_share:.2%} of the interior pixels: "
                          "'what shadow rays add' would be empty")
    d = fig.dir
    diff_exr = checks.write_exr(np.repeat((10 * diff)[..., None], 3, axis=2), d / "difference.exr")
    # edge pixels grey, those that differ red (with their neighbours, to be seen on a slide)
    differing = edge & (relative > RASTER_TOLERANCE)
    shown = np.pad(differing, 1)
    shown = np.max([shown[1 + dy:1 + dy + edge.shape[0], 1 + dx:1 + dx + edge.shape[1]]
                    for dy in (-1, 0, 1) for dx in (-1, 0, 1)], axis=0)
    edge_rgb = np.repeat(edge[..., None].astype(float) * 0.3, 3, axis=2)
    edge_rgb[shown] = (1.0, 0.05, 0.02)
    edge_exr = checks.write_exr(edge_rgb, d / "edges.exr")
    panels = [Panel(raster, "rasteriser", "--integrator raster"),
              Panel(rays, "ray casting", "--shadows off"),
              Panel(diff_exr, "|difference| x 10", f"off the edges: {worst:.1e}",
                    dark="black where the two agree: the point"),
              Panel(edge_exr, "edge pixels", f"{edge_differing} of {int(edge.sum())} differ (red)",
                    dark="only the edges are drawn"),
              Panel(shadowed, "ray casting", "with shadow rays"),
              Panel(checks.signed_exr(shadow_gain, d / "shadows-add.exr"),
                    "what shadow rays add", "blue: light they remove")]
    fig.compose(panels, cols=3)
    fill_caption(fig, max_interior=f"{worst:.1e}", edge_differing=edge_differing,
                 edge_pixels=int(edge.sum()), pixels=edge.size,
                 shadowed=f"{shadowed_share:.1%}")
    return [f"largest relative difference off the edges: {worst:.3g} (bound {RASTER_TOLERANCE})",
            f"{edge_differing} of {int(edge.sum())} edge pixels differ (of {edge.size} pixels)",
            f"shadow rays change {shadowed_share:.1%} of the interior pixels"]


# The pixel figures 'pixel-paths' and 'automaton-at-work' explain: on the lower half of the
# lecture room's mirror ball, which shows the floor (as a fraction of the image, so that --quick's
# half resolution explains the same spot).
PIXEL_AT = (310.5 / 640, 285.5 / 480)
PIXEL_OPTIONS = ["--integrator", "whitted", "--spp", 1]


def explained_pixel(fig):
    """The lecture room rendered by Whitted, the explained pixel and its `explain --json`."""
    run = fig.run
    res = run.res(640, 480)
    w, h = (int(v) for v in res.split("x"))
    x, y = int(PIXEL_AT[0] * w), int(PIXEL_AT[1] * h)
    exr = render(run, "pixel-paths", "whitted", fig.scene(0), *PIXEL_OPTIONS, "--resolution", res)
    doc = explain(run, fig.scene(0), x, y, *PIXEL_OPTIONS, "--resolution", res, "--quiet")
    # explain's contributions are the render's: their sum is the rendered pixel
    beauty = checks.layer(exr, "")[y, x]
    total = np.sum([p["rgb"] for p in doc["paths"]], axis=0)
    if not np.allclose(total, beauty, rtol=1e-4, atol=1e-6):
        raise FigureError(f"pixel {x},{y}: explain's paths sum to {total}, the render has {beauty}")
    return exr, (x, y), doc


def pixel_paths(fig):
    exr, (x, y), doc = explained_pixel(fig)
    paths = []
    for p in doc["paths"]:
        c = p["contributions"][0]  # Whitted at 1 spp: one contribution per path
        if len(c["vertices"]) != len(p["events"]) or len(c["segments"]) != len(p["events"]) - 1:
            raise FigureError(f"{p['path']}: {len(c['vertices'])} vertices and {len(c['segments'])} "
                              f"segments for {len(p['events'])} events")
        # the camera ray's segment ends where the eye sees: the pixel's centre
        end = c["segments"][0]
        if end is None or abs(end[2] - (x + 0.5)) > 0.01 or abs(end[3] - (y + 0.5)) > 0.01:
            raise FigureError(f"{p['path']}: the camera ray ends at {end}, not at the centre of "
                              f"pixel {x},{y}")
        paths.append((p["path"], c["vertices"], c["segments"]))
    if len(paths) < 3 or not any("<RS" in p for p, _, _ in paths):
        raise FigureError(f"pixel {x},{y}: {len(paths)} paths, expected several, one through "
                          "the mirror")
    scene = tomllib.loads(fig.scene(0).read_text())
    image = slide.Panel(exr).display()
    w, h = full_slide_px()
    png = fig.dir / "paths.png"
    drawn = plots.pixel_paths_plot(png, image, (x, y), paths, scene,
                                   mesh_points(fig.scene(0), scene), w, h)
    fig.note_command("python3 lectures/plots.py: pixel_paths_plot of explain's vertices and segments")
    # every path can be told apart: its colour shows in both views, over the others
    for (lpe, _, _), n in zip(paths, drawn["colour_pixels"]):
        if n < PATH_MIN_PIXELS:
            raise FigureError(f"{png}: the path {lpe} shows {n} pixels of its colour in one view "
                              f"(< {PATH_MIN_PIXELS}): another path covers it")
    if drawn["collisions"]:
        raise FigureError(f"{png}: in the top view " + "; ".join(
            f"the label '{a}' overlaps {b}" for a, b in drawn["collisions"]))
    fig.compose([Panel(png, f"pixel {x},{y}: every path explain finds",
                       "over the image (projected) and from above")])
    return [f"pixel {x},{y}: {len(paths)} paths; their sum is the rendered pixel",
            "each camera ray's segment ends at the pixel's centre",
            f"each path shows at least {min(drawn['colour_pixels'])} pixels of its colour in each "
            f"view (bar {PATH_MIN_PIXELS}); no label of the top view overlaps a marker or a label"]


PATH_MIN_PIXELS = 150  # of a path's colour in each view: a line of its own, not hidden


def mesh_points(scene_path, scene):
    """Every mesh's vertices, placed as the loader places them (scenes/README.md: scale, then
    rotate_y with x towards -z, then translate), for the top view: [(n, 3) arrays]."""
    meshes = []
    for m in scene.get("meshes", []):
        v = np.array([[float(t) for t in line.split()[1:4]]
                      for line in (scene_path.parent / m["file"]).read_text().splitlines()
                      if line.startswith("v ")])
        v = v * np.asarray(m.get("scale", 1.0), dtype=float)
        a = np.radians(m.get("rotate_y", 0.0))
        x, z = v[:, 0] * np.cos(a) + v[:, 2] * np.sin(a), -v[:, 0] * np.sin(a) + v[:, 2] * np.cos(a)
        v = np.stack([x, v[:, 1], z], axis=1) + np.asarray(m.get("translate", [0, 0, 0]), dtype=float)
        meshes.append(v[::7])
    return meshes


def automaton_at_work(fig):
    run = fig.run
    _, (x, y), doc = explained_pixel(fig)
    dot_text = sh(run, [run.lightpath, "lpe", "dot", "--set", "classes"], capture=True)
    nodes = {int(n) for n in re.findall(r"^  (\d+)[ ;]", dot_text, re.M)}
    lpes = [p["path"] for p in doc["paths"]]
    out = sh(run, [run.lightpath, "lpe", "match", "--set", "classes", "--trace", *lpes],
             capture=True).splitlines()
    rows, visited, edges = [], set(), set()
    for p, verdict, trace in zip(doc["paths"], out[0::2], out[1::2]):
        aovs = verdict.split()[0]
        states = [int(s) for s in trace.split(":", 1)[1].split()]
        # the states lpe match names are the renderer's verdict: the same AOVs
        if aovs.split(",") != p["aovs"]:
            raise FigureError(f"{p['path']}: lpe match says {aovs}, the render put it in {p['aovs']}")
        if not set(states) <= nodes:
            raise FigureError(f"{p['path']}: states {states}, the graph has {sorted(nodes)}")
        visited |= set(states)
        edges |= set(zip(states, states[1:]))
        rows.append((p["path"], states, aovs))
    if len(rows) != len(lpes):
        raise FigureError(f"lpe match answered {len(rows)} of {len(lpes)} paths")
    highlight = "".join(f'  {s} [style=filled, fillcolor="#ffd34d"];\n' for s in sorted(visited))
    highlight += "".join(f'  {a} -> {b} [color="#d62728", penwidth=4];\n' for a, b in sorted(edges))
    # strict: a repeated edge statement adds attributes to the edge instead of drawing another
    marked = "strict " + dot_text.rstrip().rstrip("}") + highlight + "}\n"
    dot, png = fig.dir / "automaton.dot", fig.dir / "automaton.png"
    dot.write_text(marked)
    fig.note_command("python3 lectures/recipes.py: the visited states filled, their edges red")
    sh(run, ["dot", "-Tpng", "-Gdpi=150", "-Gfontname=DejaVu Sans", "-Nfontname=DejaVu Sans",
             "-Efontname=DejaVu Sans", "-o", png, dot])
    slide_png = fig.dir / "automaton-states.png"
    plots.automaton_with_states(slide_png, png, rows, *full_slide_px())
    fig.note_command("python3 lectures/plots.py: automaton_with_states, the graph over lpe match --trace")
    fig.compose([Panel(slide_png, f"the classes automaton and pixel {x},{y}'s paths",
                       "lpe dot --set classes, lpe match --set classes --trace")])
    return [f"pixel {x},{y}: {len(rows)} paths through states {sorted(visited)}; "
            "lpe match's AOVs are the render's for every path"]


# "What fog adds" (issue #24): the fog scene's light split by its volume events, a partition
# (checked: the three sum to the beauty). `EV<L.>` is the lecture's single scattering (what ray
# casting adds in fog), a part of `once`.
FOG_PARTS = [("surfaces", "E[^V]*L"), ("once", "E[^V]*V[^V]*L"), ("multiple", "E.*V.*V.*L")]
FOG_SINGLE = ("single", "EV<L.>")


# The fog slide's renders miss NOISE_LEVEL (measured at 64 spp: 0.233 with fog, 0.138 without):
# 0.1 would take about 430 spp, seven times this slide's cost, beyond the deck's 3-minute budget.
# A stated exception, shown in the gallery, until the budget or the fog's variance allows it.
# The fog's noise is light that met a surface as well as the fog (E[^V]*V[^V]*L with a D, 47% of
# its squared error), multiple scattering (34%) and the surfaces (23%); the lecture's single
# scattering EV<L.> is 0.5% of it (against the 256-spp reference, 2026-11-28).
FOG_LEVEL = 0.25
FOG_WHY = ("NOT the deck's 0.1: multiple scattering in the fog needs ~430 spp for it, 7x this "
           "slide's cost, beyond the 3-minute budget")
# The room without fog takes the fog panel's samples, so the two compare at the same cost; lit
# through a window, most of its light is indirect: 0.138 at 64 spp, 0.1 would take ~125.
FOG_VACUUM_LEVEL = 0.16
FOG_VACUUM_WHY = ("NOT the deck's 0.1: the fog panel's samples, so the two compare at one cost; "
                  "0.1 would take ~125 spp")


def without_media(src, dst):
    """A copy of scene src with its media unassigned ([world] medium and every interior line
    dropped): the same room in vacuum. Returns dst."""
    lines = [line for line in Path(src).read_text().splitlines()
             if not re.match(r"\s*(medium|interior)\s*=", line)]
    dst.parent.mkdir(parents=True, exist_ok=True)
    dst.write_text("\n".join(lines) + "\n")
    return dst


def check_fog_labels(lightpath, labelled):
    """Each printed LPE accepts exactly the paths of its AOV's expression, on every path of up
    to four events from D, S and V (checks.check_label's comparison, with volume events)."""
    paths = ["E" + "".join(p) + "L" for k in range(5) for p in itertools.product("DSV", repeat=k)]
    for label, expr in labelled:
        said, meant = (checks.lpe_accepts(lightpath, e, paths) for e in (label, expr))
        if said != meant:
            raise FigureError(f"the panel labelled '{label}' shows '{expr}': they differ on "
                              f"{', '.join(sorted(said ^ meant, key=len)[:4])}")
        if not meant:
            raise FigureError(f"'{expr}' accepts no path of up to four events")


def fog(fig):
    run = fig.run
    scene = fig.scene(0)
    # Quick mode (CI's figures-quick, its longest test) at half height and 4 samples: seconds.
    common = ["--integrator", "path", "--spp", run.spp_path,
              "--resolution", run.res_for(slide.cell_aspect(6, 3))]
    vacuum = render(run, fig.id, "no-fog", without_media(scene, fig.dir / "no-fog.toml"), *common,
                    noise_level=FOG_VACUUM_LEVEL, noise_why=FOG_VACUUM_WHY)
    lpes = sum((["--lpe", f"{n}={e}"] for n, e in FOG_PARTS + [FOG_SINGLE]), [])
    exr = render(run, fig.id, "fog", scene, *common, *lpes, noise_level=FOG_LEVEL, noise_why=FOG_WHY)
    worst = checks.check_sum(exr, [n for n, _ in FOG_PARTS])
    layers = checks.read_layers(exr)
    # The lecture's single scattering is part of the light that scattered once in the fog.
    beyond = float((layers["single"] - layers["once"]).max())
    if not beyond <= 1e-5 * max(float(layers["once"].max()), 1.0):
        raise FigureError(f"{exr}: EV<L.> exceeds E[^V]*V[^V]*L by {beyond:.3g}: it is not a part of it")
    means = {n: checks.check_nonzero(exr, n, what) for n, what in
             (("", "the fog's beauty"), ("single", "single scattering"), ("multiple", "multiple scattering"))}
    dimmed = checks.check_nonzero(vacuum, "", "the room without fog")
    surfaces = float(checks.luminance(layers["surfaces"]).mean())
    if not surfaces < dimmed:
        raise FigureError(f"the surfaces seen through fog ({surfaces:.3g}) are not dimmer than "
                          f"without it ({dimmed:.3g})")
    panels = [Panel(vacuum, "without fog", "in vacuum"),
              Panel(exr, "with fog", "= bottom row"),
              Panel(exr, "single scattering", "EV<L.>", layer="single"),
              Panel(exr, "surfaces", "E[^V]*L", layer="surfaces"),
              Panel(exr, "scattered once", "E[^V]*V[^V]*L", layer="once"),
              Panel(exr, "multiple scattering", "E.*V.*V.*L", layer="multiple")]
    # The LPE printed under each AOV panel against the expression its layer was rendered with.
    rendered = dict(FOG_PARTS + [FOG_SINGLE])
    check_fog_labels(run.lightpath, [(p.below, rendered[p.layer]) for p in panels if p.layer])
    fig.compose(panels, cols=3)
    return [f"surfaces + once + multiple = beauty (worst pixel {worst:.2g})",
            f"EV<L.> is within E[^V]*V[^V]*L; mean luminance: beauty {means['']:.3g}, "
            f"single {means['single']:.3g}, multiple {means['multiple']:.3g}",
            f"surfaces through fog {surfaces:.3g} < without fog {dimmed:.3g}",
            "every printed LPE parsed by lpe match and compared on paths with V"]


# Issue #25's slide: the lecture room's glass ball focuses the key lamp onto the floor, and the
# mirror ball shows that caustic: E S+ (D|G) S+ <L.>, which only photon mapping reaches under
# point lights. The camera (the room's own, moved) looks at the mirror ball where it reflects the
# glass ball and its caustic; the AOV alone under sppm, path and bdpt, and `lpe reach`'s table.
SDS = "sds=ES+(D|G)S+<L.>"
# The glass ball's caustic seen in the mirror ball, the part of SDS the slide points at
SDS_GLASS = "glass=E<RS'mirror-ball'>+(D|G)<TS'glass-ball'>+<L.>"
SDS_CAMERA = {"eye": "[0, 1.2, 3]", "look_at": "[0.4, 0.75, -0.6]", "fov": "16"}
SDS_GRID_W = 1000          # the four renders 2x2 left of the table
SDS_CONTRAST = 2.0         # the reflected caustic's peak against the beauty's 90th percentile


def with_camera(src, dst, **camera):
    """A copy of scene src with the [camera] keys given replaced and mesh files made absolute
    (the copy is not beside the scene). Returns dst."""
    out, section = [], None
    for line in Path(src).read_text().splitlines():
        s = line.strip()
        if s.startswith("["):
            section = s.split("#")[0].strip()
        key = s.split("=")[0].strip() if "=" in s and not s.startswith("#") else None
        if section == "[camera]" and key in camera:
            line = f"{key} = {camera[key]}"
        elif section == "[[meshes]]" and key == "file":
            mesh = (Path(src).parent / s.split("=", 1)[1].split("#")[0].strip().strip('"')).resolve()
            line = f'file = "{mesh}"'
        out.append(line)
    Path(dst).write_text("\n".join(out) + "\n")
    return dst


def lpe_reach(run):
    """`lightpath lpe reach`, parsed: (integrators, classes, {(integrator, class): (point,
    area)}, the text as printed)."""
    text = sh(run, [run.lightpath, "lpe", "reach"], capture=True)
    lines = [l for l in text.splitlines() if l.strip()]
    header = next(i for i, l in enumerate(lines) if l.startswith("path class"))
    integrators = lines[header].split()[2:]
    classes, cells = [], {}
    for line in lines[header + 1:]:
        words = line.split()
        if len(words) != len(integrators) + 1 or not all("/" in w for w in words[1:]):
            raise FigureError(f"lpe reach: cannot read the row '{line}'")
        classes.append(words[0])
        for integ, cell in zip(integrators, words[1:]):
            point, area = cell.split("/")
            if {point, area} - {"yes", "no"}:
                raise FigureError(f"lpe reach: '{cell}' for {integ}, {words[0]}: not yes/no")
            cells[(integ, words[0])] = (point == "yes", area == "yes")
    return integrators, classes, cells, text


def mirror_caustic_sppm(fig):
    run = fig.run
    scene = with_camera(fig.scene(0), fig.dir / "lecture-room-mirror.toml", **SDS_CAMERA)
    aspect = slide.cell_aspect(4, 2, width=SDS_GRID_W)
    res = run.res_for(aspect)
    sds_name, sds_expr = SDS.split("=", 1)
    exrs = {}
    for integ, spp in (("sppm", run.passes_sppm), ("path", 4), ("bdpt", 4)):
        opts = ["--integrator", integ, "--spp", spp, "--resolution", res, "--lpe", SDS]
        if integ == "sppm":
            opts += ["--lpe", SDS_GLASS]
            exrs[integ] = render(run, fig.id, integ, scene, *opts, noise_level=float("inf"),
                                 noise_why="sppm's error is a bias (blur) that shrinks with its "
                                 "passes, not noise a reference at 4x the passes measures")
        else:
            # the AOV alone (no beauty, so no path it cannot accept is traced): it is exactly 0
            exrs[integ] = render(run, fig.id, integ, scene, *opts, "--no-beauty",
                                 noise_level=float("inf"),
                                 noise_why="its one panel is an AOV that is exactly 0")
    mean = checks.check_nonzero(exrs["sppm"], sds_name, f"sppm's {sds_expr}", min_mean=1e-4)
    glass = checks.check_nonzero(exrs["sppm"], "glass", "the glass ball's caustic in the mirror",
                                 min_mean=1e-5)
    for integ in ("path", "bdpt"):
        checks.check_zero(exrs[integ], sds_name, f"{integ}'s {sds_expr} under point lights")
    # the reflected caustic is seen: its peak (3x3 median, no single photon's blotch) outshines
    # most of the image
    peak = float(checks.median_filter(checks.luminance(checks.layer(exrs["sppm"], "glass")), 1).max())
    floor = float(np.percentile(checks.luminance(checks.layer(exrs["sppm"], "")), 90))
    if not peak >= SDS_CONTRAST * floor:
        raise FigureError(f"{exrs['sppm']}: the glass ball's caustic in the mirror peaks at "
                          f"{peak:.3g}, under {SDS_CONTRAST:g} x the image's 90th percentile "
                          f"{floor:.3g}: it is not seen")
    # the tool's table, and that it says what the renders show: under point lights (the room's
    # lamps) only sppm reaches the class
    integrators, classes, cells, text = lpe_reach(run)
    if sds_expr not in classes:
        raise FigureError(f"lpe reach has no row {sds_expr}: {', '.join(classes)}")
    for integ, shown in (("sppm", True), ("path", False), ("bdpt", False)):
        if cells[(integ, sds_expr)][0] != shown:
            raise FigureError(f"lpe reach says {integ} {'can' if cells[(integ, sds_expr)][0] else 'cannot'} "
                              f"reach {sds_expr} under point lights; its render shows "
                              f"{'light' if shown else 'none'}")
    png = fig.dir / "reach.png"
    plots.reach_table(png, integrators, classes, cells, *slide.side_size(SDS_GRID_W),
                      marked_class=sds_expr, marked_integrators=("path", "bdpt", "sppm"))
    fig.note_command("python3 lectures/plots.py: reach_table of lightpath lpe reach's output")
    panels = [Panel(exrs["sppm"], "sppm: beauty", f"{run.passes_sppm} photon passes"),
              Panel(exrs["sppm"], "sppm: the AOV, x4", sds_expr, layer=sds_name, exposure=4.0),
              Panel(exrs["path"], "path: the AOV", "exactly 0", layer=sds_name),
              Panel(exrs["bdpt"], "bdpt: the AOV", "exactly 0", layer=sds_name)]
    fig.compose(panels, cols=2, side=Panel(png, "lightpath lpe reach", "point | area lights"),
                grid_w=SDS_GRID_W)
    return [f"sppm ({run.passes_sppm} passes): {sds_expr} mean luminance {mean:.3g}; the glass "
            f"ball's caustic in the mirror {SDS_GLASS.split('=', 1)[1]} {glass:.3g}, its peak "
            f"{peak / max(floor, 1e-9):.1f} x the image's 90th percentile (bar {SDS_CONTRAST:g})",
            "path and bdpt: the AOV is exactly 0 in every pixel",
            "lpe reach agrees: under point lights sppm reaches it, path and bdpt do not",
            "lightpath lpe reach printed:\n" + text]
