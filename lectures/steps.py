"""The steps every figure takes: running a command (recorded for the gallery), rendering a scene
with the lightpath CLI, asking `explain --json`, and writing a scene from a template."""

import fcntl
import hashlib
import json
import os
import re
import shlex
import string
import subprocess
import time
from collections import defaultdict
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent


class FigureError(RuntimeError):
    """A step or a check of a figure failed: the message says which and why."""


def shell_word(arg):
    """arg as one shell word a reader can paste: bare when safe, else in double quotes when
    nothing inside them is special to the shell, else in single quotes (shlex)."""
    if re.fullmatch(r"[A-Za-z0-9_@%+=:,./-]+", arg):
        return arg
    if not re.search(r'["$`\\!]', arg):
        return f'"{arg}"'
    return shlex.quote(arg)


class Run:
    """Settings of one generator run, the renders made so far, and the log of the commands the
    figure being made used (for the gallery)."""

    def __init__(self, lightpath, out, quick, threads=0):
        self.lightpath = str(Path(lightpath).resolve())
        self.out = Path(out).resolve()
        self.quick = quick
        # Quality: the default is for slides, --quick for CI (2 loaded cores, ctest's 300 s).
        self.scale = 0.5 if quick else 1.0
        # raycast / Whitted: one sample at the pixel centre for CI; anti-aliased (and smooth soft
        # shadows of the area light) for slides
        self.spp_direct = 1 if quick else 16
        self.spp_path = 4 if quick else 64       # the fog slide's path tracer
        # Renders held to NOISE_LEVEL get the samples their measured error asks for, with a
        # margin (error ~ 1/sqrt(spp): predicted = measured * sqrt(old / new)); a panel is
        # not better for noise far below the level, only slower.
        # The taxonomy's path tracer (slides 2, 3, 11): the glass ball under the quad light makes
        # caustic fireflies, 60% of its squared error in 1% of the pixels; at 64 spp its relative
        # RMSE was 0.244, at 512 0.077 (128: 0.184 measured, 0.189 predicted), 448: 0.084, 384:
        # 0.092. The renders are deterministic (the same numbers on any machine and thread count),
        # so a measured error under its level stays under it until the renderer changes, when the
        # generator's check says so.
        self.spp_path_taxonomy = 4 if quick else 384
        self.spp_decomposition = 4 if quick else 40   # path: 0.075 at 48 spp, so ~0.082
        self.spp_bounces = 4 if quick else 28         # path: 0.081 at 32 spp, so ~0.087
        # Radiosity's image is its solve seen through the pixel samples, each of which samples the
        # direct light and gathers the later bounces (the final gather): at 4 spp 0.025
        # (taxonomy) and 0.052 (bounce by bounce) against the level 0.1.
        self.spp_radiosity = 1 if quick else 4
        # bdpt's taxonomy render, whose caustic AOV alone is shown (recipes.BDPT_TAXONOMY_LEVEL):
        # its beauty's fireflies are the caustics seen in and through the balls (E S+ D S+ L), which
        # only the eye's walk finds. With light walks aimed at the balls (lights/emission_guide.h)
        # the pilot took 1 walk per sample at this seed (0.30-0.31 at 16 spp, 20 CPU s); taking the
        # fewest walks within one standard error of the best (integrators/bdpt_allocation.h) it
        # takes 1/16, the most efficient here: 0.38 at 16 spp, 0.345 at 20, 0.307 at 24 (10.8 CPU s).
        self.spp_bdpt_taxonomy = 1 if quick else 24
        self.patches = 1024 if quick else 8192   # radiosity's patch budget (at full quality the default)
        # The caustics slide: bdpt's beauty against its 1024-spp reference, and over the caustic's
        # brightest 1% of pixels (the zoomed panels): 0.063 and 0.082 at 128 spp (94.5 CPU s) while
        # light walks left the lamp uniformly, one in 200 through the ball; with half of them
        # aimed at it, 0.038 and 0.044 at 32 (15.5 CPU s; the reference's own noise is in both),
        # so 16: ~0.054 and ~0.062, under the level with margin at half the time.
        # The path tracer's beauty (no caustic to find) 0.010 at 64, so 16: ~0.020 (at 8 the gold
        # ball's speckles in the zoomed shadow distract from the missing caustic).
        self.spp_caustic = 16
        self.spp_caustic_path = 4 if quick else 16
        self.passes_sppm = 4 if quick else 32    # sppm's photon passes (mirror-caustic-sppm)
        self.commands = []                       # commands of the figure being made
        self.dirs = []                           # folders holding the figure's EXRs
        self.rendered = {}                       # argv -> EXR, so figures share renders
        # Each render's --threads (0: all cores): the generator's job pool runs several figures
        # at once, each render on its share of the cores. Not part of the command the gallery
        # shows or of a reference's cache key: a render is the same on any number of threads.
        self.threads = threads
        # This generator run, for renders shared between its worker processes (shared_render)
        self.token = f"{os.getpid()}-{time.time_ns()}"
        self.measured = {}                       # EXR -> (level, why, noise): kept across figures
        self.seconds = defaultdict(float)        # wall seconds per tool ("lightpath render", ...)
        self.noise = {}                          # EXR -> its relative RMSE (measure_noise)
        self.levels = {}                         # EXR -> (its level, why) (render's noise_level)
        self.reference_seconds = 0.0             # wall seconds spent rendering noise references
        self.reference_cpu = 0.0                 # and their CPU seconds
        self.last_cpu = 0.0                      # CPU seconds of the last command sh ran
        self.references_made = self.references_cached = 0

    def res(self, w, h):
        """A render resolution, halved in quick mode."""
        return f"{int(w * self.scale)}x{int(h * self.scale)}"

    def res_for(self, aspect, h=360):
        """A render resolution h pixels high (halved in quick mode) of width/height = aspect:
        the aspect of the cells a slide's layout gives its panels (slide.cell_aspect)."""
        return self.res(round(h * aspect), h)

    def rel(self, path):
        """A path as the gallery shows it: relative to the repository's root when inside it."""
        p = Path(path).resolve()
        try:
            return str(p.relative_to(REPO))
        except ValueError:
            return str(p)

    def shown(self, argv):
        """A command line as the gallery prints it: paths relative to the repository's root
        (build/lightpath, scenes/..., build/lectures/...), each word quoted to paste as it is
        in a shell at the root."""
        return " ".join(shell_word(self.rel(a) if a.startswith("/") else a) for a in argv)


