"""The slide compositor: a 1920x1080 slide is a title over a grid of panels, each an image with a
label above and an LPE (or a note) below, drawn by one oiiotool command; and the PDF of all slides.

The grid is chosen to make the panels as large as the frame allows (every column count is tried),
and every text is at least kMinTextPx tall so that it can be read from the back of a hall.
"""

import math
from pathlib import Path

from steps import FigureError, sh

FONT = "DejaVuSans"  # named explicitly: OIIO's default font is not installed on a fresh machine
FONT_FAMILY = "DejaVu Sans"  # the same font for matplotlib (plots and text measurement)
SLIDE_W, SLIDE_H = 1920, 1080  # 16:9
BG = "0.08,0.08,0.09"  # slide background (linear); text is drawn light on dark
MARGIN = 30  # left, right and bottom margin of the grid, px
TITLE_PX = 64  # title height (font size, px)
TITLE_BASELINE = 78
TOP = 112  # the grid starts below the title
LABEL_PX = 40  # panel label (what it is)
BELOW_PX = 40  # the LPE or note under a panel
MIN_TEXT_PX = 36  # the bar for LPE captions at 1080p
LABEL_H = LABEL_PX + 14  # the cell's band above the image
BELOW_H = BELOW_PX + 16  # the cell's band below it
GAP = 24  # between cells

assert min(LABEL_PX, BELOW_PX, TITLE_PX) >= MIN_TEXT_PX


def image_size(path):
    """(width, height) of an image file, read from its header with OpenImageIO."""
    import OpenImageIO as oiio
    inp = oiio.ImageInput.open(str(path))
    if inp is None:
        raise FigureError(f"{path}: cannot open: {oiio.geterror()}")
    spec = inp.spec()
    inp.close()
    return spec.width, spec.height


def text_width(s, px):
    """Width in pixels of s drawn in DejaVu Sans at px pixels (matplotlib's text layout)."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextToPath
    w, _, _ = TextToPath().get_text_width_height_descent(
        s, FontProperties(family=FONT_FAMILY, size=px), ismath=False)
    return w


class Panel:
    """One image on a slide: an EXR layer (tone-mapped to sRGB) or a ready PNG, with its texts.

    source None is an empty cell of the grid (nothing drawn there)."""

    def __init__(self, source, label="", below="", layer=None, exposure=1.0):
        self.source = Path(source) if source is not None else None
        self.label, self.below = label, below
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
        # A plot or diagram (sRGB already): fitted and padded to the cell.
        return args + ["--ch", "R,G,B", "--fit:filter=lanczos3:pad=1", f"{w}x{h}"]


def text(x, y, s, size, color="0.9,0.9,0.9"):
    """oiiotool arguments drawing s at (x, y = baseline) in DejaVuSans."""
    return [f"--text:x={x}:y={y}:size={size}:color={color}:font={FONT}", s]


def grid(n, aspect, cols=None):
    """The largest panels for n cells of width/height = aspect: (cols, rows, panel_w, panel_h).

    Every column count from 1 to n is tried unless cols is given; the one whose panels are
    largest wins, so a slide's content fills the frame as far as the panels' shape allows."""
    best = None
    for c in ([cols] if cols else range(1, n + 1)):
        r = math.ceil(n / c)
        w_max = (SLIDE_W - 2 * MARGIN - (c - 1) * GAP) / c
        h_max = (SLIDE_H - TOP - MARGIN - (r - 1) * GAP) / r - LABEL_H - BELOW_H
        w = min(w_max, h_max * aspect)
        if w <= 0:
            continue
        if best is None or w > best[2] + 0.5:  # a tie keeps fewer columns (fewer empty cells)
            best = (c, r, w)
    if best is None:
        raise FigureError(f"{n} panels do not fit a {SLIDE_W}x{SLIDE_H} slide")
    c, r, w = best
    return c, r, int(w), int(w / aspect)


def compose(run, out_png, title, panels, cols=None, aspect=None):
    """Draw the title and the grid of panels into a 1920x1080 PNG; return the panel size.

    aspect defaults to the first panel's image. Fails (FigureError) when a label or LPE is wider
    than its cell, rather than drawing text over the neighbouring panel."""
    shown = [p for p in panels if p.source is not None]
    if aspect is None:
        w, h = image_size(shown[0].source)
        aspect = w / h
    cols, rows, panel_w, panel_h = grid(len(panels), aspect, cols)
    cell_h = LABEL_H + panel_h + BELOW_H
    grid_w = cols * panel_w + (cols - 1) * GAP
    grid_h = rows * cell_h + (rows - 1) * GAP
    x0 = (SLIDE_W - grid_w) // 2
    y0 = TOP + (SLIDE_H - MARGIN - TOP - grid_h) // 2
    if text_width(title, TITLE_PX) > SLIDE_W - 2 * MARGIN:
        raise FigureError(f"{out_png}: the title '{title}' is wider than the slide")
    # --evaloff: an LPE's {n,m} is text, not an oiiotool expression; --nosoftwareattrib: no
    # command line (with its paths) in the PNG, so reruns are byte-identical
    args = ["oiiotool", "--evaloff", "--nosoftwareattrib", "--create", f"{SLIDE_W}x{SLIDE_H}", "3",
            "--fill:color=" + BG, f"{SLIDE_W}x{SLIDE_H}+0+0"]
    args += text(MARGIN * 2, TITLE_BASELINE, title, TITLE_PX, "1,1,1")
    for i, p in enumerate(panels):
        if p.source is None:
            continue
        r, c = divmod(i, cols)
        x = x0 + c * (panel_w + GAP)
        y = y0 + r * (cell_h + GAP)
        for s, px in ((p.label, LABEL_PX), (p.below, BELOW_PX)):
            if text_width(s, px) > panel_w + GAP:
                raise FigureError(f"{out_png}: '{s}' ({px} px) is wider than its {panel_w} px panel")
        args += p.oiio_load(panel_w, panel_h) + ["--swap", "--paste", f"+{x}+{y + LABEL_H}"]
        args += text(x, y + LABEL_PX, p.label, LABEL_PX, "1,1,1")
        if p.below:
            args += text(x, y + LABEL_H + panel_h + BELOW_PX + 4, p.below, BELOW_PX, "0.75,0.85,1")
    args += ["-d", "uint8", "-o", str(out_png)]
    sh(run, args, record=False)
    return panel_w, panel_h


def write_pdf(pngs, out_pdf):
    """All slides as one PDF, one page per PNG in the order given (img2pdf: lossless, the PNGs
    are embedded as they are, each page 1920x1080 px at 96 dpi = 20 x 11.25 in)."""
    import img2pdf
    layout = img2pdf.get_fixed_dpi_layout_fun((96, 96))
    Path(out_pdf).write_bytes(img2pdf.convert([str(p) for p in pngs], layout_fun=layout))
