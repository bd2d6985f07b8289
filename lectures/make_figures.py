#!/usr/bin/python3
"""Regenerate every lecture figure of lightpath, and the gallery page that shows them.

    /usr/bin/python3 lectures/make_figures.py --lightpath build/lightpath --out build/lectures [--quick]

Each figure is rendered from the scenes with the real renderer (fixed seeds, fixed samples per
pixel, so the output is the same on every run), composed into a 1920x1080 slide with oiiotool
(labels in DejaVuSans, named explicitly: OpenImageIO's default font is not on a fresh machine),
and written as NN-name.png next to the EXRs it came from (in NN-name/). Plots use Debian's
matplotlib, the automaton Graphviz. index.html lists every figure with its caption, its scene
and the exact commands that made it.

Any failing step stops the run with a message naming the command and a non-zero exit code.
"""

import argparse
import html
import math
import shlex
import shutil
import string
import subprocess
import sys
import time
import tomllib
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
FONT = "DejaVuSans"  # named explicitly: OIIO's default font is not installed on a fresh machine
SLIDE_W, SLIDE_H = 1920, 1080  # 16:9
BG = "0.08,0.08,0.09"  # slide background (linear); text is drawn light on dark


class FigureError(RuntimeError):
    """A step of a figure failed: the message says which command and why."""


class Run:
    """Settings of one generator run, and the log of the commands each figure used."""

    def __init__(self, lightpath, out, quick):
        self.lightpath = str(Path(lightpath).resolve())
        self.out = Path(out).resolve()
        self.quick = quick
        # Quality: the default is for slides, --quick for CI (under a minute on 2 cores).
        self.scale = 0.5 if quick else 1.0
        self.spp_direct = 1 if quick else 4      # raycast / Whitted (soft shadows of the area light)
        self.spp_path = 4 if quick else 32       # path tracer
        self.commands = []                       # commands of the figure being made
        self.shared = None                       # the taxonomy renders, once made
        self.dirs = []                           # folders holding the figure's EXRs

    def res(self, w, h):
        """A render resolution, halved in quick mode."""
        return f"{int(w * self.scale)}x{int(h * self.scale)}"

    def rel(self, path):
        """A path as the gallery shows it: relative to the repository when inside it."""
        p = Path(path).resolve()
        for base, prefix in ((REPO, ""), (self.out, "")):
            try:
                return prefix + str(p.relative_to(base))
            except ValueError:
                pass
        return str(p)


def sh(run, argv, record=True, capture=False, cwd=None):
    """Run one command; on failure raise FigureError with its output. Recorded for the gallery."""
    argv = [str(a) for a in argv]
    if record:
        shown = ["lightpath" if a == run.lightpath else run.rel(a) if a.startswith("/") else a
                 for a in argv]
        run.commands.append(shlex.join(shown))
    proc = subprocess.run(argv, capture_output=True, text=True, cwd=cwd)
    if proc.returncode != 0:
        raise FigureError(f"command failed (exit {proc.returncode}): {shlex.join(argv)}\n"
                          f"{proc.stdout[-2000:]}{proc.stderr[-2000:]}")
    return proc.stdout if capture else None


def render(run, fig_dir, name, scene, *options):
    """Render SCENE into fig_dir/NAME.exr with fixed seed and --quiet; returns the EXR path."""
    exr = fig_dir / f"{name}.exr"
    run.dirs.append(fig_dir.name)
    sh(run, [run.lightpath, "render", scene, "-o", exr, "--seed", "1", "--quiet", *options])
    return exr


def scene_variant(fig_dir, template, name, **values):
    """Write a scene from a template in lectures/scenes with $placeholders filled in."""
    text = string.Template((HERE / "scenes" / template).read_text()).substitute(
        {k: str(v) for k, v in values.items()})
    path = fig_dir / f"{name}.toml"
    path.write_text(text)
    return path


# ----------------------------------------------------------------------------------------------
# Composition: a slide is a title and a grid of panels, each an image with a label above and an
# LPE (or note) below. One oiiotool command draws it.

