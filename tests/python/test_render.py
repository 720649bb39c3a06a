"""umbra.render: the command's pictures, from paths and from arrays."""

import threading

import numpy as np
import pytest

import umbra
from conftest import SOURCE, cube, command_picture


def test_a_scene_renders_as_the_command_draws_it(tmp_path):
    image = umbra.render(SOURCE / "scenes" / "demo.scene")
    assert image.shape == (800, 800, 4) and image.dtype == np.uint8
    assert np.array_equal(image, command_picture(tmp_path, SOURCE / "scenes" / "demo.scene"))


def test_a_mesh_file_renders_as_the_command_draws_it_with_the_same_options(tmp_path, models):
    path = models / "OFF" / "Wuson.off"
    image = umbra.render(path, (320, 240), camera_azimuth=80, light_elevation=40, background="white")
    assert image.shape == (240, 320, 4)
    expected = command_picture(tmp_path, path, "--size", "320x240", "--camera-azimuth", "80", "--light-elevation", "40",
                               "--background", "white")
    assert np.array_equal(image, expected)


def test_arrays_render_as_the_file_they_were_read_from(tmp_path, models):
    path = models / "OFF" / "Wuson.off"
    mesh = umbra.load(path)
    assert mesh.polygons == len(mesh.faces)  # a file of triangles: read as written
    image = umbra.render((mesh.vertices, mesh.faces), (300, 300))
    assert np.array_equal(image, command_picture(tmp_path, path, "--size", "300x300"))


def test_an_object_with_vertices_and_faces_renders_as_its_arrays():
    class TrimeshLike:  # trimesh.Trimesh and Open3D's meshes have these two attributes
        def __init__(self, vertices, faces):
            self.vertices, self.faces = vertices, faces

    vertices, faces = cube()
    from_object = umbra.render(TrimeshLike(vertices, faces), (200, 200), up="+z")
    assert np.array_equal(from_object, umbra.render((vertices, faces), (200, 200), up="+z"))
    assert len(np.unique(from_object.reshape(-1, 4), axis=0)) > 10  # a shaded cube on a floor, not a blank


def test_arrays_are_read_through_their_strides_and_types():
    vertices, faces = cube()
    plain = umbra.render((vertices, faces), (160, 120))
    # Every other row of a larger array, Fortran order, float32 and uint16: the same mesh.
    spaced = np.zeros((16, 3))
    spaced[::2] = vertices
    assert np.array_equal(umbra.render((spaced[::2], np.asfortranarray(faces)), (160, 120)), plain)
    assert np.array_equal(umbra.render((vertices.astype(np.float32), faces.astype(np.uint16)), (160, 120)), plain)
    assert np.array_equal(umbra.render((vertices.astype(">f8"), faces), (160, 120)), plain)


@pytest.mark.filterwarnings("error")  # a scene of the cube [-1,1]^3, as scenes are made
def test_mask_matches_the_command_and_depth_is_the_distance_along_the_view(tmp_path):
    scene = tmp_path / "plane.scene"
    # A floor at z = 0 seen straight down from z = 5: its depth is 5 everywhere it is seen.
    scene.write_text("light 0.3 0.2 3\n"
                     "camera eye 0 0 5 target 0 0 0 up 0 1 0 fovy 30\n"
                     "triangle -1 -1 0  1 -1 0  1 1 0\n"
                     "triangle -1 -1 0  1 1 0  -1 1 0\n"
                     "sphere 0 0 0.6 0.25\n")
    image, mask, depth = umbra.render(scene, (101, 101), mask=True, depth=True)
    expected_image, expected_mask = command_picture(tmp_path, scene, "--size", "101x101", mask=True)
    assert np.array_equal(image, expected_image) and np.array_equal(mask, expected_mask)
    assert mask.shape == depth.shape == (101, 101) and depth.dtype == np.float32
    assert np.all(np.isinf(depth[mask == 128])) and np.all(np.isfinite(depth[mask != 128]))
    # The sphere's top, 5 - 0.85 away, at the centre; the floor off to the side.
    assert depth[50, 50] == pytest.approx(4.15, abs=1e-3)
    assert depth[50, 80] == pytest.approx(5.0, abs=1e-3)
    assert depth[0, 0] == np.inf


