#!/usr/bin/env python3
"""One umbra.render of a mesh handed over as arrays, in a fresh process, as
a pipeline holding the mesh in memory makes it (bench/python_arrays.sh).

    python_render.py VERTICES.npy FACES.npy SECONDS_FILE

Appends the seconds the call took (GL context included) to SECONDS_FILE."""
import sys
import time

import numpy as np

import umbra

vertices, faces = np.load(sys.argv[1]), np.load(sys.argv[2])
start = time.perf_counter()
image = umbra.render((vertices, faces), (800, 800))
seconds = time.perf_counter() - start
assert image.shape == (800, 800, 4)
with open(sys.argv[3], "a") as out:
    out.write(f"{seconds:.3f}\n")