class Panel:
    """One image on a slide: an EXR layer (tone-mapped to sRGB) or a ready PNG, with its texts."""

    def __init__(self, source, label, below="", layer=None, exposure=1.0):
        self.source, self.label, self.below = Path(source), label, below
        self.layer, self.exposure = layer, exposure

    def oiio_load(self, w, h):
        """oiiotool arguments that push this panel, fitted into w x h, on the stack."""
        args = [str(self.source)]
        if self.source.suffix == ".exr":
            chans = ("R,G,B" if self.layer is None
                     else ",".join(f"{self.layer}.{c}" for c in "RGB"))
            args += ["--ch", chans, "--chnames", "R,G,B"]
            if self.exposure != 1.0:
                args += ["--mulc", f"{self.exposure}"]
            args += ["--clamp:min=0:max=1", "--colorconvert", "linear", "sRGB"]
            return args + ["--fit:filter=lanczos3:pad=1", f"{w}x{h}"]
        # A plot or diagram: fitted without padding (black bars would frame a white plot).
        return args + ["--ch", "R,G,B", "--fit:filter=lanczos3", f"{w}x{h}"]


def text(x, y, s, size, color="0.9,0.9,0.9"):
    """oiiotool arguments drawing s at (x, y = baseline) in DejaVuSans."""
    return [f"--text:x={x}:y={y}:size={size}:color={color}:font={FONT}", s]


def compose(run, out_png, title, panels, cols, panel_w, panel_h, gap=20, top=110):
    """Draw title and a cols-wide grid of panels (label above, LPE below) into a 1920x1080 PNG."""
    rows = math.ceil(len(panels) / cols)
    label_h, below_h = 40, 44
    cell_h = label_h + panel_h + below_h
    grid_w = cols * panel_w + (cols - 1) * gap
    x0 = (SLIDE_W - grid_w) // 2
    grid_h = rows * cell_h + (rows - 1) * gap
    if grid_w > SLIDE_W or top + grid_h > SLIDE_H:
        raise FigureError(f"{out_png}: {cols}x{rows} panels of {panel_w}x{panel_h} do not fit the slide")
    y0 = top + (SLIDE_H - top - grid_h) // 2
    # --nosoftwareattrib: no command line (with its paths) in the PNG, so reruns are byte-identical
    args = ["oiiotool", "--nosoftwareattrib", "--create", f"{SLIDE_W}x{SLIDE_H}", "3",
            "--fill:color=" + BG, f"{SLIDE_W}x{SLIDE_H}+0+0"]
    args += text(60, 75, title, 52, "1,1,1")
    for i, p in enumerate(panels):
        r, c = divmod(i, cols)
        x = x0 + c * (panel_w + gap)
        y = y0 + r * (cell_h + gap)
        args += p.oiio_load(panel_w, panel_h) + ["--swap", "--paste", f"+{x}+{y + label_h}"]
        args += text(x, y + 30, p.label, 28, "1,1,1")
        if p.below:
            args += text(x, y + label_h + panel_h + 32, p.below, 24, "0.75,0.85,1")
    args += ["-d", "uint8", "-o", str(out_png)]
    sh(run, args)


# ----------------------------------------------------------------------------------------------
# The figures. Each function renders into fig_dir and composes out_png.

CLASSES = [("raycast", "E(D|G)L"), ("raytrace", "ES+(D|G)L"), ("mirror", "ES+L"),
           ("emission", "EL"), ("indirect", "ES*(D|G)(D|G|S)+L")]


def taxonomy_renders(run, fig_dir):
    """The taxonomy scene under the three integrators, shared by figures 1, 2 and 11.

    Rendered once, into 01-taxonomy/, with the classes AOVs plus figure 11's ambient term (the
    classic methods) or what it stands for (the path tracer: the only one whose paths bounce on);
    a later figure reuses the EXRs and lists the same commands in the gallery."""
    if run.shared is None:
        scene = REPO / "scenes/taxonomy.toml"
        shared_dir = run.out / "01-taxonomy"
        shared_dir.mkdir(parents=True, exist_ok=True)
        before = len(run.commands)
        exrs = {}
        for integ in ("raycast", "whitted", "path"):
            spp = run.spp_path if integ == "path" else run.spp_direct
            extra = "bounced=ES*D(D|G|S)+L" if integ == "path" else "ambient=ES*D<L'ambient'>"
            exrs[integ] = render(run, shared_dir, integ, scene, "--integrator", integ,
                                 "--resolution", run.res(640, 360), "--spp", spp,
                                 "--sampler", "sobol", "--aovs", "classes", "--lpe", extra)
        run.shared = (exrs, run.commands[before:])
    else:
        run.commands += run.shared[1]
        run.dirs.append("01-taxonomy")
    return run.shared[0]


