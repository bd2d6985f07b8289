"""The slide compositor: a 1920x1080 slide is a title over a grid of panels, each an image with a
label above and an LPE (or a note) below, drawn with OpenImageIO's Python bindings; and the PDF of
all slides.

The grid is chosen to make the panels as large as the frame allows (every column count is tried),
and every text is set at MIN_TEXT_PX or more (font size in px; an LPE's parentheses and bars fill
it) so that it can be read from the back of a hall. A slide fills its frame (empty_fraction: at
most MAX_EMPTY of it is empty) and no panel is too dark for a projector (DARK_FLOOR).
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

CONTENT_W, CONTENT_H = SLIDE_W - 2 * MARGIN, SLIDE_H - TOP - MARGIN  # where the grid may go
MAX_EMPTY = 0.15  # the bar: a slide leaves at most 15% of its content area empty
# A panel whose lit pixels (display luminance above NONBLACK, sRGB-encoded after its exposure)
# average below DARK_FLOOR reads as black on a projector: compose refuses it unless its exposure
# was chosen (and its label says so) or it is flagged dark on purpose. Measured over the lit
# pixels, so that a small bright highlight on black (a mirror's spot) passes and a dim glow fails.
DARK_FLOOR = 0.1
NONBLACK = 1 / 255  # the first step above black of an 8-bit slide

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

    source None is an empty cell of the grid (nothing drawn there). dark: why the panel may be
    darker than DARK_FLOOR (a difference that is near zero by design), listed in the notes."""

    def __init__(self, source, label="", below="", layer=None, exposure=1.0, crop=None, dark=None):
        self.source = Path(source) if source is not None else None
        self.dark = dark
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


def grid(n, aspect, cols=None, width=CONTENT_W):
    """The largest panels for n cells of width/height = aspect in a grid at most width wide:
    (cols, rows, panel_w, panel_h).

    Every column count from 1 to n is tried unless cols is given; the one whose panels are
    largest wins, so a slide's content fills the frame as far as the panels' shape allows."""
    best = None
    for c in ([cols] if cols else range(1, n + 1)):
        r = math.ceil(n / c)
        w_max = (width - (c - 1) * GAP) / c
        h_max = (CONTENT_H - (r - 1) * GAP) / r - LABEL_H - BELOW_H
        w = min(w_max, h_max * aspect)
        if w <= 0:
            continue
        if best is None or w > best[2] + 0.5:  # a tie keeps fewer columns (fewer empty cells)
            best = (c, r, w)
    if best is None:
        raise FigureError(f"{n} panels do not fit a {SLIDE_W}x{SLIDE_H} slide")
    c, r, w = best
    return c, r, int(w), int(w / aspect)


def cell_aspect(n, cols, width=CONTENT_W):
    """width/height of the image box of each cell when n panels in cols columns fill a grid
    width wide and the content area's full height: the aspect a recipe renders at so that its
    panels fill the frame (the render's resolution is chosen from the layout)."""
    rows = math.ceil(n / cols)
    w = (width - (cols - 1) * GAP) / cols
    h = (CONTENT_H - (rows - 1) * GAP) / rows - LABEL_H - BELOW_H
    return w / h


def side_size(grid_w):
    """The image size of a side panel beside a grid grid_w wide (see compose's side)."""
    return (CONTENT_W - grid_w - GAP, CONTENT_H - LABEL_H - BELOW_H)


class Cell:
    """One cell of a slide's layout: its top-left corner (x, y), its image box (w x h, between
    the label band above and the caption band below), its place in the grid (row, col; side: the
    panel right of the grid, which spans every row), and the size of the picture fitted into the box
    (image_w x image_h, centred; 0 x 0 for an empty cell)."""

    def __init__(self, x, y, w, h, row, col, image_w=0, image_h=0, side=False):
        self.x, self.y, self.w, self.h, self.row, self.col = x, y, w, h, row, col
        self.image_w, self.image_h, self.side = image_w, image_h, side

    @property
    def used(self):
        return self.image_w > 0 and self.image_h > 0

    @property
    def height(self):
        """The whole cell: label band, image box, caption band."""
        return LABEL_H + self.h + BELOW_H


