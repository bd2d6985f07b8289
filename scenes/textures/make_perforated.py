#!/usr/bin/env python3
"""Writes perforated.png beside this script: a 32x32 8-bit RGBA tile of a perforated sheet, grey
(160) and opaque but for a round hole of radius 10 texels at its centre (alpha 0 inside, a
one-texel ramp at the rim). scenes/perforated-screen.toml cuts a screen out with it.
Run: python3 make_perforated.py
"""
import math
import struct
import zlib
from pathlib import Path

SIZE, RADIUS = 32, 10.0


def alpha(x, y):
    d = math.hypot(x + 0.5 - SIZE / 2, y + 0.5 - SIZE / 2)
    return round(255 * min(1.0, max(0.0, d - RADIUS + 0.5)))


rows = [[(160, 160, 160, alpha(x, y)) for x in range(SIZE)] for y in range(SIZE)]
raw = b"".join(b"\0" + bytes(c for px in row for c in px) for row in rows)
chunk = lambda kind, data: struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 6, 0, 0, 0)) +
       chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
(Path(__file__).resolve().parent / "perforated.png").write_bytes(png)
