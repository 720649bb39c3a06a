"""docs/batch-checks.md's Dask recipe, run: a LocalCluster of Debian's
python3-distributed maps umbra.check and umbra.render over a folder of real
model files, in worker processes, and gets what the command gives."""

import json
import shutil
import subprocess

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