def fig_taxonomy(run, fig_dir, out_png, title):
    exrs = taxonomy_renders(run, fig_dir)
    panels = [Panel(exrs["raycast"], "ray casting", "E(D|G)L"),
              Panel(exrs["whitted"], "Whitted ray tracing", "E S* (D|G) L"),
              Panel(exrs["path"], "path tracing", "E(D|G|S)*L")]
    compose(run, out_png, title, panels, cols=3, panel_w=600, panel_h=338)


def check_sum(exr, layers, tol=1e-4):
    """Fail unless the named AOV layers sum to the beauty in every pixel and channel.

    Why: the figure claims beauty = sum of the panels; the generator proves it on the very
    EXR the panels come from (relative tolerance, plus an absolute floor for dark pixels)."""
    import numpy as np
    import OpenImageIO as oiio
    buf = oiio.ImageBuf(str(exr))
    spec = buf.spec()
    pixels = buf.get_pixels(oiio.FLOAT)
    names = list(spec.channelnames)

    def layer(prefix):
        idx = [names.index(f"{prefix}{c}") for c in "RGB"]
        return pixels[..., idx].astype(np.float64)

    beauty = layer("")
    total = sum(layer(f"{l}.") for l in layers)
    err = np.abs(total - beauty) / np.maximum(np.abs(beauty), 1.0)
    worst = float(err.max())
    if not worst <= tol:
        raise FigureError(f"{exr}: {' + '.join(layers)} differs from the beauty by {worst:.3g} "
                          f"(relative, worst pixel) > {tol}: the decomposition figure would lie")
    return worst


def fig_decomposition(run, fig_dir, out_png, title):
    exrs = taxonomy_renders(run, fig_dir)
    panels, notes = [], []
    for integ, names in (("whitted", [n for n, _ in CLASSES[:4]]),
                         ("path", [n for n, _ in CLASSES])):
        worst = check_sum(exrs[integ], names)
        notes.append(f"{integ}: max relative |sum - beauty| = {worst:.2g}")
        panels.append(Panel(exrs[integ], f"{integ}: beauty", "= sum of this row"))
        panels += [Panel(exrs[integ], n, lpe, layer=n) for n, lpe in CLASSES if n in names]
        if integ == "whitted":
            panels.append(None)  # empty cell: Whitted has no indirect light
    panels = [p for p in panels]
    # Empty cell: a black panel would mislead, so draw the grid manually via a placeholder image.
    blank = fig_dir / "blank.png"
    sh(run, ["oiiotool", "--create", "16x9", "3", "--fill:color=" + BG, "16x9+0+0",
             "-d", "uint8", "-o", blank], record=False)
    panels = [p if p is not None else Panel(blank, "(no indirect)", "") for p in panels]
    compose(run, out_png, title, panels, cols=6, panel_w=296, panel_h=167, gap=16)
    return notes


def fig_szymczak(run, fig_dir, out_png, title):
    scene = REPO / "scenes/szymczak-one-light.toml"
    exr = render(run, fig_dir, "szymczak", scene, "--integrator", "raycast",
                 "--resolution", run.res(640, 480), "--spp", run.spp_direct,
                 "--lpe", "ambient=ED<L'ambient'>", "--lpe", "diffuse=ED<L'lamp'>",
                 "--lpe", "specular=EG<L'lamp'>", "--lpe", "background=EB")
    check_sum(exr, ["ambient", "diffuse", "specular", "background"])
    panels = [Panel(exr, "ambient  ka Ia", "ED<L'ambient'>", layer="ambient"),
              Panel(exr, "diffuse  kd (N.L) I/att", "ED<L'lamp'>", layer="diffuse"),
              Panel(exr, "specular  ks (H.N)^n I/att", "EG<L'lamp'>", layer="specular"),
              Panel(exr, "total", "beauty = sum of the three")]
    compose(run, out_png, title, panels, cols=4, panel_w=450, panel_h=338, gap=16)


