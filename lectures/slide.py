"""The slide compositor: a 1920x1080 slide is a title over a grid of panels, each an image with a
label above and an LPE (or a note) below, drawn with OpenImageIO's Python bindings; and the PDF of
all slides.

The grid is chosen to make the panels as large as the frame allows (every column count is tried),
and every text is set at MIN_TEXT_PX or more (font size in px; an LPE's parentheses and bars fill
it) so that it can be read from the back of a hall.
"""

import math
from pathlib import Path

import numpy as np

from steps import FigureError

FONT = "DejaVuSans"  # named explicitly: OIIO's default font is not installed on a fresh machine
FONT_FAMILY = "DejaVu Sans"  # the same font for matplotlib (plots and text measurement)
SLIDE_W, SLIDE_H = 1920, 1080  # 16:9
BG = (0.08, 0.08, 0.09)  # slide background (display values); text is drawn light on dark
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
TEXT_SEPARATION = GAP // 2  # the least room between one cell's text and the next cell's

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

    def __init__(self, source, label="", below="", layer=None, exposure=1.0, crop=None):
        self.source = Path(source) if source is not None else None
        self.label, self.below = label, below
        self.layer, self.exposure = layer, exposure
        self.crop = crop  # (x0, y0, x1, y1) fractions of the image: a zoomed inset

    def pixels(self):
        """display(), cut to the crop when there is one."""
        pixels = self.display()
        if self.crop is None:
            return pixels
        h, w = pixels.shape[:2]
        x0, y0, x1, y1 = self.crop
        return pixels[round(y0 * h):round(y1 * h), round(x0 * w):round(x1 * w)]

    def display(self):
        """The panel's pixels for display: an (h, w, 3) float array of sRGB values in [0, 1].

        An EXR layer is scaled by the exposure, clamped and sRGB-encoded (IEC 61966-2-1), as
        OpenImageIO's linear -> sRGB conversion does; a PNG is taken as it is."""
        import OpenImageIO as oiio
        if self.source.suffix == ".exr":
            from checks import layer
            linear = np.clip(layer(self.source, self.layer or "") * self.exposure, 0.0, 1.0)
            return np.where(linear <= 0.0031308, 12.92 * linear,
                            1.055 * np.power(linear, 1 / 2.4) - 0.055)
        buf = oiio.ImageBuf(str(self.source))
        pixels = buf.get_pixels(oiio.FLOAT)
        if buf.has_error or pixels is None:
            raise FigureError(f"{self.source}: cannot read: {buf.geterror()}")
        return pixels[..., :3]

    def fitted(self, w, h):
        """The display pixels (cropped) scaled (Lanczos 3; box for an inset) to the largest size
        of their aspect within w x h: an (h', w', 3) array, h' <= h and w' <= w."""
        import OpenImageIO as oiio
        pixels = np.ascontiguousarray(self.pixels(), dtype=np.float32)
        src_h, src_w = pixels.shape[:2]
        scale = min(w / src_w, h / src_h)
        fw, fh = max(1, round(src_w * scale)), max(1, round(src_h * scale))
        src = oiio.ImageBuf(oiio.ImageSpec(src_w, src_h, 3, oiio.FLOAT))
        src.set_pixels(oiio.ROI(0, src_w, 0, src_h), pixels)
        # an inset keeps its pixels square and sharp (box: each source pixel a block)
        out = oiio.ImageBufAlgo.resize(src, filtername="box" if self.crop else "lanczos3",
                                       roi=oiio.ROI(0, fw, 0, fh))
        if out.has_error:
            raise FigureError(f"{self.source}: scaling to {fw}x{fh}: {out.geterror()}")
        return np.clip(out.get_pixels(oiio.FLOAT)[..., :3], 0.0, 1.0)


def grid(n, aspect, cols=None, width=SLIDE_W - 2 * MARGIN):
    """The largest panels for n cells of width/height = aspect in a grid at most width wide:
    (cols, rows, panel_w, panel_h).

    Every column count from 1 to n is tried unless cols is given; the one whose panels are
    largest wins, so a slide's content fills the frame as far as the panels' shape allows."""
    best = None
    for c in ([cols] if cols else range(1, n + 1)):
        r = math.ceil(n / c)
        w_max = (width - (c - 1) * GAP) / c
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


