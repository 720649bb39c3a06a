#!/usr/bin/env python3
"""Writes the small meshes that umbra's scenes use. They are made here, by this
script, so they carry no outside licence: run it to remake them (the output is
deterministic).

  icosphere.obj   a sphere of 320 triangles (an icosahedron split twice): closed, genus 0
  torus.obj       a torus of 24 x 12 quads: closed, genus 1
  open_box.obj    a box without its lid: 4 border edges, one hole (per-triangle fallback)
  pair.off        two closed pieces in one file: a cube and a tetrahedron
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def write_obj(name, points, faces, comment):
    with open(os.path.join(HERE, name), "w") as out:
        out.write(f"# {comment}\n# made by scenes/meshes/make_meshes.py\n")
        for p in points:
            out.write("v %.9f %.9f %.9f\n" % p)
        for f in faces:
            out.write("f " + " ".join(str(i + 1) for i in f) + "\n")


def icosphere(levels):
    t = (1 + 5 ** 0.5) / 2
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
              (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    points = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in points]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
             (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                p = [(x + y) / 2 for x, y in zip(points[a], points[b])]
                n = math.sqrt(sum(c * c for c in p))
                points.append(tuple(c / n for c in p))
                middle[key] = len(points) - 1
            return middle[key]

        finer = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = finer
    return points, faces


def torus(n, m, big, small):
    points, faces = [], []
    for i in range(n):
        for j in range(m):
            u, v = 2 * math.pi * i / n, 2 * math.pi * j / m
            points.append(((big + small * math.cos(v)) * math.cos(u), (big + small * math.cos(v)) * math.sin(u),
                           small * math.sin(v)))
    at = lambda i, j: (i % n) * m + (j % m)
    for i in range(n):
        for j in range(m):
            faces.append((at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)))
    return points, faces


def box(lo, hi):
    points = [(hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]) for i in range(8)]
    faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    return points, faces


def main():
    write_obj("icosphere.obj", *icosphere(2), "a unit icosphere, 320 triangles")
    write_obj("torus.obj", *torus(24, 12, 1.0, 0.35), "a torus, radii 1 and 0.35, 288 quads")
    points, faces = box((-1, -1, -1), (1, 1, 1))
    write_obj("open_box.obj", points, [f for f in faces if f != (4, 5, 7, 6)], "a box without its lid (z = 1)")
    cube_points, cube_faces = box((-1, -1, -1), (0, 0, 0))
    tet_points = [(0.3, 0.3, -1.0), (1.0, 0.3, -1.0), (0.3, 1.0, -1.0), (0.3, 0.3, -0.3)]
    tet_faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    with open(os.path.join(HERE, "pair.off"), "w") as out:
        out.write("OFF\n# a cube and a tetrahedron, two closed pieces\n# made by scenes/meshes/make_meshes.py\n")
        out.write(f"{len(cube_points) + len(tet_points)} {len(cube_faces) + len(tet_faces)} 0\n")
        for p in cube_points + tet_points:
            out.write("%g %g %g\n" % p)
        for f in cube_faces:
            out.write(f"{len(f)} " + " ".join(map(str, f)) + "\n")
        for f in tet_faces:
            out.write("3 " + " ".join(str(i + len(cube_points)) for i in f) + "\n")


if __name__ == "__main__":
    main()
