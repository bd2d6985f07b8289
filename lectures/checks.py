"""What a figure claims, checked on the EXR its panels come from before the figure is written.

Each check raises FigureError, which stops the generator: a slide that would lie is not drawn."""

import itertools
import re
import subprocess
import tomllib
from pathlib import Path

import numpy as np

from steps import FigureError


_layers_cache = {}


def read_layers(exr):
    """{layer name: float64 array (h, w, 3)} of an EXR; the beauty is ''.

    Cached by path and modification time: several checks and figures read one render."""
    key = (str(exr), Path(exr).stat().st_mtime_ns)
    if key not in _layers_cache:
        _layers_cache[key] = _read_layers(exr)
    return _layers_cache[key]


def _read_layers(exr):
    import OpenImageIO as oiio
    buf = oiio.ImageBuf(str(exr))
    if buf.has_error:
        raise FigureError(f"{exr}: {buf.geterror()}")
    names = list(buf.spec().channelnames)
    pixels = buf.get_pixels(oiio.FLOAT).astype(np.float64)
    layers = {}
    for i, name in enumerate(names):
        prefix, _, channel = name.rpartition(".")
        if channel == "R" and f"{prefix + '.' if prefix else ''}B" in names:
            dot = prefix + "." if prefix else ""
            layers[prefix] = pixels[..., [names.index(dot + c) for c in "RGB"]]
    return layers


def read_layer(exr, name):
    """One layer of an EXR ('' is the beauty) as a float64 (h, w, 3) array, reading only its three
    channels unless the whole EXR is cached already: a noise reference has a dozen layers, and
    the noise is measured on one (five times faster than reading them all)."""
    key = (str(exr), Path(exr).stat().st_mtime_ns)
    if key in _layers_cache:
        return layer(exr, name)
    import OpenImageIO as oiio
    inp = oiio.ImageInput.open(str(exr))
    if inp is None:
        raise FigureError(f"{exr}: {oiio.geterror()}")
    names = list(inp.spec().channelnames)
    dot = name + "." if name else ""
    wanted = [dot + c for c in "RGB"]
    if not all(c in names for c in wanted):
        inp.close()
        return layer(exr, name)  # the error that names the layers it has
    first = names.index(wanted[0])
    if names[first:first + 3] != wanted:
        inp.close()
        return read_layers(exr)[name]
    pixels = inp.read_image(0, 0, first, first + 3, oiio.FLOAT)
    inp.close()
    if pixels is None:
        raise FigureError(f"{exr}: {oiio.geterror()}")
    return pixels.astype(np.float64)


def write_exr(rgb, path):
    """An (h, w, 3) array as a float EXR, so the compositor tone-maps it as it does renders."""
    import OpenImageIO as oiio
    h, w, _ = rgb.shape
    buf = oiio.ImageBuf(oiio.ImageSpec(w, h, 3, oiio.FLOAT))
    # C order: set_pixels reads the buffer as laid out, and a channel selection is not
    buf.set_pixels(oiio.ROI(0, w, 0, h), np.ascontiguousarray(rgb, dtype=np.float32))
    if not buf.write(str(path)):
        raise FigureError(f"{path}: {buf.geterror()}")
    return path


def luminance(rgb):
    """Rec. 709 luminance of an (h, w, 3) array."""
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


def signed_exr(diff, path, positive=(1.0, 0.55, 0.12), negative=(0.2, 0.5, 1.0)):
    """A signed difference drawn as light: luminance above zero in orange, below zero in blue."""
    y = luminance(diff)[..., None]
    rgb = np.maximum(y, 0) * np.array(positive) + np.maximum(-y, 0) * np.array(negative)
    return write_exr(rgb, path)


def srgb_to_linear(v):
    """sRGB-encoded values in [0, 1] to linear (IEC 61966-2-1), the compositor's inverse."""
    v = np.asarray(v, dtype=np.float64)
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


def median_filter(y, radius):
    """Each pixel of a 2-D array the median of the (2 radius + 1)^2 pixels around it (edges
    clamped): noise is smoothed and a single firefly vanishes instead of spreading."""
    k = 2 * radius + 1
    padded = np.pad(y, radius, mode="edge")
    windows = np.lib.stride_tricks.sliding_window_view(padded, (k, k))
    return np.median(windows.reshape(*y.shape, k * k), axis=-1)


def diverging_exrs(diffs, paths, radius=0, cmap="RdBu_r", percentile=99.0):
    """Signed differences drawn with one diverging colour map and one scale: zero white
    (never dark on the slide's dark ground), red above zero, blue below, full colour at the
    percentile of |luminance| over all of them; each luminance median-filtered over radius
    pixels around it. Returns (paths, the scale)."""
    from matplotlib import colormaps
    ys = [median_filter(luminance(d), radius) if radius else luminance(d) for d in diffs]
    scale = max(float(np.percentile(np.abs(np.concatenate([y.ravel() for y in ys])), percentile)),
                1e-6)
    for y, path in zip(ys, paths):
        srgb = colormaps[cmap](np.clip(0.5 + 0.5 * y / scale, 0.0, 1.0))[..., :3]
        write_exr(srgb_to_linear(srgb), path)  # the compositor sRGB-encodes it back
    return paths, scale


def layer(exr, name):
    """One layer of an EXR ('' is the beauty), with a clear error when it is missing."""
    layers = read_layers(exr)
    if name not in layers:
        raise FigureError(f"{exr}: no layer '{name}' (has {', '.join(sorted(layers))})")
    return layers[name]