def children_cpu():
    """CPU seconds (user + system) of every finished child process so far: a machine shared with
    other work slows the wall clock, not this."""
    import resource
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def sh(run, argv, record=True, capture=False):
    """Run one command; on failure raise FigureError with its output. Recorded for the gallery."""
    argv = [str(a) for a in argv]
    if record:
        run.commands.append(run.shown(argv))
    t0, cpu0 = time.monotonic(), children_cpu()
    proc = subprocess.run(argv, capture_output=True, text=True)
    tool = Path(argv[0]).name + (" " + argv[1] if argv[0] == run.lightpath else "")
    run.seconds[tool] += time.monotonic() - t0
    run.last_cpu = children_cpu() - cpu0
    if proc.returncode != 0:
        raise FigureError(f"command failed (exit {proc.returncode}): {shlex.join(argv)}\n"
                          f"{proc.stdout[-2000:]}{proc.stderr[-2000:]}")
    return proc.stdout if capture else None


def render(run, folder, name, scene, *options, noise_level=None, noise_why=""):
    """Render scene into out/folder/name.exr (seed 1, --quiet); return the EXR path.

    The same command is run once per generator run: a figure that needs a render another figure
    made reuses its EXR and lists the same command in the gallery, in whichever of the
    generator's worker processes it was made (shared_render).

    At the default quality a path, bdpt or radiosity render is held to NOISE_LEVEL
    (measure_noise), or to noise_level when the recipe states another and says why (noise_why):
    a level above NOISE_LEVEL for a panel whose lesson is its noise, or float("inf") for renders
    that are measurements themselves (the run-time plot's budgets)."""
    if noise_level is not None and not noise_why:
        raise FigureError(f"render {folder}/{name}: a noise level of its own needs a reason")
    directory = run.out / folder
    directory.mkdir(parents=True, exist_ok=True)
    exr = directory / f"{name}.exr"
    argv = [run.lightpath, "render", str(scene), "-o", str(exr), "--seed", "1", "--quiet",
            *[str(o) for o in options]]
    run.dirs.append(folder)
    run.commands.append(run.shown(argv))
    key = tuple(argv)
    if key not in run.rendered:
        level = (NOISE_LEVEL if noise_level is None else noise_level, noise_why)
        with shared_render(run, argv) as share:
            done = share.done
            if done is None:
                sh(run, with_threads(run, argv), record=False)
                cpu = run.last_cpu
                noise = None
                if not run.quick and level[0] != float("inf"):
                    noise = measure_noise(run, argv, exr)
                done = {"level": level, "noise": noise}
                share.record(done)
                if not run.quick:
                    spp = argv[argv.index("--spp") + 1] if "--spp" in argv else "1"
                    verdict = ("" if noise is None else
                               f", relative RMSE {noise:.3f} against {NOISE_REFERENCE_FACTOR}x "
                               f"its samples (level {level[0]})" +
                               ("" if noise <= level[0] else "  ABOVE its level"))
                    print(f"  render {run.rel(exr)}: {spp} spp, {cpu:.1f} CPU s{verdict}",
                          flush=True)
        run.rendered[key] = exr
        run.measured[exr] = (tuple(done["level"]), done["noise"])
    # this figure's account of the render, whichever figure or worker made it
    level, noise = run.measured[exr]
    run.levels[exr] = level
    if noise is not None:
        run.noise[exr] = noise
    return exr