def plot_exponent(run, png, exponents):
    """matplotlib: (H.N)^n = cos^n(angle) against the angle, one curve per n."""
    script = f"""
import math, matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
plt.rcParams.update({{"font.family": "DejaVu Sans", "font.size": 15}})
fig, ax = plt.subplots(figsize=(7.2, 6.4), dpi=100)
a = [i * 0.1 for i in range(0, 901)]
for n in {exponents!r}:
    ax.plot(a, [math.cos(math.radians(x)) ** n for x in a], lw=2.5, label=f"n = {{n}}")
ax.set_xlabel("angle between H and N (degrees)")
ax.set_ylabel("(H.N)^n")
ax.set_xlim(0, 90); ax.set_ylim(0, 1.02)
ax.grid(alpha=0.3); ax.legend()
fig.tight_layout()
fig.savefig({str(png)!r})
"""
    sh(run, ["/usr/bin/python3", "-c", script], record=False)
    run.commands.append("/usr/bin/python3 (matplotlib): plot cos(angle)^n, in make_figures.py plot_exponent")


def fig_exponent(run, fig_dir, out_png, title):
    exponents = [1, 10, 100, 1000]
    panels = []
    for n in exponents:
        scene = scene_variant(fig_dir, "exponent.toml", f"exponent-n{n}", n=n)
        exr = render(run, fig_dir, f"n{n}", scene, "--integrator", "raycast",
                     "--resolution", run.res(400, 300), "--spp", run.spp_direct)
        panels.append(Panel(exr, f"n = {n}", "E(D|G)L, ks (H.N)^n"))
    plot = fig_dir / "plot.png"
    plot_exponent(run, plot, exponents)
    panels.append(Panel(plot, "(H.N)^n against the angle"))
    # 2x2 renders on the left, the plot on the right: draw as a 3-column grid whose third
    # column holds the plot (row 1), leaving row 2's third cell out.
    order = [panels[0], panels[1], panels[4], panels[2], panels[3]]
    compose(run, out_png, title, order, cols=3, panel_w=480, panel_h=360, gap=30)


def fig_attenuation(run, fig_dir, out_png, title):
    # The nearest ball is about 2.5 from the lamp: intensities make it receive about 1.
    cases = [("1/d^2", "[0, 0, 1]", 6.0, "c2 = 1: physical"),
             ("1/(c1 d)", "[0, 1, 0]", 2.5, "c1 = 1: the lecture's compromise"),
             ("constant", "[1, 0, 0]", 1.0, "c0 = 1: no attenuation")]
    panels = []
    for i, (label, att, intensity, note) in enumerate(cases):
        scene = scene_variant(fig_dir, "attenuation.toml", f"attenuation-{i}",
                              intensity=intensity, attenuation=att)
        exr = render(run, fig_dir, f"attenuation-{i}", scene, "--integrator", "raycast",
                     "--resolution", run.res(640, 360), "--spp", run.spp_direct)
        panels.append(Panel(exr, f"{label}   [c0,c1,c2] = {att}", note))
    compose(run, out_png, title, panels, cols=3, panel_w=600, panel_h=338)


def shadow_scene(fig_dir, s):
    """The shadow scene with every length multiplied by s."""
    return scene_variant(fig_dir, "shadow.toml", f"shadow-scale-{s:g}", s=f"{s:g}",
                         eye_y=1.2 * s, eye_z=4.0 * s, look_y=0.3 * s, r=0.5 * s,
                         light_x=-6.0 * s, light_y=1.2 * s)


def fig_shadow(run, fig_dir, out_png, title):
    cases = [(1.0, ["--ray-offset", "none"], "no offset, scale 1", "ray-offset none: acne"),
             (1e3, ["--ray-offset", "epsilon", "--epsilon", "1e-4"], "epsilon 1e-4, scale 1e3",
              "too small for the scene: acne"),
             (2e-4, ["--ray-offset", "epsilon", "--epsilon", "1e-4"], "epsilon 1e-4, scale 2e-4",
              "too large: shadow rays skip the ball"),
             (1e3, [], "robust offset, scale 1e3", "error bound of the hit point (default)")]
    panels = []
    for i, (s, opts, label, note) in enumerate(cases):
        exr = render(run, fig_dir, f"shadow-{i}", shadow_scene(fig_dir, s), *opts,
                     "--resolution", run.res(640, 360), "--spp", run.spp_direct)
        panels.append(Panel(exr, label, note))
    compose(run, out_png, title, panels, cols=2, panel_w=640, panel_h=360, gap=30)


