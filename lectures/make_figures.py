#!/usr/bin/python3
"""Regenerate every lecture figure of lightpath, the gallery page and the PDF of all slides.

    /usr/bin/python3 lectures/make_figures.py --lightpath build/lightpath --out build/lectures [--quick]

lectures/figures.toml lists the figures in slide order (id, title, caption, recipe, scenes). For
each, the function named by `recipe` in recipes.py renders the scenes with the real renderer
(fixed seeds and samples), checks on the EXRs what the slide claims, and composes the slide
(slide.py) as NN-id.png, NN its place in the list. gallery.py writes index.html; slides.pdf holds
every slide in order. Any failing step or check stops the run with a message naming the figure
and a non-zero exit code.
"""

import argparse
import json
import multiprocessing
import os
import shutil
import sys
import time
import tomllib
from collections import defaultdict
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import gallery  # noqa: E402  (the modules beside this script)
import recipes  # noqa: E402
import slide  # noqa: E402
import steps  # noqa: E402
from steps import HERE, REPO, FigureError, Run  # noqa: E402

FIGURES_TOML = HERE / "figures.toml"
PDF_NAME = "slides.pdf"
REQUIRED_KEYS = ("id", "title", "caption", "recipe", "scenes")


def load_figures(path=FIGURES_TOML):
    """The figure list, checked: every key present, ids unique, each recipe a function."""
    figures = tomllib.loads(path.read_text())["figure"]
    seen = set()
    for i, f in enumerate(figures, 1):
        missing = [k for k in REQUIRED_KEYS if k not in f]
        if missing:
            raise FigureError(f"{path}: figure {i} has no {', '.join(missing)}")
        if f["id"] in seen:
            raise FigureError(f"{path}: figure id '{f['id']}' appears twice")
        seen.add(f["id"])
        if not callable(getattr(recipes, f["recipe"], None)):
            raise FigureError(f"{path}: figure '{f['id']}': no recipe '{f['recipe']}' in recipes.py")
        for s in f["scenes"]:
            if not (REPO / s).is_file():
                raise FigureError(f"{path}: figure '{f['id']}': no scene {s}")
    return figures


class Figure:
    """One figure being made: its entry of figures.toml, its folder, and what the gallery shows."""

    def __init__(self, run, number, entry):
        self.run, self.number = run, number
        self.id, self.title, self.caption = entry["id"], entry["title"], entry["caption"]
        self.recipe, self.scenes = entry["recipe"], list(entry["scenes"])
        self.dir = run.out / self.id
        self.png = run.out / f"{number:02d}-{self.id}.png"
        self.commands, self.notes, self.dirs, self.seconds = [], [], [], 0.0
        self.layout_note = ""
        self.alarms = []  # renders above their noise level: flagged in the gallery, fail the run

    def scene(self, i):
        """The i-th scene of figures.toml, as a path."""
        return REPO / self.scenes[i]

    def note_command(self, text):
        """A step that is no command (a plot drawn in Python), listed in the gallery."""
        self.run.commands.append(text)

    def compose(self, panels, cols=None, aspect=None, side=None, grid_w=None):
        """This figure's slide: its title over the panels (slide.compose)."""
        empty = slide.compose(self.png, self.title, panels, cols=cols, aspect=aspect,
                              side=side, grid_w=grid_w)
        flagged = [f"'{p.label}' ({p.dark})" for p in [*panels, side] if p is not None and p.dark]
        self.layout_note = (f"layout: {empty:.1%} of the frame empty (bar {slide.MAX_EMPTY:.0%}); "
                            f"no panel's lit pixels darker than {slide.DARK_FLOOR} mean display "
                            "luminance unless its exposure is stated" +
                            (f"; dark on purpose: {', '.join(flagged)}" if flagged else ""))

    def make(self):
        self.dir.mkdir(parents=True, exist_ok=True)
        self.run.commands, self.run.dirs = [], []
        t0, cpu0 = time.monotonic(), steps.children_cpu() + sum(os.times()[:2])
        self.notes = getattr(recipes, self.recipe)(self) or []
        self.notes.append(self.layout_note)
        self.seconds = time.monotonic() - t0
        self.cpu = steps.children_cpu() + sum(os.times()[:2]) - cpu0
        if not self.png.is_file():
            raise FigureError(f"recipe {self.recipe} wrote no slide")
        self.commands = list(self.run.commands)
        self.dirs = sorted(set(self.run.dirs))
        for exr, noise in sorted(self.run.noise.items()):
            if exr.parent.name in self.dirs:
                level, why = self.run.levels[exr]
                self.notes.append(f"noise: {exr.parent.name}/{exr.name} relative RMSE {noise:.3f} "
                                  f"against {steps.NOISE_REFERENCE_FACTOR}x its samples (level "
                                  f"{level}{': ' + why if why else ''})")
                if not noise <= level:
                    self.alarms.append(f"{exr.parent.name}/{exr.name}: relative RMSE {noise:.3f} "
                                       f"is ABOVE its level {level}")
        for exr, (level, why) in sorted(self.run.levels.items()):
            if exr.parent.name in self.dirs and level == float("inf"):
                self.notes.append(f"noise: {exr.parent.name}/{exr.name} not held to a level: {why}")


