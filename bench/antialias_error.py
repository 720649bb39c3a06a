"""How close antialiased pictures come to a finer reference, at edges.

    python3 bench/antialias_error.py REFERENCE.png FACTOR PICTURE.png...

REFERENCE is FACTOR times each picture's size along a side; it is
box-filtered down by FACTOR (each FACTOR x FACTOR block averaged). An edge
pixel is one whose block in REFERENCE is not uniform (some channel spans
more than 2 levels): its footprint holds an edge. Prints, per picture, the
mean over edge pixels of the largest channel difference from the filtered
reference, in levels of 255, and over the other pixels.
"""
import sys

from png_pixels import read_png


def main():
    ref_path, factor, pictures = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    rw, rh, rc, ref = read_png(ref_path)
    w, h = rw // factor, rh // factor
    filtered, edge = [], []
    for y in range(h):
        for x in range(w):
            block = [[ref[((y * factor + j) * rw + x * factor + i) * rc + c] for j in range(factor) for i in range(factor)]
                     for c in range(3)]
            filtered.append([sum(b) / len(b) for b in block])
            edge.append(max(max(b) - min(b) for b in block) > 2)
    print(f"{sum(edge)} edge pixels of {w * h}")
    for path in pictures:
        pw, ph, pc, pixels = read_png(path)
        if (pw, ph) != (w, h):
            sys.exit(f"{path}: {pw}x{ph}, the reference filtered is {w}x{h}")
        errors = [max(abs(pixels[k * pc + c] - filtered[k][c]) for c in range(3)) for k in range(w * h)]
        on = [e for e, is_edge in zip(errors, edge) if is_edge]
        off = [e for e, is_edge in zip(errors, edge) if not is_edge]
        print(f"{path}: edge pixels {sum(on) / max(1, len(on)):.2f} levels, others {sum(off) / max(1, len(off)):.2f}")


main()