RAY_SPHERE_CASES = [
    # name, ray direction (from the origin), sphere centre, radius
    ("no hit", (1, 0.0, 0), (3, 1.6, 0), 1.0),
    ("tangent", (1, 0.0, 0), (3, 1.0, 0), 1.0),
    ("two hits", (1, 0.0, 0), (3, 0.0, 0), 1.0),
    ("origin inside", (1, 0.0, 0), (0.5, 0.0, 0), 1.5),
    ("sphere behind", (1, 0.0, 0), (-2.5, 0.0, 0), 1.0),
]


def explain_first_hit(run, fig_dir, i, direction, centre, r):
    """Ask the renderer (lightpath explain) whether the ray hits the ball, and the first hit's t."""
    scene = scene_variant(fig_dir, "ray-sphere.toml", f"case-{i}",
                          dir_x=direction[0], dir_y=direction[1], dir_z=direction[2],
                          cx=centre[0], cy=centre[1], cz=centre[2], r=r)
    outp = sh(run, [run.lightpath, "explain", scene, "--pixel", "0,0", "--integrator", "raycast",
                    "--lpe", "diffuse=ED<L'eye-lamp'>", "--lpe", "ambient=ED<L'ambient'>"],
              capture=True)
    hit = "'ball'" in outp or "touched: ball" in outp
    t = None
    for line in outp.splitlines():
        parts = line.split()
        if parts[:1] == ["diffuse"] and len(parts) >= 2:
            v = float(parts[1])
            t = 1.0 / v if v > 0 else None
    return hit, t


def fig_ray_sphere(run, fig_dir, out_png, title):
    results = []
    for i, (name, d, c, r) in enumerate(RAY_SPHERE_CASES):
        hit, t = explain_first_hit(run, fig_dir, i, d, c, r)
        results.append((name, d, c, r, hit, t))
    png = fig_dir / "diagram.png"
    script = f"""
import math, matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
plt.rcParams.update({{"font.family": "DejaVu Sans", "font.size": 14}})
cases = {results!r}
fig, axes = plt.subplots(1, len(cases), figsize=(18.4, 5.0), dpi=100)
for ax, (name, d, c, r, hit, t) in zip(axes, cases):
    ax.set_aspect("equal"); ax.set_xlim(-3.7, 5.2); ax.set_ylim(-2.2, 2.8); ax.axis("off")
    ax.add_patch(plt.Circle((c[0], c[1]), r, fill=False, lw=2.5, color="tab:blue"))
    ax.annotate("", xy=(5.0, 0), xytext=(0, 0), arrowprops=dict(arrowstyle="->", lw=2, color="k"))
    ax.plot([0], [0], "ko")
    # the second root, from the formula: t = f.d +- sqrt(r^2 - |f - (f.d)d|^2), f = c - o
    b = c[0]; h2 = r * r - c[1] * c[1]
    roots = [] if h2 < 0 else sorted({{b - math.sqrt(h2), b + math.sqrt(h2)}})
    for x in roots:
        if x > 0 and (t is None or abs(x - t) > 1e-3):
            ax.plot([x], [0], "o", ms=9, mfc="none", mec="gray", mew=2)
    if t is not None:
        ax.plot([t], [0], "o", ms=11, color="tab:red")
    verdict = ("hit, t = %.3f" % t) if (hit and t is not None) else ("hit" if hit else "miss")
    ax.set_title(name + "\\nlightpath: " + verdict, fontsize=16)
fig.tight_layout(rect=(0, 0.08, 1, 1))
fig.text(0.5, 0.03, "red: first hit reported by the renderer   grey ring: the other root of the quadratic",
         ha="center", fontsize=14)
fig.savefig({str(png)!r})
"""
    sh(run, ["/usr/bin/python3", "-c", script], record=False)
    run.commands.append("/usr/bin/python3 (matplotlib): draw the cases, in make_figures.py fig_ray_sphere")
    compose(run, out_png, title, [Panel(png, "one ray per case, from the dot to the right",
                                        "hit/miss and t from lightpath explain")],
            cols=1, panel_w=1800, panel_h=489)
    return [f"{n}: {'hit' if h else 'miss'}" + (f", t = {t:.4f}" if t else "")
            for n, _, _, _, h, t in results]


