#!/usr/bin/env python3
"""Per picture that umbra render wrote with --mask: how much of the frame is
in shadow (mask 0: faces turned from the light or in shadow), how much is
pure black, and how much sees no surface (mask 128). Reads 8-bit RGB and grey
PNGs, as umbra writes them, with the standard library alone.

  png_stats.py IMAGE.png...   (each IMAGE.png beside its IMAGE.mask.png)
prints "NAME SHADOW BLACK BACKGROUND CLIPPED SPREAD": the first four as
fractions of the frame (CLIPPED: every channel at 98% white or above), and
SPREAD, in grey levels, how far the pixels in shadow (mask 0) spread: from
the 5th to the 95th percentile of their grey (the mean of the channels), 0
when under 1% of the frame is in shadow.
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour in (0, 2), f"{path}: only 8-bit grey or RGB"
            channels = 1 if colour == 0 else 3
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1: line[i] = (line[i] + a) & 255
            elif kind == 2: line[i] = (line[i] + b) & 255
            elif kind == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        previous = line
    return width, height, channels, b"".join(rows)


for image in sys.argv[1:]:
    w, h, ch, rgb = read_png(image)
    _, _, _, mask = read_png(image[:-len(".png")] + ".mask.png")
    n = w * h
    black = sum(1 for i in range(n) if rgb[3 * i] == 0 and rgb[3 * i + 1] == 0 and rgb[3 * i + 2] == 0)
    clipped = sum(1 for i in range(n) if min(rgb[3 * i:3 * i + 3]) >= 250)
    shadowed = sorted(sum(rgb[3 * i:3 * i + 3]) / 3 for i in range(n) if mask[i] == 0)
    spread = 0.0
    if len(shadowed) >= n // 100:
        spread = shadowed[int(0.95 * (len(shadowed) - 1))] - shadowed[int(0.05 * (len(shadowed) - 1))]
    print(f"{image} {mask.count(0) / n:.4f} {black / n:.4f} {mask.count(128) / n:.4f} {clipped / n:.4f} {spread:.1f}")