def empty_fraction(cells):
    """The fraction of the slide's content area that the layout leaves empty.

    The content area is the frame inside the margins and below the title: x in [MARGIN,
    SLIDE_W - MARGIN], y in [TOP, SLIDE_H - MARGIN]. Empty is defined by the layout, not by the
    pixels' colour: the content area minus
      - every used cell's label band and caption band (the cell's width) and its picture (the
        fitted image, not the box it is centred in: the box's bars beside or above a picture
        of another shape are empty),
      - the gaps between used cells: between two side by side in a row, between two one above
        the other, the GAP x GAP square where four meet, and the strip between the grid and a
        side panel.
    So empty grid cells, bars around a picture of the wrong aspect and the unused strips beside
    and below the grid all count as empty."""
    filled = np.zeros((SLIDE_H, SLIDE_W), bool)

    def mark(x, y, w, h):
        filled[max(y, 0):max(y + h, 0), max(x, 0):max(x + w, 0)] = True

    for c in cells:
        if c.used:
            mark(c.x, c.y, c.w, LABEL_H)
            mark(c.x + (c.w - c.image_w) // 2, c.y + LABEL_H + (c.h - c.image_h) // 2,
                 c.image_w, c.image_h)
            mark(c.x, c.y + LABEL_H + c.h, c.w, BELOW_H)
    used = {(c.row, c.col): c for c in cells if c.used and not c.side}
    for c in cells:
        if c.used and c.side and used:  # the gap between the grid's area and the side panel
            mark(c.x - GAP, c.y, GAP, c.height)
    for c in used.values():
        right, below = used.get((c.row, c.col + 1)), used.get((c.row + 1, c.col))
        if right is not None:
            top = min(c.y, right.y)
            mark(c.x + c.w, top, right.x - c.x - c.w, max(c.y + c.height, right.y + right.height) - top)
        if below is not None:
            mark(c.x, c.y + c.height, c.w, below.y - c.y - c.height)
        if right is not None and below is not None and (c.row + 1, c.col + 1) in used:
            mark(c.x + c.w, c.y + c.height, right.x - c.x - c.w, below.y - c.y - c.height)
    inside = filled[TOP:SLIDE_H - MARGIN, MARGIN:SLIDE_W - MARGIN]
    return 1.0 - float(inside.mean())


def lit_luminance(pixels):
    """The mean Rec. 709 luminance of the display (sRGB-encoded) pixels above NONBLACK: how
    bright what a projector shows of the panel is; 0 for a black panel."""
    y = pixels[..., :3] @ np.array([0.2126, 0.7152, 0.0722])
    lit = y[y > NONBLACK]
    return float(lit.mean()) if lit.size else 0.0


def check_brightness(out_png, p, fitted):
    """A rendered panel that is not black but whose lit pixels are darker on average than
    DARK_FLOOR (lit_luminance) is refused,
    unless the recipe chose its exposure, which its label or caption must then state ("x4"), or
    flagged it dark on purpose (Panel.dark says why)."""
    if p.source.suffix != ".exr":
        return
    mean = lit_luminance(fitted)
    if p.exposure == 1.0 and p.dark is None:
        if 0.0 < mean < DARK_FLOOR:
            raise FigureError(f"{out_png}: the panel '{p.label}' is too dark for a projector: its lit "
                              f"pixels' mean display luminance is {mean:.3f} < {DARK_FLOOR}; give it an exposure "
                              "and say so in its label")
    elif p.exposure != 1.0 and f"x{p.exposure:g}" not in p.label + " " + p.below:
        raise FigureError(f"{out_png}: the panel '{p.label}' is shown at exposure {p.exposure:g}, "
                          f"but neither its label nor its caption says x{p.exposure:g}")


