#!/usr/bin/python3
"""Unit tests of the slide compositor's layout rules (slide.py), on synthetic panels:

    /usr/bin/python3 lectures/test_slide.py

The empty area is checked against rectangles worked out here by hand, not by the function under
test; compose must refuse a layout that leaves more than MAX_EMPTY of the frame empty and a
panel too dark for a projector, and accept a layout that fills the frame."""

import sys
import tempfile
import unittest
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import checks  # noqa: E402  (the modules beside this script)
import slide  # noqa: E402
import steps  # noqa: E402
from slide import (BELOW_H, CONTENT_H, CONTENT_W, GAP, LABEL_H, Cell, Panel,  # noqa: E402
                   compose, empty_fraction)
from steps import FigureError  # noqa: E402

AREA = CONTENT_W * CONTENT_H  # 1860 x 938


def exr(directory, name, w, h, value):
    """A w x h EXR of one grey value."""
    return checks.write_exr(np.full((h, w, 3), value, np.float64), Path(directory) / f"{name}.exr")


class EmptyFraction(unittest.TestCase):
    def test_one_cell_filling_the_content_area_leaves_nothing_empty(self):
        c = Cell(slide.MARGIN, slide.TOP, CONTENT_W, CONTENT_H - LABEL_H - BELOW_H, 0, 0,
                 CONTENT_W, CONTENT_H - LABEL_H - BELOW_H)
        self.assertEqual(empty_fraction([c]), 0.0)

    def test_a_narrow_picture_leaves_the_bars_beside_it_empty(self):
        h = CONTENT_H - LABEL_H - BELOW_H
        c = Cell(slide.MARGIN, slide.TOP, CONTENT_W, h, 0, 0, 930, h)  # half the width
        self.assertAlmostEqual(empty_fraction([c]), 930 * h / AREA, places=6)

    def test_two_cells_side_by_side_count_their_gap_and_leave_the_rest(self):
        # two 400-wide cells of 300-high pictures, a GAP between them, top left of the area
        cells = [Cell(slide.MARGIN + i * (400 + GAP), slide.TOP, 400, 300, 0, i, 400, 300)
                 for i in range(2)]
        filled = (2 * 400 + GAP) * (LABEL_H + 300 + BELOW_H)
        self.assertAlmostEqual(empty_fraction(cells), 1 - filled / AREA, places=6)

    def test_an_empty_cell_and_its_gap_count_as_empty(self):
        cells = [Cell(slide.MARGIN + i * (400 + GAP), slide.TOP, 400, 300, 0, i,
                      400 if i == 0 else 0, 300 if i == 0 else 0) for i in range(2)]
        filled = 400 * (LABEL_H + 300 + BELOW_H)
        self.assertAlmostEqual(empty_fraction(cells), 1 - filled / AREA, places=6)


class Compose(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def test_a_layout_that_fills_the_frame_is_drawn(self):
        # six panels, three columns, each rendered at the aspect of its cell
        aspect = slide.cell_aspect(6, 3)
        src = exr(self.dir, "fill", round(360 * aspect), 360, 0.5)
        out = self.dir / "fill.png"
        empty = compose(out, "Fills", [Panel(src, f"p{i}") for i in range(6)], cols=3)
        self.assertLessEqual(empty, slide.MAX_EMPTY)
        self.assertTrue(out.is_file())

    def test_three_wide_panels_in_one_row_are_refused(self):
        # the attenuation slide as it was: 16:9 pictures, one row, half the height unused
        src = exr(self.dir, "wide", 640, 360, 0.5)
        out = self.dir / "wide.png"
        with self.assertRaisesRegex(FigureError, r"of the frame empty"):
            compose(out, "Too empty", [Panel(src, f"p{i}") for i in range(3)])
        self.assertFalse(out.exists(), "a refused slide must not be written")

    def test_five_panels_in_a_grid_of_six_at_4_3_are_refused(self):
        src = exr(self.dir, "four-three", 640, 480, 0.5)
        with self.assertRaisesRegex(FigureError, r"1 empty cell"):
            compose(self.dir / "five.png", "Five", [Panel(src, f"p{i}") for i in range(5)], cols=3)

    def test_a_dark_panel_is_refused_unless_its_exposure_is_stated(self):
        aspect = slide.cell_aspect(6, 3)
        w = round(360 * aspect)
        # dark: 0.002 is a display value of 0.026, lit (above 1/255) but far below DARK_FLOOR
        bright, dark = exr(self.dir, "bright", w, 360, 0.5), exr(self.dir, "dark", w, 360, 0.002)
        panels = [Panel(bright, f"p{i}") for i in range(5)]
        with self.assertRaisesRegex(FigureError, r"too dark for a projector"):
            compose(self.dir / "dark.png", "Dark", panels + [Panel(dark, "dark")], cols=3)
        with self.assertRaisesRegex(FigureError, r"neither its label nor its caption says x100"):
            compose(self.dir / "dark.png", "Dark",
                    panels + [Panel(dark, "dark", exposure=100.0)], cols=3)
        compose(self.dir / "dark.png", "Dark",
                panels + [Panel(dark, "dark, x100", exposure=100.0)], cols=3)
        compose(self.dir / "dark.png", "Dark", panels + [Panel(dark, "dark", dark="why")], cols=3)
        black = exr(self.dir, "black", w, 360, 0.0)  # exactly black: a zero the slide shows
        compose(self.dir / "black.png", "Black", panels + [Panel(black, "zero")], cols=3)


class NoiseLevel(unittest.TestCase):
    """The default figures' quality gate (steps.py): the verdict that fails the run."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def test_relative_rmse_against_a_hand_computed_value(self):
        # half the pixels 1.3, half 0.7, against 1.0: RMSE 0.3 of a mean 1.0
        img = np.full((4, 8, 3), 1.3)
        img[:, 4:] = 0.7
        a = checks.write_exr(img, self.dir / "a.exr")
        ref = exr(self.dir, "ref", 8, 4, 1.0)
        self.assertAlmostEqual(steps.relative_rmse(a, ref), 0.3, places=5)

    def test_a_render_above_its_level_fails_and_a_stated_level_holds(self):
        a, b, c, d = (Path(f"/x/{n}.exr") for n in "abcd")
        noise = {a: 0.05, b: 0.244, c: 0.3, d: float("nan")}
        levels = {a: (steps.NOISE_LEVEL, ""), b: (steps.NOISE_LEVEL, ""), c: (0.4, "why"),
                  d: (steps.NOISE_LEVEL, "")}
        self.assertEqual([e for e, _, _ in steps.noise_above(noise, levels)], [b, d])

    def test_a_level_of_its_own_needs_a_reason(self):
        run = steps.Run(sys.executable, self.dir, quick=False)
        with self.assertRaisesRegex(FigureError, r"needs a reason"):
            steps.render(run, "f", "n", self.dir / "s.toml", noise_level=0.5)


if __name__ == "__main__":
    unittest.main()
