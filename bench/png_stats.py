#!/usr/bin/env python3
"""Per picture that umbra render wrote with --mask: how much of the frame is
in shadow (mask 0: faces turned from the light or in shadow), how much is
pure black, and how much sees no surface (mask 128). Reads 8-bit RGB and grey
PNGs, as umbra writes them (png_pixels.py).

  png_stats.py IMAGE.png...   (each IMAGE.png beside its IMAGE.mask.png)
prints "NAME SHADOW BLACK BACKGROUND CLIPPED SPREAD": the first four as
fractions of the frame (CLIPPED: every channel at 98% white or above), and
SPREAD, in grey levels, how far the pixels in shadow (mask 0) spread: from
the 5th to the 95th percentile of their grey (the mean of the channels), 0
when under 1% of the frame is in shadow.
"""
import sys

from png_pixels import read_png


for image in sys.argv[1:]:
    w, h, ch, rgb = read_png(image)
    assert ch == 3, f"{image}: umbra writes RGB pictures unless the background is transparent"
    _, _, _, mask = read_png(image[:-len(".png")] + ".mask.png")
    n = w * h
    black = sum(1 for i in range(n) if rgb[3 * i] == 0 and rgb[3 * i + 1] == 0 and rgb[3 * i + 2] == 0)
    clipped = sum(1 for i in range(n) if min(rgb[3 * i:3 * i + 3]) >= 250)
    shadowed = sorted(sum(rgb[3 * i:3 * i + 3]) / 3 for i in range(n) if mask[i] == 0)
    spread = 0.0
    if len(shadowed) >= n // 100:
        spread = shadowed[int(0.95 * (len(shadowed) - 1))] - shadowed[int(0.05 * (len(shadowed) - 1))]
    print(f"{image} {mask.count(0) / n:.4f} {black / n:.4f} {mask.count(128) / n:.4f} {clipped / n:.4f} {spread:.1f}")