def test_the_mask_alone_comes_after_the_image():
    image, mask = umbra.render(SOURCE / "scenes" / "demo.scene", (64, 64), mask=True)
    assert image.shape == (64, 64, 4) and mask.shape == (64, 64) and set(np.unique(mask)) <= {0, 128, 255}


def test_options_change_the_picture_and_bad_ones_say_so_in_python_words():
    vertices, faces = cube()
    default = umbra.render((vertices, faces), (96, 96))
    assert not np.array_equal(default, umbra.render((vertices, faces), (96, 96), camera_azimuth=120))
    transparent = umbra.render((vertices, faces), (96, 96), background="transparent", floor="none")
    assert transparent[0, 0, 3] == 0 and transparent[48, 48, 3] == 255
    with pytest.raises(TypeError, match="unknown keyword argument camera_azimth"):
        umbra.render((vertices, faces), camera_azimth=3)
    with pytest.raises(umbra.OptionError, match="camera_elevation"):
        umbra.render((vertices, faces), camera_elevation=95)
    with pytest.raises(umbra.OptionError, match="light"):
        umbra.render((vertices, faces), light=(1, 2, 3), light_azimuth=10)


@pytest.mark.parametrize("vertices, faces, message", [
    (np.zeros((4, 2)), np.array([[0, 1, 2]]), r"arrays: vertices must be an \(n, 3\) array of points, got shape \(4, 2\)"),
    (np.zeros(12), np.array([[0, 1, 2]]), r"arrays: vertices must be a two-dimensional array, got shape \(12,\)"),
    (np.array([[0, 0, 0], [1, 0, 0], [0, np.nan, 0]]), np.array([[0, 1, 2]]), r"arrays: vertices\[2, 1\] is NaN"),
    (np.array([[0, 0, 0], [1, 0, 0], [0, np.inf, 0]]), np.array([[0, 1, 2]]), r"vertices\[2, 1\] is infinite"),
    (np.eye(3), np.array([[0, 1, 3]]), r"arrays: faces\[0, 2\] is 3, but vertices has 3 rows"),
    (np.eye(3), np.array([[0, -1, 2]]), r"faces\[0, 1\] is -1, but vertices has 3 rows"),
    (np.eye(3), np.array([[0.0, 1.0, 2.0]]), r"faces must hold integers \(vertex indices\), got float64"),
    (np.eye(3), np.array([[0, 1]]), r"faces must be an \(m, 3\) array"),
    (np.array([["a", "b", "c"]]), np.array([[0, 1, 2]]), r"vertices must hold numbers"),
])
def test_bad_arrays_raise_a_clear_error(vertices, faces, message):
    with pytest.raises(umbra.InputError, match=message):
        umbra.render((vertices, faces), (32, 32))
    with pytest.raises(umbra.InputError, match=message):
        umbra.check((vertices, faces))


def test_a_bad_file_raises_with_its_location(tmp_path):
    scene = tmp_path / "bad.scene"
    scene.write_text("light 0 0 2\nsphere 0 0 0 O.5\n")
    with pytest.raises(umbra.InputError, match=r"bad.scene:2:\d+: .*radius"):
        umbra.render(scene)
    with pytest.raises(umbra.InputError, match="cannot"):
        umbra.render(tmp_path / "missing.obj")
    with pytest.raises(TypeError, match="a mesh is a path"):
        umbra.render(42)


def test_a_renderer_keeps_one_context_and_refuses_work_once_closed():
    vertices, faces = cube()
    with umbra.Renderer() as renderer:
        first = renderer.render((vertices, faces), (64, 64))
        assert np.array_equal(renderer.render((vertices, faces), (64, 64)), first)
        assert renderer.platform  # the GL it drew with
        assert renderer.render((vertices, faces), (80, 40)).shape == (40, 80, 4)  # another size, the same renderer
    with pytest.raises(RuntimeError, match="closed"):
        renderer.render((vertices, faces), (64, 64))