def fig_automaton(run, fig_dir, out_png, title):
    dot = fig_dir / "automaton.dot"
    png = fig_dir / "automaton.png"
    text_dot = sh(run, [run.lightpath, "lpe", "dot", "E(S*)(D|G)L"], capture=True)
    dot.write_text(text_dot)
    sh(run, ["dot", "-Tpng", "-Gdpi=200", "-Gfontname=DejaVu Sans", "-Nfontname=DejaVu Sans",
             "-Efontname=DejaVu Sans",
             "-o", png, dot])
    compose(run, out_png, title, [Panel(png, "E(S*)(D|G)L, minimised", "lightpath lpe dot | dot -Tpng")],
            cols=1, panel_w=1700, panel_h=760)


def fig_bench(run, fig_dir, out_png, title):
    csv, png = fig_dir / "bench-error.csv", fig_dir / "bench-error.png"
    # The full benchmark renders a 4096-spp reference; both modes use --quick (closed-form
    # scenes, budgets up to 32 spp) so that the figures stay within minutes.
    sh(run, [run.lightpath, "bench", "error", "--quick", "--csv", csv, "--plot", png,
             "--cache", fig_dir / "cache"])
    compose(run, out_png, title, [Panel(png, "RMSE against CPU seconds (log-log)", "lightpath bench error --quick")],
            cols=1, panel_w=1500, panel_h=800)


def fig_light_groups(run, fig_dir, out_png, title):
    scene = REPO / "scenes/szymczak-three-lights.toml"
    groups = [("red", "red-lamp"), ("green", "green-lamp"), ("blue", "blue-lamp"),
              ("ambient", "ambient")]
    exr = render(run, fig_dir, "groups", scene, "--resolution", run.res(640, 480),
                 "--spp", run.spp_direct,
                 *sum((["--lpe", f"{n}=E.*<L'{l}'>"] for n, l in groups), []),
                 "--lpe", "background=E.*B")
    check_sum(exr, [n for n, _ in groups] + ["background"])
    panels = [Panel(exr, "beauty", "= sum of the groups")]
    panels += [Panel(exr, n, f"E.*<L'{l}'>", layer=n) for n, l in groups]
    compose(run, out_png, title, panels, cols=3, panel_w=480, panel_h=360, gap=30)


def fig_ambient(run, fig_dir, out_png, title):
    exrs = taxonomy_renders(run, fig_dir)
    w, p = exrs["whitted"], exrs["path"]
    panels = [Panel(w, "Whitted: beauty", "E S* (D|G) L"),
              Panel(p, "path tracer: beauty", "E(D|G|S)*L"),
              Panel(w, "ambient term", "ES*D<L'ambient'>", layer="ambient"),
              Panel(p, "what it stands for", "ES*D(D|G|S)+L", layer="bounced")]
    compose(run, out_png, title, panels, cols=2, panel_w=640, panel_h=360, gap=30, top=90)


FIGURES = {
    "01-taxonomy": fig_taxonomy, "02-decomposition": fig_decomposition,
    "03-szymczak": fig_szymczak, "04-exponent": fig_exponent, "05-attenuation": fig_attenuation,
    "06-shadow-acne": fig_shadow, "07-ray-sphere": fig_ray_sphere, "08-automaton": fig_automaton,
    "09-run-time-error": fig_bench, "10-light-groups": fig_light_groups, "11-ambient": fig_ambient,
}


# ----------------------------------------------------------------------------------------------
# Gallery

def write_gallery(run, made):
    """index.html: every figure with its caption, scene and the exact commands that made it.

    The page checks its own images on load (naturalWidth > 0) and writes the verdict into
    #status, which test_gallery.py reads from headless Chromium."""
    items = []
    for fig, png, commands, notes, seconds, dirs in made:
        cmds = "\n".join(html.escape(c) for c in commands)
        links = ", ".join(f'<a href="{d}/"><code>{d}/</code></a>' for d in dirs)
        where = f"EXRs it came from in {links}" if dirs else f'files in <a href="{fig["id"]}/"><code>{fig["id"]}/</code></a>'
        note = "".join(f"<li>{html.escape(n)}</li>" for n in notes)
        items.append(f"""
<section id="{fig['id']}">
  <h2>{html.escape(fig['id'][:2])}. {html.escape(fig['title'])}</h2>
  <a href="{png}"><img src="{png}" alt="{html.escape(fig['title'])}" width="960" height="540"></a>
  <p class="caption">{html.escape(fig['caption'])}</p>
  <p class="scene">Scene: <code>{html.escape(fig['scene'] or '(none)')}</code>;
     {where}; made in {seconds:.1f} s.</p>
  {f'<ul class="notes">{note}</ul>' if note else ''}
  <details><summary>Commands</summary><pre>{cmds}</pre></details>
</section>""")
    mode = "--quick" if run.quick else "default quality"
    page = f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>lightpath lecture figures</title>
