"""The picture in docs/rendering.md's "Many views and their data": four
views of Khronos's two-cylinder engine, a row each, with their passes side
by side (colour, depth as grey from near to far, normals as colour
(n + 1) / 2, object, shadow), drawn through the Python module:

    PYTHONPATH=build/python python3 bench/views_picture.py docs/images/views.png
"""

import sys

import numpy as np
from PIL import Image

import umbra

ENGINE = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"
SIDE = 200

views = umbra.render(ENGINE, (SIDE, SIDE), views=4, passes=("depth", "normal", "object", "shadow"))
rows = []
for i in range(4):
    depth = views["depth"][i]
    seen = np.isfinite(depth)
    near, far = depth[seen].min(), depth[seen].max()
    grey = np.where(seen, 255 - 200 * (depth - near) / (far - near), 0).astype(np.uint8)
    normal = np.where(seen[..., None], (views["normal"][i] + 1) / 2 * 255, 0).astype(np.uint8)
    tiles = [views["color"][i][..., :3], np.dstack([grey] * 3), normal, np.dstack([views["object"][i]] * 3),
             np.dstack([views["shadow"][i]] * 3)]
    rows.append(np.hstack(tiles))
Image.fromarray(np.vstack(rows)).save(sys.argv[1])