def test_threads_render_at_once_and_get_the_same_pictures():
    vertices, faces = cube()
    expected = umbra.render((vertices, faces), (120, 90))
    shared = umbra.Renderer()
    results = []

    def draw(renderer):
        for _ in range(3):
            results.append(renderer.render((vertices, faces), (120, 90)) if renderer else umbra.render((vertices, faces), (120, 90)))

    threads = [threading.Thread(target=draw, args=(r,)) for r in (None, None, shared, shared)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    shared.close()
    assert len(results) == 12 and all(np.array_equal(r, expected) for r in results)


def test_a_mesh_that_is_not_closed_warns():
    vertices, faces = cube(open_top=True)
    with pytest.warns(umbra.UmbraWarning, match=r"arrays: mesh \"arrays\" is open, 1 hole: edge-multiplicity volume"):
        umbra.render((vertices, faces), (64, 64))


# The GL does not survive fork(): a child forked by multiprocessing (its
# default on Linux) after its parent drew once hung forever in render(). It
# now refuses at once, saying how to start workers; a child whose parent has
# not drawn draws. Each case in a fresh interpreter, bounded in time.
FORKED = """
import multiprocessing, sys, umbra
def child(queue):
    try:
        queue.put(umbra.render(sys.argv[1], (24, 24)).shape)
    except RuntimeError as e:
        queue.put(str(e))
if __name__ == "__main__":
    if sys.argv[2] == "drew":
        umbra.render(sys.argv[1], (24, 24))
    context = multiprocessing.get_context(sys.argv[3])
    queue = context.Queue()
    worker = context.Process(target=child, args=(queue,))
    worker.start()
    print(queue.get(timeout=60))
    worker.join(60)
"""


@pytest.mark.parametrize("parent, start, said", [
    ("drew", "fork", "umbra cannot draw in a process forked from one that had drawn"),
    ("drew", "spawn", "(24, 24, 4)"),
    ("did not draw", "fork", "(24, 24, 4)"),
])
def test_a_forked_worker_draws_or_says_why_it_cannot(tmp_path, parent, start, said):
    import subprocess
    import sys
    script = tmp_path / "forked.py"
    script.write_text(FORKED)
    run = subprocess.run([sys.executable, str(script), str(SOURCE / "scenes" / "meshes" / "torus.obj"), parent, start],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert run.stdout.startswith(said), run.stdout


def test_views_are_the_commands_files_as_stacked_arrays(tmp_path, models):
    """render(views=N, passes=...) returns what umbra render --views N
    --passes ... writes, view by view, and its cameras as transforms.json."""
    import json
    import subprocess
    from PIL import Image
    from conftest import UMBRA

    path = models / "OFF" / "Wuson.off"
    passes = ("depth", "normal", "object", "shadow")
    got = umbra.render(path, (64, 48), views=3, passes=passes, camera_elevation=20)
    out = tmp_path / "views"
    subprocess.run([UMBRA, "render", str(path), "--size", "64x48", "--views", "3", "--passes", ",".join(passes),
                    "--camera-elevation", "20", "-o", str(out)], check=True, capture_output=True)
    assert got["color"].shape == (3, 48, 64, 4) and got["color"].dtype == np.uint8
    assert got["depth"].shape == (3, 48, 64) and got["depth"].dtype == np.float32
    assert got["normal"].shape == (3, 48, 64, 3) and got["normal"].dtype == np.float32
    assert got["cameras"] == json.loads((out / "transforms.json").read_text())
    for i in range(3):
        stem = out / f"{i:03d}"
        assert np.array_equal(got["color"][i], np.asarray(Image.open(f"{stem}.png").convert("RGBA")))
        assert np.array_equal(got["object"][i], np.asarray(Image.open(f"{stem}.object.png")))
        assert np.array_equal(got["shadow"][i], np.asarray(Image.open(f"{stem}.shadow.png")))
        channels, depth = umbra._umbra.read_exr(f"{stem}.depth.exr")
        assert channels == ["Z"] and np.array_equal(got["depth"][i], depth[..., 0])
        channels, normal = umbra._umbra.read_exr(f"{stem}.normal.exr")
        assert channels == ["B", "G", "R"] and np.array_equal(got["normal"][i], normal[..., ::-1])
        assert np.array_equal(got["object"][i] == 255, np.isfinite(got["depth"][i]))
        assert got["object"][i].sum() > 0


def test_a_turntable_is_the_commands_frames_as_one_array(tmp_path, models):
    """render(turntable=N, orbit=...) returns the frames umbra render
    --turntable N --orbit ... draws, and their cameras and lights."""
    import json
    import subprocess
    from PIL import Image
    from conftest import UMBRA

    path = models / "OFF" / "Wuson.off"
    for orbit in ("model", "light"):
        got = umbra.render(path, (48, 32), turntable=4, orbit=orbit)
        out = tmp_path / orbit
        subprocess.run([UMBRA, "render", str(path), "--size", "48x32", "--turntable", "4", "--orbit", orbit, "-o", f"{out}/"],
                       check=True, capture_output=True)
        assert got["color"].shape == (4, 32, 48, 4) and set(got) == {"color", "cameras"}
        cameras = got["cameras"]
        assert cameras == json.loads((out / "transforms.json").read_text()) and cameras["umbra_turning"] == orbit
        for i in range(4):
            assert np.array_equal(got["color"][i], np.asarray(Image.open(out / f"{i:03d}.png").convert("RGBA")))
        # The orbiting light moves and the camera holds still; the turntable moves both about the model.
        poses = [frame["transform_matrix"] for frame in cameras["frames"]]
        lights = [frame["light_positions"] for frame in cameras["frames"]]
        assert lights[1] != lights[0] and (poses[1] == poses[0]) == (orbit == "light")
    with pytest.raises(TypeError, match="orbit says what turntable=N turns"):
        umbra.render(path, (16, 16), orbit="light")
    with pytest.raises(TypeError, match="views=N and turntable=N each say which pictures to draw"):
        umbra.render(path, (16, 16), views=2, turntable=2)
    with pytest.raises(umbra.OptionError, match='orbit takes "model" or "light", got "sun"'):
        umbra.render(path, (16, 16), turntable=2, orbit="sun")


def test_view_keywords_say_what_is_wrong_in_pythons_words():
    cube_mesh = cube()
    with pytest.raises(umbra.OptionError, match="passes takes depth, normal, object or shadow"):
        umbra.render(cube_mesh, (16, 16), views=2, passes=("colour",))
    with pytest.raises(umbra.OptionError, match="views_on takes ring or sphere"):
        umbra.render(cube_mesh, (16, 16), views=2, views_on="cube")
    with pytest.raises(TypeError, match="passes and views_on are for views=N"):
        umbra.render(cube_mesh, (16, 16), passes=("depth",))
    with pytest.raises(ValueError, match="views"):
        umbra.render(cube_mesh, (16, 16), views=0)
    arrays = umbra.render(cube_mesh, (16, 16), views=2)
    assert set(arrays) == {"color", "cameras"} and arrays["color"].shape == (2, 16, 16, 4)


def test_cameras_redraw_the_views_they_came_from(tmp_path, models):
    """cameras= (the returned "cameras", or a transforms.json's path) draws
    the same views again, at the file's size unless size is given."""
    import json

    path = models / "OFF" / "Wuson.off"
    first = umbra.render(path, (40, 30), views=2, passes=("depth", "shadow"))
    again = umbra.render(path, cameras=first["cameras"], passes=("depth", "shadow"))
    for key in ("color", "depth", "shadow"):
        assert np.array_equal(first[key], again[key]), key
    (tmp_path / "transforms.json").write_text(json.dumps(first["cameras"]))
    from_file = umbra.render(path, cameras=tmp_path / "transforms.json")
    assert np.array_equal(first["color"], from_file["color"])
    larger = umbra.render(path, (80, 60), cameras=first["cameras"])
    assert larger["color"].shape == (2, 60, 80, 4)
    with pytest.raises(TypeError, match="give one or the other"):
        umbra.render(path, views=2, cameras=first["cameras"])
    with pytest.raises(umbra.InputError, match="cameras: fl_x and fl_y must be one focal length"):
        umbra.render(path, cameras={**first["cameras"], "fl_x": 1.0})


def test_an_orthographic_picture_is_the_commands(tmp_path, models):
    path = models / "OFF" / "Wuson.off"
    image = umbra.render(path, (48, 32), orthographic=True)
    assert np.array_equal(image, command_picture(tmp_path, path, "--size", "48x32", "--orthographic"))
    views = umbra.render(path, (48, 32), views=2, orthographic=True, passes=("depth",))
    assert views["cameras"]["camera_model"] == "ORTHOGRAPHIC"