def with_threads(run, argv):
    """argv as run: with the run's --threads unless it sets its own."""
    if run.threads and "--threads" not in argv:
        return [*argv, "--threads", str(run.threads)]
    return argv


class shared_render:
    """The one render of a command in this generator run, among its worker processes: entered
    under a lock of the command, its `done` is None when this process is to render it (and
    record what it measured), or what the worker that rendered it recorded."""

    def __init__(self, run, argv):
        folder = run.out / ".renders"
        folder.mkdir(parents=True, exist_ok=True)
        key = hashlib.sha256("\0".join(argv).encode()).hexdigest()[:16]
        self.lock_path, self.done_path = folder / f"{key}.lock", folder / f"{key}.json"
        self.token, self.done = run.token, None

    def __enter__(self):
        self.lock = open(self.lock_path, "w")
        fcntl.flock(self.lock, fcntl.LOCK_EX)
        try:
            recorded = json.loads(self.done_path.read_text())
            if recorded.get("token") == self.token:
                self.done = recorded["result"]
        except (OSError, ValueError):
            pass
        return self

    def record(self, result):
        self.done_path.write_text(json.dumps({"token": self.token, "result": result}))

    def __exit__(self, *exc):
        self.lock.close()
        return False


# The quality level of the default figures: every path-traced, bdpt and radiosity render's
# relative RMSE against a reference at NOISE_REFERENCE_FACTOR times its samples (another seed,
# cached between runs in out/references/) is measured and printed; NOISE_LEVEL is the level every
# slide's render must meet unless its recipe states another (render's noise_level, with why). A
# render above its level is flagged in the gallery and the run's summary, and the run fails
# (noise_above; make_figures.py exits 1).
NOISY_INTEGRATORS = ("path", "bdpt", "radiosity")
NOISE_REFERENCE_FACTOR = 4
NOISE_LEVEL = 0.1


def relative_rmse(exr, reference, name=""):
    """sqrt(mean((image - reference)^2)) / mean(reference), over the pixels and channels of the
    beauty (or of the layer name: a render without a beauty, --no-beauty, is measured on the
    AOV its panel shows). Against an independent reference with k times the samples the noise
    of both counts: this overstates the image's own error by sqrt(1 + 1/k)."""
    import numpy as np
    from checks import layer, read_layer
    a, b = layer(exr, name), read_layer(reference, name)
    return float(np.sqrt(((a - b) ** 2).mean()) / max(float(b.mean()), 1e-9))


def noise_layer(options):
    """The layer a render's noise is measured on: the beauty, or for a --no-beauty render its
    first --lpe's AOV (the one its panel shows)."""
    if "--no-beauty" not in options:
        return ""
    return options[options.index("--lpe") + 1].split("=", 1)[0]


def reference_key(argv, scene):
    """A cached reference's name: its command after the binary (so a reference serves the same
    command from any build tree, as it already serves a rebuilt binary at the same path) and the
    scene's text."""
    return hashlib.sha256("\0".join([*argv[1:], Path(scene).read_text()]).encode()).hexdigest()[:16]


