#!/usr/bin/python3
"""Open the lecture gallery (index.html) in headless Chromium and check it as a reader would see it,
and check the PDF of the slides beside it.

    /usr/bin/python3 lectures/test_gallery.py build/lectures/index.html [--expect N]

Passes when the page reports every image loaded (index.html's own script checks naturalWidth of
each <img> on load and writes "images ok: N" into #status), N is the number of figures (by
default, the [[figure]] tables of lectures/figures.toml), Chromium logged no console error (a
missing file, a script error), and slides.pdf beside the page has N pages (poppler's pdfinfo, a
reader independent of the img2pdf that wrote it). Saves a screenshot, gallery-screenshot.png,
beside the page. Exit code 0 on success, 1 with the reason otherwise.
"""

import argparse
import html
import re
import shutil
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

FIGURES_TOML = Path(__file__).resolve().parent / "figures.toml"
REPO = Path(__file__).resolve().parent.parent


def pasted_commands_fail(dom):
    """Paste the page's explain and lpe commands (quick, and quoted like every other: LPEs with
    <, >, quotes and braces) into bash at the repository's root: the ones that fail, with why."""
    commands = [html.unescape(line) for pre in re.findall(r"<pre>(.*?)</pre>", dom, re.DOTALL)
                for line in pre.splitlines()
                if re.match(r"\S*lightpath (explain|lpe) ", line)]
    failed = []
    for command in commands[:8]:
        proc = subprocess.run(["bash", "-c", command], cwd=REPO, capture_output=True, text=True)
        if proc.returncode != 0:
            failed.append(f"{command}\n    exit {proc.returncode}: {proc.stderr.strip()[-300:]}")
    return commands, failed


def figure_count():
    """How many figures lectures/figures.toml lists: the slides the gallery and PDF must hold."""
    return len(tomllib.loads(FIGURES_TOML.read_text())["figure"])


def pdf_pages(pdf):
    """The page count pdfinfo (poppler-utils) reads from the PDF, or None when it cannot."""
    if shutil.which("pdfinfo") is None:
        sys.exit("test_gallery: no pdfinfo; install Debian's poppler-utils (scripts/setup does)")
    proc = subprocess.run(["pdfinfo", str(pdf)], capture_output=True, text=True)
    m = re.search(r"^Pages:\s+(\d+)$", proc.stdout, re.MULTILINE)
    return int(m.group(1)) if proc.returncode == 0 and m else None


def chromium():
    """Debian's chromium (or chromium-browser / google-chrome where that is what exists)."""
    for name in ("chromium", "chromium-browser", "google-chrome"):
        if shutil.which(name):
            return name
    sys.exit("test_gallery: no chromium found; install Debian's chromium (scripts/setup does)")


def run_chromium(args, profile):
    """Run headless Chromium with a throw-away profile; return (stdout, stderr)."""
    argv = [chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
            f"--user-data-dir={profile}", "--enable-logging=stderr", "--v=0",
            "--virtual-time-budget=10000", *args]
    proc = subprocess.run(argv, capture_output=True, text=True, timeout=400)
    if proc.returncode != 0:
        sys.exit(f"test_gallery: chromium failed (exit {proc.returncode}):\n{proc.stderr[-3000:]}")
    return proc.stdout, proc.stderr


def console_errors(stderr):
    """Console messages and failed loads from Chromium's log (not its own startup noise)."""
    bad = []
    for line in stderr.splitlines():
        if ("CONSOLE" in line and ("error" in line.lower() or "Uncaught" in line)) \
                or "ERR_FILE_NOT_FOUND" in line or "Failed to load resource" in line:
            bad.append(line.strip())
    return bad


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("page", help="the gallery's index.html")
    ap.add_argument("--expect", type=int, default=None,
                    help="number of figures the page and the PDF must show (default: figures.toml's)")
    a = ap.parse_args()
    expect = a.expect if a.expect is not None else figure_count()
    page = Path(a.page).resolve()
    if not page.is_file():
        sys.exit(f"test_gallery: no page at {page}; build the 'figures' target first")
    url = page.as_uri()
    with tempfile.TemporaryDirectory() as profile:
        dom, log = run_chromium(["--dump-dom", url], profile)
        shot = page.parent / "gallery-screenshot.png"
        run_chromium([f"--screenshot={shot}", "--window-size=1280,2400", url], profile)

    m = re.search(r'<p id="status">([^<]*)</p>', dom)
    status = m.group(1) if m else "(no #status element)"
    errors = console_errors(log)
    problems = []
    if status != f"images ok: {expect}":
        problems.append(f"page status is '{status}', expected 'images ok: {expect}'")
    pdf = page.parent / "slides.pdf"
    pages = pdf_pages(pdf) if pdf.is_file() else None
    if pages != expect:
        problems.append(f"{pdf}: {pages if pages is not None else 'no readable PDF'} pages, "
                        f"expected {expect}, one per figure")
    if errors:
        problems.append("console errors:\n  " + "\n  ".join(errors))
    # The commands must paste as they are: no quote-splicing that shlex.join makes of a quote
    # (read from the DOM Chromium built, where the page's &quot; entities are characters again)
    if "'\"'\"'" in dom:
        problems.append("the page's commands contain '\"'\"' quoting")
    pasted, failed = pasted_commands_fail(dom)
    if not pasted:
        problems.append("the page lists no explain or lpe command to paste")
    if failed:
        problems.append("pasted into bash, these commands fail:\n  " + "\n  ".join(failed))
    if not shot.is_file() or shot.stat().st_size == 0:
        problems.append(f"no screenshot written at {shot}")
    if problems:
        sys.exit("test_gallery: FAILED\n" + "\n".join(problems))
    print(f"test_gallery: {status}, no console errors, {pdf.name} has {pages} pages; "
          f"screenshot {shot}")


if __name__ == "__main__":
    main()
