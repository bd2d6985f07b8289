"""The figures' plots and diagrams, drawn with Debian's matplotlib at the size they take on the
slide (so their text keeps the slide's text size: 28 pt at 100 dpi is 39 px)."""

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the non-interactive backend)

DPI = 100
SLIDE_STYLE = {"font.family": "DejaVu Sans", "font.size": 28, "axes.linewidth": 2,
               "lines.linewidth": 4, "figure.facecolor": "white"}


def exponent_plot(png, exponents, width_px, height_px):
    """(H.N)^n = cos^n(angle) against the angle between H and N, one curve per n."""
    with plt.rc_context(SLIDE_STYLE):
        fig, ax = plt.subplots(figsize=(width_px / DPI, height_px / DPI), dpi=DPI)
        angles = [i * 0.1 for i in range(0, 901)]
        for n in exponents:
            ax.plot(angles, [math.cos(math.radians(a)) ** n for a in angles], label=f"n = {n}")
        ax.set_xlabel("angle between H and N (degrees)")
        ax.set_ylabel("(H.N)^n")
        ax.set_xlim(0, 90)
        ax.set_ylim(0, 1.02)
        ax.grid(alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(png)
        plt.close(fig)


def ray_sphere_diagram(png, cases, width_px, height_px):
    """One small diagram per case: the ray from the origin along +x, the circle, the first hit
    the renderer reported (red) and the quadratic's other root (grey ring).

    cases: [(name, centre, radius, hit, t)] with t the renderer's first-hit distance or None."""
    with plt.rc_context(SLIDE_STYLE):
        fig, axes = plt.subplots(1, len(cases), figsize=(width_px / DPI, height_px / DPI), dpi=DPI)
        for ax, (name, c, r, hit, t) in zip(axes, cases):
            ax.set_aspect("equal")
            ax.set_xlim(-3.7, 5.2)
            ax.set_ylim(-2.4, 2.6)
            ax.axis("off")
            ax.add_patch(plt.Circle((c[0], c[1]), r, fill=False, lw=4, color="tab:blue"))
            ax.annotate("", xy=(5.0, 0), xytext=(0, 0),
                        arrowprops=dict(arrowstyle="->", lw=3, color="k"))
            ax.plot([0], [0], "ko", ms=10)
            # the roots along the ray (direction +x): t = c.x -+ sqrt(r^2 - c.y^2)
            h2 = r * r - c[1] * c[1]
            roots = [] if h2 < 0 else sorted({c[0] - math.sqrt(h2), c[0] + math.sqrt(h2)})
            for x in roots:
                if x > 0 and (t is None or abs(x - t) > 1e-3):
                    ax.plot([x], [0], "o", ms=16, mfc="none", mec="gray", mew=3)
            if t is not None:
                ax.plot([t], [0], "o", ms=18, color="tab:red")
            verdict = f"t = {t:.3f}" if (hit and t is not None) else ("hit" if hit else "miss")
            ax.set_title(f"{name}\n{verdict}", fontsize=30)
        fig.tight_layout(rect=(0, 0.1, 1, 1))
        fig.text(0.5, 0.03, "red: the first hit lightpath reports   grey ring: the other root",
                 ha="center", fontsize=28)
        fig.savefig(png)
        plt.close(fig)