<style>
body {{ font-family: "DejaVu Sans", sans-serif; max-width: 1000px; margin: 2em auto; color: #222; }}
img {{ max-width: 100%; height: auto; border: 1px solid #ccc; }}
pre {{ background: #f4f4f4; padding: 0.6em; overflow-x: auto; font-size: 12px; }}
.caption {{ font-size: 1.05em; }} .scene, .notes {{ color: #555; font-size: 0.9em; }}
</style>
<script>
// Errors the page sees (failed image loads, script errors, console.error) go into #status,
// which test_gallery.py reads from headless Chromium.
window.galleryErrors = [];
window.addEventListener("error", e => window.galleryErrors.push(
    e.message || ("failed to load " + (e.target && (e.target.src || e.target.href)))), true);
const consoleError = console.error;
console.error = (...a) => {{ window.galleryErrors.push(a.join(" ")); consoleError(...a); }};
</script></head><body>
<h1>lightpath lecture figures</h1>
<p>Generated by <code>cmake --build build --target figures</code> ({mode}) with
<code>lectures/make_figures.py</code>: fixed seeds and samples, the same images on every run (but for figure 9, which plots measured times).
Each figure is a 1920x1080 PNG; the EXRs it came from are in its folder.</p>
<p id="status">checking images...</p>
{''.join(items)}
<script>
window.addEventListener("load", () => {{
  const imgs = Array.from(document.images);
  const bad = imgs.filter(i => !i.complete || i.naturalWidth === 0).map(i => i.getAttribute("src"));
  const errs = window.galleryErrors;
  document.getElementById("status").textContent =
      bad.length > 0 ? "images broken: " + bad.join(" ")
      : errs.length > 0 ? "errors: " + errs.join("; ") : "images ok: " + imgs.length;
}});
</script>
</body></html>
"""
    (run.out / "index.html").write_text(page)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lightpath", required=True, help="the built lightpath binary")
    ap.add_argument("--out", required=True, help="output folder (the build tree's lectures/)")
    ap.add_argument("--quick", action="store_true", help="small and few samples: CI, under a minute")
    ap.add_argument("--only", nargs="*", help="figure ids to make (default: all)")
    a = ap.parse_args()

    for tool in ("oiiotool", "dot"):
        if shutil.which(tool) is None:
            sys.exit(f"make_figures: '{tool}' not found; run scripts/setup (it installs the packages)")
    if not Path(a.lightpath).is_file():
        sys.exit(f"make_figures: no lightpath binary at {a.lightpath}")

    run = Run(a.lightpath, a.out, a.quick)
    run.out.mkdir(parents=True, exist_ok=True)
    figures = tomllib.loads((HERE / "figures.toml").read_text())["figure"]
    made = []
    start = time.monotonic()
    for fig in figures:
        if a.only and fig["id"] not in a.only:
            continue
        t0 = time.monotonic()
        fig_dir = run.out / fig["id"]
        fig_dir.mkdir(parents=True, exist_ok=True)
        png = f"{fig['id']}.png"
        run.commands, run.dirs = [], []
        try:
            notes = FIGURES[fig["id"]](run, fig_dir, run.out / png, fig["title"]) or []
        except FigureError as e:
            sys.exit(f"make_figures: figure {fig['id']}: {e}")
        seconds = time.monotonic() - t0
        made.append((fig, png, list(run.commands), notes, seconds, sorted(set(run.dirs))))
        print(f"figure {fig['id']:20s} {seconds:6.1f} s  {run.out / png}", flush=True)
    write_gallery(run, made)
    print(f"gallery {run.out / 'index.html'}  ({time.monotonic() - start:.1f} s in all)")


if __name__ == "__main__":
    main()