def compose(out_png, title, panels, cols=None, aspect=None, side=None, grid_w=None):
    """Draw the title and the grid of panels into a 1920x1080 PNG; return the fraction of the
    content area left empty (empty_fraction).

    side: one more panel (a plot) right of a grid grid_w wide, as tall as the slide allows;
    draw it at side_size(grid_w) so that its text keeps its size.

    In process, with OpenImageIO's Python bindings (fit, render_text). aspect defaults to the
    first panel's image. Fails (FigureError) when a label or LPE is wider than its cell, rather
    than drawing text over the neighbouring panel; when the layout leaves more than MAX_EMPTY of
    the content area empty; and when a panel is too dark (check_brightness)."""
    import OpenImageIO as oiio
    shown = [p for p in panels if p.source is not None]
    if aspect is None:
        w, h = image_size(shown[0].source)
        aspect = w / h
    width = CONTENT_W if side is None else grid_w
    cols, rows, panel_w, panel_h = grid(len(panels), aspect, cols, width)
    cell_h = LABEL_H + panel_h + BELOW_H
    used_w = cols * panel_w + (cols - 1) * GAP
    grid_h = rows * cell_h + (rows - 1) * GAP
    x0 = (SLIDE_W - used_w) // 2 if side is None else MARGIN + (grid_w - used_w) // 2
    y0 = TOP + (CONTENT_H - grid_h) // 2
    cells = [(p, Cell(x0 + (i % cols) * (panel_w + GAP), y0 + (i // cols) * (cell_h + GAP),
                      panel_w, panel_h, i // cols, i % cols)) for i, p in enumerate(panels)]
    if side is not None:
        side_w, side_h = side_size(grid_w)
        cells.append((side, Cell(MARGIN + grid_w + GAP, TOP, side_w, side_h, 0, cols, side=True)))
    if text_width(title, TITLE_PX) > CONTENT_W:
        raise FigureError(f"{out_png}: the title '{title}' is wider than the slide")
    canvas = np.empty((SLIDE_H, SLIDE_W, 3), np.float32)
    canvas[...] = BG
    texts = [(MARGIN * 2, TITLE_BASELINE, title, TITLE_PX, (1, 1, 1))]
    for p, c in cells:
        if p.source is None:
            continue
        for s, px in ((p.label, LABEL_PX), (p.below, BELOW_PX)):
            # a text may reach into the gap, never into the next cell's text
            if text_width(s, px) > c.w + GAP - TEXT_SEPARATION:
                raise FigureError(f"{out_png}: '{s}' ({px} px) is wider than its {c.w} px "
                                  f"panel: it would run into the next cell's text")
        fitted = p.fitted(c.w, c.h)  # centred in its cell
        check_brightness(out_png, p, fitted)
        c.image_h, c.image_w = fitted.shape[:2]
        fy = c.y + LABEL_H + (c.h - c.image_h) // 2
        fx = c.x + (c.w - c.image_w) // 2
        canvas[fy:fy + c.image_h, fx:fx + c.image_w] = fitted
        texts.append((c.x, c.y + LABEL_PX, p.label, LABEL_PX, (1, 1, 1)))
        if p.below:
            texts.append((c.x, c.y + LABEL_H + c.h + BELOW_PX + 4, p.below, BELOW_PX,
                          (0.75, 0.85, 1)))
    empty = empty_fraction([c for _, c in cells])
    if empty > MAX_EMPTY:
        unused = sum(1 for p, _ in cells if p.source is None) + cols * rows - len(panels)
        raise FigureError(f"{out_png}: the layout leaves {empty:.0%} of the frame empty "
                          f"(> {MAX_EMPTY:.0%}): {cols}x{rows} cells of {panel_w}x{panel_h} for "
                          f"pictures of aspect {aspect:.2f} ({cell_aspect(len(panels), cols, width):.2f} "
                          f"would fill it), {unused} empty cell(s)")
    buf = oiio.ImageBuf(oiio.ImageSpec(SLIDE_W, SLIDE_H, 3, oiio.FLOAT))
    buf.set_pixels(oiio.ROI(0, SLIDE_W, 0, SLIDE_H), canvas)
    for x, y, s, px, color in texts:
        if s and not oiio.ImageBufAlgo.render_text(buf, x, y, s, px, FONT, color):
            raise FigureError(f"{out_png}: drawing '{s}': {buf.geterror()}")
    buf.set_write_format(oiio.UINT8)
    # zlib level 3 instead of 6: half the CPU of writing a slide, 5% larger files
    buf.specmod().attribute("png:compressionLevel", 3)
    if not buf.write(str(out_png)):
        raise FigureError(f"{out_png}: {buf.geterror()}")
    return empty


def write_pdf(pngs, out_pdf):
    """All slides as one PDF, one page per PNG in the order given (img2pdf: lossless, the PNGs
    are embedded as they are, each page 1920x1080 px at 96 dpi = 20 x 11.25 in)."""
    import img2pdf
    layout = img2pdf.get_fixed_dpi_layout_fun((96, 96))
    Path(out_pdf).write_bytes(img2pdf.convert([str(p) for p in pngs], layout_fun=layout))
