"""docs/batch-checks.md's Dask recipe, run: a LocalCluster of Debian's
python3-distributed maps umbra.check and umbra.render over a folder of real
model files, in worker processes, and gets what the command gives."""

import json
import shutil
import subprocess
import sys

import numpy as np
import pytest

distributed = pytest.importorskip("distributed", reason="needs Debian's python3-distributed (build.sh test installs it)")

import umbra
from conftest import UMBRA, command_picture

MODELS = ["OFF/Wuson.off", "OFF/Cube.off", "PLY/cube.ply", "PLY/Wuson.ply", "STL/Spider_ascii.stl", "STL/Wuson.stl"]


def thumbnail(path):
    return umbra.render(path, (128, 96))


def test_a_local_cluster_checks_and_renders_a_folder_as_the_command_does(tmp_path, models):
    folder = tmp_path / "meshes"
    folder.mkdir()
    for name in MODELS:
        shutil.copy(models / name, folder / name.replace("/", "-"))
    paths = sorted(str(p) for p in folder.iterdir())
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        reports = client.gather(client.map(umbra.check, paths))
        pictures = client.gather(client.map(thumbnail, paths))
    run = subprocess.run([UMBRA, "check", "--json", str(folder)], capture_output=True, text=True)
    expected = {r["path"]: r for r in map(json.loads, run.stdout.splitlines())}
    assert len(reports) == len(expected) == len(MODELS)
    for path, report, picture in zip(paths, reports, pictures):
        del report["defects"]
        for r in (report, expected[path]):
            r["self_intersections"].pop("seconds")
        assert report == expected[path], path
        assert np.array_equal(picture, command_picture(tmp_path, path, "--size", "128x96")), path


def test_the_recipe_runs_as_the_docs_give_it(tmp_path, models):
    """The Python block of docs/batch-checks.md's Dask section, saved as a
    file and run as a user runs it: once pasted at a script's top level it
    failed in Dask's workers and then hung."""
    from conftest import SOURCE
    page = (SOURCE / "docs" / "batch-checks.md").read_text()
    section = page[page.index("### Dask"):]
    recipe = section[section.index("```python\n") + len("```python\n"):section.index("```", section.index("```python\n") + 10)]
    script = tmp_path / "solids.py"
    script.write_text(recipe)
    folder = tmp_path / "meshes"
    folder.mkdir()
    for name in ("STL/Spider_ascii.stl", "STL/Wuson.stl"):
        shutil.copy(models / name, folder / name.split("/")[1])
    # And a solid: a tetrahedron, its faces outward.
    corners = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    (folder / "tetrahedron.stl").write_text("solid t\n" + "".join(
        "facet normal 0 0 0\nouter loop\n" + "".join("vertex %g %g %g\n" % corners[k] for k in f) + "endloop\nendfacet\n"
        for f in faces) + "endsolid t\n")
    run = subprocess.run([sys.executable, str(script), str(folder)], capture_output=True, text=True, timeout=600, cwd=tmp_path)
    assert run.returncode == 0, run.stderr[-3000:]
    paths = sorted(str(p) for p in folder.glob("*.stl"))
    solids = [p for p in paths if umbra.check(p)["solid"]]
    expected = [f"{p} is a solid: (256, 256, 4) picture" for p in solids] + [f"{len(solids)} solids of {len(paths)} meshes"]
    assert run.stdout.splitlines() == expected