def side_size(grid_w):
    """The image size of a side panel beside a grid grid_w wide (see compose's side)."""
    return (SLIDE_W - 2 * MARGIN - grid_w - GAP,
            SLIDE_H - TOP - MARGIN - LABEL_H - BELOW_H)


def compose(out_png, title, panels, cols=None, aspect=None, side=None, grid_w=None):
    """Draw the title and the grid of panels into a 1920x1080 PNG; return the panel size.

    side: one more panel (a plot) right of a grid grid_w wide, as tall as the slide allows;
    draw it at side_size(grid_w) so that its text keeps its size.

    In process, with OpenImageIO's Python bindings (fit, render_text). aspect defaults to the
    first panel's image. Fails (FigureError) when a label or LPE is wider than its cell, rather
    than drawing text over the neighbouring panel."""
    import OpenImageIO as oiio
    shown = [p for p in panels if p.source is not None]
    if aspect is None:
        w, h = image_size(shown[0].source)
        aspect = w / h
    width = SLIDE_W - 2 * MARGIN if side is None else grid_w
    cols, rows, panel_w, panel_h = grid(len(panels), aspect, cols, width)
    cell_h = LABEL_H + panel_h + BELOW_H
    used_w = cols * panel_w + (cols - 1) * GAP
    grid_h = rows * cell_h + (rows - 1) * GAP
    x0 = (SLIDE_W - used_w) // 2 if side is None else MARGIN + (grid_w - used_w) // 2
    y0 = TOP + (SLIDE_H - MARGIN - TOP - grid_h) // 2
    cells = [(p, x0 + (i % cols) * (panel_w + GAP), y0 + (i // cols) * (cell_h + GAP),
              panel_w, panel_h) for i, p in enumerate(panels)]
    if side is not None:
        side_w, side_h = side_size(grid_w)
        cells.append((side, MARGIN + grid_w + GAP, TOP, side_w, side_h))
    if text_width(title, TITLE_PX) > SLIDE_W - 2 * MARGIN:
        raise FigureError(f"{out_png}: the title '{title}' is wider than the slide")
    canvas = np.empty((SLIDE_H, SLIDE_W, 3), np.float32)
    canvas[...] = BG
    texts = [(MARGIN * 2, TITLE_BASELINE, title, TITLE_PX, (1, 1, 1))]
    for p, x, y, panel_w, panel_h in cells:
        if p.source is None:
            continue
        for s, px in ((p.label, LABEL_PX), (p.below, BELOW_PX)):
            # a text may reach into the gap, never into the next cell's text
            if text_width(s, px) > panel_w + GAP - TEXT_SEPARATION:
                raise FigureError(f"{out_png}: '{s}' ({px} px) is wider than its {panel_w} px "
                                  f"panel: it would run into the next cell's text")
        fitted = p.fitted(panel_w, panel_h)  # centred in its cell
        fy = y + LABEL_H + (panel_h - fitted.shape[0]) // 2
        fx = x + (panel_w - fitted.shape[1]) // 2
        canvas[fy:fy + fitted.shape[0], fx:fx + fitted.shape[1]] = fitted
        texts.append((x, y + LABEL_PX, p.label, LABEL_PX, (1, 1, 1)))
        if p.below:
            texts.append((x, y + LABEL_H + panel_h + BELOW_PX + 4, p.below, BELOW_PX,
                          (0.75, 0.85, 1)))
    buf = oiio.ImageBuf(oiio.ImageSpec(SLIDE_W, SLIDE_H, 3, oiio.FLOAT))
    buf.set_pixels(oiio.ROI(0, SLIDE_W, 0, SLIDE_H), canvas)
    for x, y, s, px, color in texts:
        if s and not oiio.ImageBufAlgo.render_text(buf, x, y, s, px, FONT, color):
            raise FigureError(f"{out_png}: drawing '{s}': {buf.geterror()}")
    buf.set_write_format(oiio.UINT8)
    if not buf.write(str(out_png)):
        raise FigureError(f"{out_png}: {buf.geterror()}")
    return panel_w, panel_h


def write_pdf(pngs, out_pdf):
    """All slides as one PDF, one page per PNG in the order given (img2pdf: lossless, the PNGs
    are embedded as they are, each page 1920x1080 px at 96 dpi = 20 x 11.25 in)."""
    import img2pdf
    layout = img2pdf.get_fixed_dpi_layout_fun((96, 96))
    Path(out_pdf).write_bytes(img2pdf.convert([str(p) for p in pngs], layout_fun=layout))
