"""The steps every figure takes: running a command (recorded for the gallery), rendering a scene
with the lightpath CLI, asking `explain --json`, and writing a scene from a template."""

import json
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

    def __init__(self, lightpath, out, quick):
        self.lightpath = str(Path(lightpath).resolve())
        self.out = Path(out).resolve()
        self.quick = quick
        # Quality: the default is for slides, --quick for CI (2 loaded cores, ctest's 300 s).
        self.scale = 0.5 if quick else 1.0
        self.spp_direct = 1 if quick else 4      # raycast / Whitted (soft shadows of the area light)
        self.spp_path = 4 if quick else 64       # path tracer and bdpt
        self.patches = 1024 if quick else 4096   # radiosity's patch budget
        self.spp_caustic = 16 if quick else 256  # bdpt on the caustics slide: a converged focus
        self.commands = []                       # commands of the figure being made
        self.dirs = []                           # folders holding the figure's EXRs
        self.rendered = {}                       # argv -> EXR, so figures share renders
        self.seconds = defaultdict(float)        # wall seconds per tool ("lightpath render", ...)

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


def sh(run, argv, record=True, capture=False):
    """Run one command; on failure raise FigureError with its output. Recorded for the gallery."""
    argv = [str(a) for a in argv]
    if record:
        run.commands.append(run.shown(argv))
    t0 = time.monotonic()
    proc = subprocess.run(argv, capture_output=True, text=True)
    tool = Path(argv[0]).name + (" " + argv[1] if argv[0] == run.lightpath else "")
    run.seconds[tool] += time.monotonic() - t0
    if proc.returncode != 0:
        raise FigureError(f"command failed (exit {proc.returncode}): {shlex.join(argv)}\n"
                          f"{proc.stdout[-2000:]}{proc.stderr[-2000:]}")
    return proc.stdout if capture else None


def render(run, folder, name, scene, *options):
    """Render scene into out/folder/name.exr (seed 1, --quiet); return the EXR path.

    The same command is run once per generator run: a figure that needs a render another figure
    made reuses its EXR and lists the same command in the gallery."""
    directory = run.out / folder
    directory.mkdir(parents=True, exist_ok=True)
    exr = directory / f"{name}.exr"
    argv = [run.lightpath, "render", str(scene), "-o", str(exr), "--seed", "1", "--quiet",
            *[str(o) for o in options]]
    run.dirs.append(folder)
    key = tuple(argv)
    if key in run.rendered:
        run.commands.append(run.shown(argv))
        return exr
    sh(run, argv)
    run.rendered[key] = exr
    return exr


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
