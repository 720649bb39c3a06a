"""What the Python module's tests share: the umbra command they compare
with (UMBRA), the source tree (UMBRA_SOURCE_DIR), and its pictures read back.
CTest sets both variables and PYTHONPATH to the build's python/ folder."""

import os
import pathlib
import subprocess

import numpy as np
import pytest
from PIL import Image

SOURCE = pathlib.Path(os.environ.get("UMBRA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
UMBRA = os.environ.get("UMBRA", str(SOURCE / "build" / "umbra"))
ASSIMP_MODELS = pathlib.Path("/usr/share/assimp/models")


def command_picture(tmp_path, path, *options, mask=False):
    """umbra render's picture of `path` as an (h, w, 4) array (alpha 255
    where the PNG has none), and with mask=True its --mask too."""
    out, mask_out = tmp_path / "command.png", tmp_path / "command-mask.png"
    args = [UMBRA, "render", str(path), "-o", str(out), *options]
    if mask:
        args += ["--mask", str(mask_out)]
    subprocess.run(args, check=True, capture_output=True)
    image = np.asarray(Image.open(out).convert("RGBA"))
    return (image, np.asarray(Image.open(mask_out))) if mask else image


def cube(open_top=False):
    """A unit cube, faces outward: 8 vertices, 12 triangles (10 with its top open)."""
    vertices = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=np.float64)
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    if open_top:
        quads.remove((4, 5, 7, 6))
    faces = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))], dtype=np.int64)
    return vertices, faces


@pytest.fixture
def models():
    if not ASSIMP_MODELS.is_dir():
        pytest.skip("needs Debian's assimp-testmodels (build.sh test installs it)")
    return ASSIMP_MODELS
