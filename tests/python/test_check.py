"""umbra.check, umbra.repair and umbra.load: the check's report, the repair
and the file's content, from paths and arrays."""

import json
import subprocess

import numpy as np
import pytest

import umbra
from conftest import SOURCE, UMBRA, cube

# Time measured, not found: differs from run to run.
TIMED = ("seconds",)


def without_times(report):
    report = dict(report)
    report["self_intersections"] = {k: v for k, v in report["self_intersections"].items() if k not in TIMED}
    return report


def command_report(path):
    run = subprocess.run([UMBRA, "check", "--json", str(path)], capture_output=True, text=True)
    assert run.returncode in (0, 1), run.stderr
    return json.loads(run.stdout)


def test_a_closed_cube_is_a_closed_manifold_with_no_defects():
    report = umbra.check(cube())
    assert report["closed_manifold"] and report["triangles"] == 12 and report["vertices"] == 8
    assert report["volume"] == pytest.approx(1.0)
    assert report["path"] == "arrays"
    assert all(len(a) == 0 for a in report["defects"].values())


def test_an_open_cube_names_its_four_border_edges():
    report = umbra.check(cube(open_top=True))
    assert not report["closed_manifold"] and report["border_edges"] == 4 and report["border_loops"] == 1
    edges = report["defects"]["border_edges"]
    assert edges.shape == (4, 2) and edges.dtype == np.uint32
    # The top square's sides: vertices 4, 5, 7, 6 round it.
    assert {frozenset(e) for e in edges.tolist()} == {frozenset(p) for p in ((4, 5), (5, 7), (7, 6), (6, 4))}


def test_every_defect_is_listed_where_the_printed_report_shows_five(tmp_path):
    # 8 separate triangles, each with 3 border edges: 24 in all.
    rng = np.random.default_rng(7)
    vertices = rng.random((24, 3))
    faces = np.arange(24).reshape(8, 3)
    report = umbra.check((vertices, faces))
    assert report["border_edges"] == 24 and report["defects"]["border_edges"].shape == (24, 2)
    assert len(report["examples"]["border_edges"]) == 5  # as check --json prints them
    assert set(report["defects"]["border_edges"].ravel().tolist()) == set(range(24))


def test_the_report_of_a_file_is_the_commands(models):
    for path in (models / "OFF" / "Wuson.off", models / "PLY" / "cube.ply", models / "OFF" / "Cube.off"):
        report = umbra.check(path)
        del report["defects"]
        assert without_times(report) == without_times(command_report(path)), path


def test_a_file_that_cannot_be_read_raises_its_located_error(tmp_path):
    broken = tmp_path / "broken.off"
    broken.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(umbra.InputError, match=r"broken.off:\d+"):
        umbra.check(broken)


def test_repair_fills_the_open_cube_and_says_so():
    vertices, faces, report = umbra.repair(cube(open_top=True))
    assert vertices.shape == (8, 3) and faces.shape == (12, 3) and faces.dtype == np.uint32
    assert report["closed_manifold"] and report["volume"] == pytest.approx(1.0)
    assert any("filled 1 hole" in line for line in report["changes"]), report["changes"]
    assert umbra.check((vertices, faces))["closed_manifold"]  # what it hands back checks as it reported


def test_repair_with_no_holes_to_fill_leaves_the_hole(tmp_path):
    vertices, faces, report = umbra.repair(cube(open_top=True), max_hole_edges=0)
    assert len(faces) == 10 and report["border_edges"] == 4


def test_load_reads_a_file_as_written(models):
    mesh = umbra.load(models / "PLY" / "cube.ply")
    assert mesh.vertices.shape[1] == 3 and mesh.faces.shape[1] == 3
    assert mesh.format.startswith("PLY")
    # Its quads, each split into two triangles.
    assert mesh.polygons == 6 and len(mesh.faces) == 12
    assert mesh.polygon_of_face.tolist() == [p for p in range(6) for _ in range(2)]
    report = umbra.check(mesh)
    assert report["triangles"] == 12


def test_load_of_a_missing_file_raises():
    with pytest.raises(umbra.InputError, match="nowhere.obj"):
        umbra.load("/nowhere.obj")


def test_the_defect_picture_comes_as_an_array_the_commands_size(tmp_path):
    report = umbra.check(cube(open_top=True), picture=(640, 480))
    picture = report["picture"]
    assert picture.shape == (480, 640, 4) and picture.dtype == np.uint8
    # The open cube's border, in the border edges' red, below the legend (whose swatch is red too).
    red = (picture[70:, :, 0] > 200) & (picture[70:, :, 1] < 80) & (picture[70:, :, 2] < 80)
    assert red.sum() > 200
    assert "picture" not in umbra.check(cube())


# Every bad argument is a ValueError or TypeError in umbra's words, before
# any work: NaN and negative numbers were taken, picture=(0, 0) failed
# inside the staged scene ("arrays (staged):10:30"), a path with a NUL byte
# was read as the part before it, and some errors were pybind11's dumps.
@pytest.mark.parametrize("call, error, said", [
    (lambda m: umbra.check(m, time_limit=float("nan")), ValueError, "time_limit expects a number of 0 or more, got nan"),
    (lambda m: umbra.check(m, time_limit=-1), ValueError, "time_limit expects a number of 0 or more, got -1"),
    (lambda m: umbra.check(m, picture=(0, 0)), ValueError, "picture's width expects a whole number from 1 to 16384, got 0"),
    (lambda m: umbra.check(m, picture="big"), TypeError, "picture expects (width, height) in pixels, got 'big'"),
    (lambda m: umbra.check(str(m) + "\0.txt"), ValueError, "a path cannot hold a NUL byte"),
    (lambda m: umbra.load(str(m) + "\0.txt"), ValueError, "a path cannot hold a NUL byte"),
    (lambda m: umbra.repair(m, max_hole_edges=-1), ValueError, "max_hole_edges expects a whole number from 0 to 1000000, got -1"),
    (lambda m: umbra.repair(m, merge_tolerance=float("inf")), ValueError, "merge_tolerance expects a number of 0 or more, got inf"),
    (lambda m: umbra.render(m, (float("nan"), 3)), ValueError, "size's width expects a whole number from 1 to 16384, got nan"),
    (lambda m: umbra.render(m, 3), TypeError, "size expects (width, height) in pixels, got 3"),
    (lambda m: umbra.Renderer(gl=5), TypeError, "gl expects a name (auto, egl or osmesa), got int 5"),
    (lambda m: umbra.Renderer(gl="vulkan"), ValueError, 'gl expects auto, egl or osmesa, got "vulkan"'),
])
def test_a_bad_argument_is_said_in_umbras_words(call, error, said):
    with pytest.raises(error) as raised:
        call(SOURCE / "scenes" / "meshes" / "torus.obj")
    assert said in str(raised.value)
    assert "incompatible" not in str(raised.value) and "(staged)" not in str(raised.value)
