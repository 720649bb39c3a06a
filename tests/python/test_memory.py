"""Memory stays flat over many renders in one process: what a dataset
pipeline does (Open3D's offscreen renderer is known to leak until its
pictures come back blank)."""

import numpy as np

import umbra
from conftest import cube

RENDERS = 10_000
# A leak of 1 KiB a render would add 10 MB over the loop; the bound leaves
# room for the allocator's own slack, no more.
MOST_GROWTH_BYTES = 8 << 20


def resident_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * 4096


def test_memory_stays_flat_over_ten_thousand_renders():
    vertices, faces = cube()
    with umbra.Renderer() as renderer:
        first = renderer.render((vertices, faces), (32, 32))
        for _ in range(200):  # the context's, the allocator's and NumPy's first needs
            renderer.render((vertices, faces), (32, 32), mask=True)
        before = resident_bytes()
        for _ in range(RENDERS):
            image, mask = renderer.render((vertices, faces), (32, 32), mask=True)
        grown = resident_bytes() - before
    assert np.array_equal(image, first)  # the last picture is the first: nothing went blank
    assert grown < MOST_GROWTH_BYTES, f"grew {grown / 2**20:.1f} MiB over {RENDERS} renders"
