#!/usr/bin/env python3
"""Pairs of pictures side by side, two pairs a row, in one PNG: to look at
umbra's staged pictures next to another tool's of the same files.

  side_by_side.py OUT.png LEFT.png RIGHT.png [LEFT.png RIGHT.png ...]

Each picture is shrunk by a whole factor to at most 240 pixels a side
(nearest pixel) and laid on grey; a missing or unreadable one leaves its
place grey. 8-bit grey, RGB or RGBA PNGs (alpha over white), with the
standard library alone.
"""
import struct
import sys
import zlib

CELL = 240


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body[:13])
            if depth != 8 or colour not in (0, 2, 6) or interlace:
                raise ValueError("only 8-bit grey, RGB or RGBA, not interlaced")
            channels = {0: 1, 2: 3, 6: 4}[colour]
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
        rows.append(line)
        previous = line
    def rgb(x, y):
        px = rows[y][x * channels:(x + 1) * channels]
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
        w, h, rgb = read_png(path)
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