# The generator run a worker process makes its figures in (make_figure): set before the pool's
# processes are forked, so each inherits it.
RUN = None
TIMES_NAME = "figure-cpu.json"  # each figure's CPU seconds last run: the pool's order next run


def make_figure(number, entry):
    """Make one figure in this (worker) process; return what the parent needs of it: the
    Figure's attributes and the run's accounts of its renders, references and tools."""
    run = RUN
    run.noise, run.levels, run.seconds = {}, {}, defaultdict(float)
    run.reference_seconds = run.reference_cpu = 0.0
    run.references_made = run.references_cached = 0
    fig = Figure(run, number, entry)
    fig.make()
    account = {k: getattr(run, k) for k in ("noise", "levels", "seconds", "reference_seconds",
                                            "reference_cpu", "references_made",
                                            "references_cached")}
    return {k: v for k, v in vars(fig).items() if k != "run"}, account


def make_all(run, todo, jobs):
    """Make the figures todo [(number, entry)] on a pool of jobs worker processes, the longest
    first (by last run's CPU seconds); yield each Figure as it is done. A figure's slide and
    files are the same whatever the order: each writes only its own folder, and a render two
    figures share is made once (steps.shared_render)."""
    global RUN
    RUN = run
    shutil.rmtree(run.out / ".renders", ignore_errors=True)  # the last run's locks and records
    times_path = run.out / TIMES_NAME
    try:
        last = json.loads(times_path.read_text()).get("quick" if run.quick else "default", {})
    except (OSError, ValueError):
        last = {}
    order = sorted(todo, key=lambda ne: -last.get(ne[1]["id"], 0.0))

    def adopt(number, entry, result):
        attributes, account = result
        fig = Figure(run, number, entry)
        vars(fig).update(attributes)
        return fig, account

    if jobs <= 1:
        for number, entry in order:
            try:
                result = make_figure(number, entry)
            except FigureError as e:
                raise FigureError(f"figure {entry['id']}: {e}") from e
            yield adopt(number, entry, result)
        return
    pool = ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context("fork"))
    try:
        futures = {pool.submit(make_figure, number, entry): (number, entry)
                   for number, entry in order}
        for future in as_completed(futures):
            number, entry = futures[future]
            try:
                result = future.result()
            except FigureError as e:
                raise FigureError(f"figure {entry['id']}: {e}") from e
            yield adopt(number, entry, result)
    finally:
        pool.shutdown(wait=True, cancel_futures=True)


