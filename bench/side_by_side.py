#!/usr/bin/env python3
"""Pairs of pictures side by side, two pairs a row, in one PNG: to look at
umbra's staged pictures next to another tool's of the same files.

  side_by_side.py OUT.png LEFT.png RIGHT.png [LEFT.png RIGHT.png ...]

Each picture is shrunk by a whole factor to at most 240 pixels a side
(nearest pixel) and laid on grey; a missing or unreadable one leaves its
place grey. 8-bit grey, RGB or RGBA PNGs (alpha over white), with the
standard library alone (png_pixels.py reads them).
"""
import struct
import sys
import zlib

from png_pixels import read_png

CELL = 240


def pixel_reader(path):
    """(width, height, rgb(x, y)): alpha laid over white."""
    width, height, channels, pixels = read_png(path)
    def rgb(x, y):
        px = pixels[(y * width + x) * channels:(y * width + x + 1) * channels]
        if channels == 1: return (px[0],) * 3
        if channels == 3: return tuple(px)
        alpha = px[3] / 255
        return tuple(round(v * alpha + 255 * (1 - alpha)) for v in px[:3])
    return width, height, rgb


def write_png(path, width, height, pixels):
    raw = b"".join(b"\x00" + bytes(pixels[y * width * 3:(y + 1) * width * 3]) for y in range(height))
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


out, pictures = sys.argv[1], sys.argv[2:]
PAIRS_A_ROW = 2
rows = -(-len(pictures) // (2 * PAIRS_A_ROW))
width, height = 2 * PAIRS_A_ROW * (CELL + 4) + 4 * PAIRS_A_ROW, rows * (CELL + 6) + 6
pixels = bytearray([128] * (width * height * 3))
for k, path in enumerate(pictures):
    try:
        w, h, rgb = pixel_reader(path)
    except (OSError, ValueError, zlib.error):
        continue
    step = max(1, -(-max(w, h) // CELL))
    pair, column = k // 2, k % 2  # a pair's left and right
    x0 = 4 + (pair % PAIRS_A_ROW) * (2 * CELL + 12) + column * (CELL + 4)
    y0 = 6 + (pair // PAIRS_A_ROW) * (CELL + 6)
    for y in range(h // step):
        for x in range(w // step):
            at = ((y0 + y) * width + x0 + x) * 3
            pixels[at:at + 3] = bytes(rgb(x * step, y * step))
write_png(out, width, height, pixels)