def measure_noise(run, argv, exr):
    """The render's relative RMSE against its cached higher-spp reference, as against one at
    NOISE_REFERENCE_FACTOR times its samples (reference_noise), or None for a render that is
    not of a noisy integrator.

    The cache holds references by command (its --spp aside) and scene text; any with at least
    NOISE_REFERENCE_FACTOR times the render's samples serves (the one with the most), so that
    lowering a render's samples needs no new reference; a missing one is made at that factor."""
    options = argv[argv.index("--quiet") + 1:]
    get = lambda flag: options[options.index(flag) + 1] if flag in options else None  # noqa: E731
    if get("--integrator") not in NOISY_INTEGRATORS or get("--spp") is None:
        return None
    spp = int(get("--spp"))
    ref_options = list(options)
    ref_options[ref_options.index("--spp") + 1] = "*"
    ref_argv = [argv[0], "render", argv[2], "--seed", "2", "--quiet", *ref_options]
    key = reference_key(ref_argv, argv[2])
    folder = run.out / "references"
    folder.mkdir(parents=True, exist_ok=True)
    cached = [int(m.group(1)) for f in folder.glob(f"{key}-*spp.exr")
              if (m := re.fullmatch(rf"{key}-(\d+)spp\.exr", f.name))]
    ref_spp = max(cached, default=0)
    if ref_spp >= spp * NOISE_REFERENCE_FACTOR:
        run.references_cached += 1
    else:
        ref_spp = spp * NOISE_REFERENCE_FACTOR
        ref_argv[ref_argv.index("*")] = str(ref_spp)
        t0 = time.monotonic()
        sh(run, with_threads(run, ref_argv[:3] + ["-o", str(folder / f"{key}-{ref_spp}spp.exr")] +
                             ref_argv[3:]), record=False)
        run.reference_seconds += time.monotonic() - t0
        run.reference_cpu += run.last_cpu
        run.references_made += 1
    measured = relative_rmse(exr, folder / f"{key}-{ref_spp}spp.exr", noise_layer(options))
    return reference_noise(measured, ref_spp / spp)


def reference_noise(measured, k):
    """A relative RMSE measured against an independent reference with k times the samples, as
    it would be against one with NOISE_REFERENCE_FACTOR times: both images' noise counts, the
    reference's variance 1/k of the render's, so measured^2 = e^2 (1 + 1/k) for the render's
    own error e, and the level is on e^2 (1 + 1/NOISE_REFERENCE_FACTOR)."""
    return measured * ((1 + 1 / NOISE_REFERENCE_FACTOR) / (1 + 1 / k)) ** 0.5


def cached_render(run, scene, *options):
    """A render of scene (seed 2, --quiet) that is the same in every run, a converged reference:
    cached in out/references/ by command and scene text, made when missing. Returns its path."""
    argv = [run.lightpath, "render", str(scene), "--seed", "2", "--quiet", *[str(o) for o in options]]
    key = reference_key(argv, scene)
    path = run.out / "references" / f"{key}.exr"
    path.parent.mkdir(parents=True, exist_ok=True)
    run.commands.append(run.shown(argv[:3] + ["-o", str(path)] + argv[3:]))
    with shared_render(run, argv):
        if not path.is_file():
            sh(run, with_threads(run, argv[:3] + ["-o", str(path)] + argv[3:]), record=False)
    return path


def explain(run, scene, x, y, *options):
    """`lightpath explain --json` of one pixel, parsed (schema lightpath-explain-1, docs/lpe.md)."""
    out = sh(run, [run.lightpath, "explain", str(scene), "--pixel", f"{x},{y}", "--json",
                   *[str(o) for o in options]], capture=True)
    doc = json.loads(out)
    if doc.get("schema") != "lightpath-explain-1":
        raise FigureError(f"explain {scene}: schema {doc.get('schema')!r}, "
                          "expected 'lightpath-explain-1'")
    return doc


def scene_variant(directory, template, name, **values):
    """Write a scene from a template in lectures/scenes with its $placeholders filled in."""
    text = string.Template((HERE / "scenes" / template).read_text()).substitute(
        {k: str(v) for k, v in values.items()})
    path = Path(directory) / f"{name}.toml"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def noise_above(noise, levels):
    """[(EXR, its relative RMSE, its level)] of every measured render above its level: the
    renders that fail the default quality."""
    return [(exr, n, levels[exr][0]) for exr, n in sorted(noise.items()) if not n <= levels[exr][0]]