def add_account(totals, account):
    """Add one figure's accounts (make_figure) to the run's totals, a dict of the same keys."""
    totals["noise"].update(account["noise"])
    totals["levels"].update(account["levels"])
    for tool, seconds in account["seconds"].items():
        totals["seconds"][tool] = totals["seconds"].get(tool, 0.0) + seconds
    for k in ("reference_seconds", "reference_cpu", "references_made", "references_cached"):
        totals[k] += account[k]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lightpath", required=True, help="the built lightpath binary")
    ap.add_argument("--out", required=True, help="output folder (the build tree's lectures/)")
    ap.add_argument("--quick", action="store_true", help="small and few samples: CI")
    ap.add_argument("--only", nargs="*", help="figure ids to make (default: all; no PDF then)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                    help="figures made at once, each render on cores/jobs threads "
                    "(default: the number of cores; 1: one at a time, each on all cores)")
    a = ap.parse_args()

    for tool in ("dot",):
        if shutil.which(tool) is None:
            sys.exit(f"make_figures: '{tool}' not found; run scripts/setup (it installs the packages)")
    if not Path(a.lightpath).is_file():
        sys.exit(f"make_figures: no lightpath binary at {a.lightpath}")

    cores = os.cpu_count() or 1
    run = Run(a.lightpath, a.out, a.quick, threads=0 if a.jobs <= 1 else max(1, cores // a.jobs))
    run.out.mkdir(parents=True, exist_ok=True)
    try:
        entries = load_figures()
    except FigureError as e:
        sys.exit(f"make_figures: {e}")
    unknown = set(a.only or []) - {e["id"] for e in entries}
    if unknown:
        sys.exit(f"make_figures: --only: no figure {', '.join(sorted(unknown))} in {FIGURES_TOML}")
    todo = [(n, e) for n, e in enumerate(entries, 1) if not a.only or e["id"] in a.only]
    made = []
    start = time.monotonic()
    cpu_start = steps.children_cpu() + sum(os.times()[:2])
    totals = {"noise": {}, "levels": {}, "seconds": {}, "reference_seconds": 0.0,
              "reference_cpu": 0.0, "references_made": 0, "references_cached": 0}
    try:
        for fig, account in make_all(run, todo, a.jobs):
            add_account(totals, account)
            fig.reference_cpu = account["reference_cpu"]
            made.append(fig)
            made_refs = (f" ({account['reference_cpu']:.1f} of them in references)"
                         if account["references_made"] else "")
            print(f"figure {fig.number:2d} {fig.id:20s} {fig.seconds:6.1f} s {fig.cpu:6.1f} CPU s"
                  f"{made_refs}  {fig.png}", flush=True)
    except FigureError as e:
        sys.exit(f"make_figures: {e}")
    made.sort(key=lambda f: f.number)
    for k, v in totals.items():  # the whole run's accounts, as the summary below reads them
        setattr(run, k, v)
    render_wall = time.monotonic() - start
    times_path = run.out / TIMES_NAME
    try:
        times = json.loads(times_path.read_text())
    except (OSError, ValueError):
        times = {}
    times.setdefault("quick" if run.quick else "default", {}).update(
        {f.id: round(f.cpu - f.reference_cpu, 1) for f in made})  # a cached run's cost
    times_path.write_text(json.dumps(times, indent=1, sort_keys=True) + "\n")
    pdf = run.out / PDF_NAME
    if a.only:
        pdf.unlink(missing_ok=True)  # a partial run: no PDF that would miss slides
    else:
        slide.write_pdf([f.png for f in made], pdf)
        print(f"slides  {pdf}  ({len(made)} pages)")
    above = steps.noise_above(run.noise, run.levels)
    gallery.write_gallery(run.out / "index.html", made, run.quick, PDF_NAME,
                          alarm=[f"{run.rel(e)}: relative RMSE {n:.3f} above its level {level}"
                                 for e, n, level in above])
    print("time in tools: " + ", ".join(f"{tool} {s:.1f} s" for tool, s in
                                        sorted(run.seconds.items(), key=lambda kv: -kv[1])))
    print(f"time in references: {run.reference_seconds:.1f} s, {run.reference_cpu:.1f} CPU s "
          f"({run.references_made} made, {run.references_cached} cached in "
          f"{run.out / 'references'})")
    print("time per slide: " + ", ".join(f"{f.number} {f.seconds:.1f} s ({f.cpu:.1f} CPU s)"
                                         for f in made))
    cpu = steps.children_cpu() + sum(os.times()[:2]) - cpu_start
    print(f"CPU time {cpu:.1f} s, {cpu - run.reference_cpu:.1f} s of it outside references; "
          f"the figures took {render_wall:.1f} s of wall clock on {a.jobs} job(s) of "
          f"{run.threads or cores} thread(s), at a load average of {os.getloadavg()[0]:.1f}")
    if run.noise:
        print(f"noise: {len(run.noise)} path, bdpt and radiosity renders, relative RMSE "
              f"{min(run.noise.values()):.3f} to {max(run.noise.values()):.3f}; "
              + (f"ABOVE their level: " + ", ".join(f"{run.rel(e)} {n:.3f} > {level}"
                                                     for e, n, level in above)
                 if above else "each at or below its level"))
    print(f"gallery {run.out / 'index.html'}")
    print(f"total time {time.monotonic() - start:.1f} s")
    if above:
        sys.exit(f"make_figures: FAILED: {len(above)} render(s) above their noise level "
                 "(flagged in the gallery)")


if __name__ == "__main__":
    main()