def check_sum(exr, names, tol=1e-4, total=""):
    """Fail unless the named AOV layers sum to the layer total (the beauty by default) in every
    pixel and channel.

    Why: the slide claims beauty = sum of its panels; this proves it on the very EXR the panels
    come from (relative tolerance, with an absolute floor of 1 for dark pixels)."""
    layers = read_layers(exr)
    missing = [n for n in [*names, total] if n not in layers]
    if missing:
        raise FigureError(f"{exr}: no layer {', '.join(missing)}")
    beauty = layers[total]
    summed = sum(layers[n] for n in names)
    worst = float((np.abs(summed - beauty) / np.maximum(np.abs(beauty), 1.0)).max())
    if not worst <= tol:
        raise FigureError(f"{exr}: {' + '.join(names)} differs from {total or 'the beauty'} by {worst:.3g} "
                          f"(relative, worst pixel) > {tol}: the slide's sum would lie")
    return worst


def check_nonzero(exr, name, what, min_mean=1e-3):
    """Fail unless the layer's mean luminance is at least min_mean: the panel shows something."""
    mean = float(luminance(layer(exr, name)).mean())
    if not mean >= min_mean:
        raise FigureError(f"{exr}: '{name or 'beauty'}' ({what}) has mean luminance {mean:.3g} "
                          f"< {min_mean}: the panel would be black")
    return mean


def check_zero(exr, name, what):
    """Fail unless the layer is exactly zero in every pixel."""
    peak = float(np.abs(layer(exr, name)).max())
    if peak != 0.0:
        raise FigureError(f"{exr}: '{name}' ({what}) reaches {peak:.3g}, expected exactly 0")
    return peak


def check_close(a, b, rtol, what, scale=None):
    """Fail unless the channel means of arrays a and b agree to rtol of scale (default: b's
    mean luminance).

    For two estimates of one quantity from different samples: their means agree, their pixels
    need not."""
    scale = max(float(luminance(b).mean()) if scale is None else scale, 1e-6)
    diff = np.abs(a.reshape(-1, 3).mean(axis=0) - b.reshape(-1, 3).mean(axis=0)).max() / scale
    if not diff <= rtol:
        raise FigureError(f"{what}: the means differ by {diff:.3g} of {scale:.3g} (relative) > {rtol}")
    return float(diff)


def enumerated_paths(max_events=4):
    """Every path E x1..xk L with k <= max_events events from D, G, S (compact notation): the
    paths on which a label is compared with what its panel shows."""
    return ["E" + "".join(p) + "L" for k in range(max_events + 1)
            for p in itertools.product("DGS", repeat=k)]


_accepts_cache = {}


def lpe_accepts(lightpath, expr, paths):
    """The paths `lightpath lpe match` says expr accepts; FigureError when it refuses expr."""
    key = (expr, tuple(paths))
    if key not in _accepts_cache:
        proc = subprocess.run([lightpath, "lpe", "match", "--quiet", expr, *paths],
                              capture_output=True, text=True)
        if proc.returncode != 0:
            raise FigureError(f"'{expr}': lightpath lpe match refuses it (exit "
                              f"{proc.returncode}): {proc.stderr.strip()}")
        accepted = {line.split()[-1] for line in proc.stdout.splitlines()
                    if line.startswith("match ")}
        _accepts_cache[key] = accepted
    return _accepts_cache[key]


def check_label(lightpath, label, exr, layer_name, layer_expr, classes):
    """Fail unless a panel's printed LPE is what the panel shows, by `lightpath lpe match`.

    A panel of one AOV (layer_expr given): the label accepts exactly the paths the AOV's own
    expression accepts, on every path of enumerated_paths(). A beauty (layer_expr None): for each
    (name, expr) of classes whose AOV in exr is non-zero somewhere, the label accepts at least one
    path of that class: a label that misses light the image holds is refused."""
    paths = enumerated_paths()
    said = lpe_accepts(lightpath, label, paths)
    if layer_expr is not None:
        meant = lpe_accepts(lightpath, layer_expr, paths)
        if said != meant:
            extra, missed = sorted(said - meant, key=len), sorted(meant - said, key=len)
            raise FigureError(f"{exr}: the '{layer_name}' panel is labelled '{label}', but its AOV "
                              f"is '{layer_expr}': the label " +
                              (f"adds {', '.join(extra[:4])}" if extra else "") +
                              (" and " if extra and missed else "") +
                              (f"misses {', '.join(missed[:4])}" if missed else ""))
        return
    for name, expr in classes:
        if not np.any(layer(exr, name)):
            continue
        held = lpe_accepts(lightpath, expr, paths)
        if not held & said:
            raise FigureError(f"{exr}: the beauty holds {name} light {expr} (e.g. "
                              f"{', '.join(sorted(held, key=len)[:3])}), but its label '{label}' "
                              "accepts none of those paths")


def check_caption_objects(caption, scene_toml, kinds=("wall", "floor", "ceiling", "ball")):
    """Fail when the caption names a kind of object ('the walls', 'the red ball') the scene does
    not have as often as it says: the objects whose names hold the kind must be at least one
    for the singular and two for the plural. 'lamp' is any light of the scene."""
    scene = tomllib.loads(Path(scene_toml).read_text())
    names = [o.get("name", "") for key in ("spheres", "planes", "triangles", "meshes")
             for o in scene.get(key, [])]
    counts = {kind: sum(kind in n for n in names) for kind in kinds}
    counts["lamp"] = len(scene.get("lights", []))
    for kind, have in counts.items():
        for m in re.finditer(rf"\b{kind}(s?)\b", caption):
            need = 2 if m.group(1) else 1
            if have < need:
                raise FigureError(f"the caption says '{m.group(0)}', but {scene_toml} has {have} "
                                  f"{kind}(s) (objects: {', '.join(names)})")
