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

    def test_a_reference_s_layer_read_alone_is_the_layer_read_with_all(self):
        import OpenImageIO as oiio
        names = ["R", "G", "B", "caustic.R", "caustic.G", "caustic.B", "rest.R", "rest.G", "rest.B"]
        pixels = np.arange(4 * 5 * 9, dtype=np.float32).reshape(4, 5, 9) / 7.0
        spec = oiio.ImageSpec(5, 4, 9, oiio.FLOAT)
        spec.channelnames = names
        buf = oiio.ImageBuf(spec)
        buf.set_pixels(oiio.ROI(0, 5, 0, 4, 0, 1, 0, 9), pixels)
        path = self.dir / "layers.exr"
        self.assertTrue(buf.write(str(path)))
        layers = (("", 0), ("caustic", 3), ("rest", 6))
        alone = {name: checks.read_layer(path, name) for name, _ in layers}  # nothing cached yet
        for name, first in layers:
            np.testing.assert_array_equal(alone[name], pixels[..., first:first + 3].astype(np.float64))
            np.testing.assert_array_equal(alone[name], checks.read_layers(path)[name])
        with self.assertRaisesRegex(FigureError, r"no layer 'direct' \(has , caustic, rest\)"):
            checks.read_layer(self.dir / "layers.exr", "direct")

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


# A stand-in for the lightpath binary: `render SCENE -o OUT ... --spp N` writes a 4x4 EXR whose
# every channel is N (1 without --spp) and appends its command line to the file CALLS beside it.
FAKE_LIGHTPATH = """#!/usr/bin/python3
import sys
from pathlib import Path
sys.path.insert(0, {lectures!r})
import numpy as np
import checks
argv = sys.argv[1:]
with open(Path(sys.argv[0]).parent / "CALLS", "a") as log:
    log.write(" ".join(argv) + "\\n")
spp = float(argv[argv.index("--spp") + 1]) if "--spp" in argv else 1.0
checks.write_exr(np.full((4, 4, 3), spp), argv[argv.index("-o") + 1])
"""


class References(unittest.TestCase):
    """The noise references (steps.measure_noise): any cached one with enough samples serves, and
    a render two worker processes ask for is made once (steps.shared_render)."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = Path(self.tmp.name)
        self.lightpath = self.dir / "bin" / "lightpath"
        self.lightpath.parent.mkdir()
        self.lightpath.write_text(FAKE_LIGHTPATH.format(lectures=str(Path(__file__).resolve().parent)))
        self.lightpath.chmod(0o755)
        self.scene = self.dir / "s.toml"
        self.scene.write_text("# a scene\n")
        self.run = steps.Run(self.lightpath, self.dir / "out", quick=False)

    def tearDown(self):
        self.tmp.cleanup()

    def calls(self):
        log = self.lightpath.parent / "CALLS"
        return log.read_text().splitlines() if log.is_file() else []

    def test_reference_noise_against_hand_computed_values(self):
        # measured^2 = e^2 (1 + 1/k): against 4x it is itself; against 16x, e^2 = 0.01 / 1.0625,
        # and as against 4x: sqrt(0.01 * 1.25 / 1.0625) = 0.108465...
        self.assertAlmostEqual(steps.reference_noise(0.1, 4), 0.1, places=12)
        self.assertAlmostEqual(steps.reference_noise(0.1, 16), 0.1084652289, places=9)

    def test_a_cached_reference_with_enough_samples_serves_a_render_with_fewer(self):
        def noise(spp):
            exr = checks.write_exr(np.full((4, 4, 3), 1.0), self.dir / f"r{spp}.exr")
            argv = [self.run.lightpath, "render", str(self.scene), "-o", str(exr), "--seed", "1",
                    "--quiet", "--integrator", "path", "--spp", str(spp)]
            return steps.measure_noise(self.run, argv, exr)
        # 2 spp: a reference at 8 is made (every pixel 8 against the render's 1: 7/8 relative)
        self.assertAlmostEqual(noise(2), 7 / 8, places=6)
        self.assertEqual(len(self.calls()), 1)
        # 1 spp: that reference has 8x its samples, it serves; the noise as against 4x
        self.assertAlmostEqual(noise(1), steps.reference_noise(7 / 8, 8), places=6)
        self.assertEqual(len(self.calls()), 1)
        # 4 spp: it has 2x, too few: one at 16 is made
        self.assertAlmostEqual(noise(4), 15 / 16, places=6)
        self.assertEqual(len(self.calls()), 2)
        self.assertEqual(sorted(f.name.split("-")[1] for f in (self.dir / "out" / "references").iterdir()),
                         ["16spp.exr", "8spp.exr"])
        self.assertEqual((self.run.references_made, self.run.references_cached), (2, 1))

    def test_a_reference_serves_the_same_command_from_another_build_tree(self):
        def noise(run, calls_dir):
            exr = checks.write_exr(np.full((4, 4, 3), 1.0), self.dir / "r.exr")
            argv = [run.lightpath, "render", str(self.scene), "-o", str(exr), "--seed", "1",
                    "--quiet", "--integrator", "path", "--spp", "2"]
            steps.measure_noise(run, argv, exr)
            log = calls_dir / "CALLS"
            return len(log.read_text().splitlines()) if log.is_file() else 0
        self.assertEqual(noise(self.run, self.lightpath.parent), 1)
        other = self.dir / "other-build" / "lightpath"
        other.parent.mkdir()
        other.write_text(self.lightpath.read_text())
        other.chmod(0o755)
        run = steps.Run(other, self.dir / "out", quick=False)
        self.assertEqual(noise(run, other.parent), 0)
        self.assertEqual((run.references_made, run.references_cached), (0, 1))

    def test_a_render_two_worker_processes_ask_for_is_made_once(self):
        import multiprocessing
        run = self.run
        run.quick = True  # no noise reference: only the render's own command is counted

        def work(_):
            steps.render(run, "f", "n", self.scene, "--integrator", "path", "--spp", 2)
        ctx = multiprocessing.get_context("fork")
        workers = [ctx.Process(target=work, args=(i,)) for i in range(4)]
        for w in workers:
            w.start()
        for w in workers:
            w.join()
        self.assertEqual([w.exitcode for w in workers], [0] * 4)
        self.assertEqual(len(self.calls()), 1)
        # another generator run (another token) makes it again
        steps.render(steps.Run(self.lightpath, self.dir / "out", quick=True), "f", "n", self.scene,
                     "--integrator", "path", "--spp", 2)
        self.assertEqual(len(self.calls()), 2)


if __name__ == "__main__":
    unittest.main()
