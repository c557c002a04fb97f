"""A PNG file of the figure's pixels, written fast: it runs on every update of a live figure.

>>> import numpy as np
>>> encode_png(np.zeros((2, 3, 4), np.uint8))[:8]
b'\\x89PNG\\r\\n\\x1a\\n'
"""
from __future__ import annotations

import struct
import sys
import zlib

import numpy as np

__all__ = ["encode_png", "PNG_WITH_ALPHA"]

# In the browser edition (Pyodide: sys.platform "emscripten"), dropping the alpha channel is most
# of a PNG's cost (a strided copy: 17 ms a frame there, against 7-8 ms for an RGBA PNG whose rows
# are plain copies); the file is ~13 % larger, which costs nothing between a web worker and its
# page. Elsewhere RGB is as fast (7.5 vs 8 ms on the desktop) and smaller.
PNG_WITH_ALPHA = sys.platform == "emscripten"


def encode_png(rgba: np.ndarray, alpha: bool = False) -> bytes:
    """A PNG file of an RGBA pixel array (H, W, 4); the alpha channel is kept
    only when ``alpha`` is True.

    Written out by hand because it runs on every update: no per-row filters
    and the fastest zlib level take ~6 ms for 600x600 pixels, against ~12 ms
    for Pillow's default PNG writer.
    """
    height, width = rgba.shape[:2]
    channels = 4 if alpha else 3
    rows = np.zeros((height, 1 + channels * width), np.uint8)  # each row: filter byte 0, then pixels
    rows[:, 1:] = rgba[..., :channels].reshape(height, -1)

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    color_type = 6 if alpha else 2                               # 8-bit RGBA or RGB
    header = struct.pack(">IIBBBBB", width, height, 8, color_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
            + chunk(b"IDAT", zlib.compress(rows.tobytes(), 1)) + chunk(b"IEND", b""))
