"""What a figure claims, checked on the EXR its panels come from before the figure is written.

Each check raises FigureError, which stops the generator: a slide that would lie is not drawn."""

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


def layer(exr, name):
    """One layer of an EXR ('' is the beauty), with a clear error when it is missing."""
    layers = read_layers(exr)
    if name not in layers:
        raise FigureError(f"{exr}: no layer '{name}' (has {', '.join(sorted(layers))})")
    return layers[name]


def check_sum(exr, names, tol=1e-4):
    """Fail unless the named AOV layers sum to the beauty in every pixel and channel.

    Why: the slide claims beauty = sum of its panels; this proves it on the very EXR the panels
    come from (relative tolerance, with an absolute floor of 1 for dark pixels)."""
    layers = read_layers(exr)
    missing = [n for n in names if n not in layers]
    if missing:
        raise FigureError(f"{exr}: no layer {', '.join(missing)}")
    beauty = layers[""]
    total = sum(layers[n] for n in names)
    worst = float((np.abs(total - beauty) / np.maximum(np.abs(beauty), 1.0)).max())
    if not worst <= tol:
        raise FigureError(f"{exr}: {' + '.join(names)} differs from the beauty by {worst:.3g} "
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
