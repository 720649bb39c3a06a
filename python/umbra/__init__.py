"""umbra: exact hard shadows, and whether a mesh is a closed 2-manifold.

The command's work as Python functions, with NumPy arrays in and out
(docs/python.md):

    render(mesh, size=None, **options)        -> (h, w, 4) uint8 array (800 x 800 unless a scene says)
    render(mesh, size, views=12, passes=("depth", "normal", "object", "shadow"))
    render(mesh, cameras="transforms.json", passes=(...))
                                              -> a dict of stacked arrays and the cameras
    check(mesh)                               -> the check --json report, a dict
    repair(mesh)                              -> vertices, faces, report
    load(path)                                -> a Mesh: vertices, faces, format, ...

A mesh is a file's path (a mesh file, or for render a scene file too), a
(vertices, faces) pair of arrays ((n, 3) numbers and (m, 3) vertex indices,
as trimesh holds them), or any object with .vertices and .faces (trimesh,
Open3D, umbra.Mesh). Errors carry umbra's message, FILE:LINE:COL included:
InputError for bad input, OptionError for a bad option, both ValueErrors.
"""

import json
import os
import re
import threading
import warnings as _warnings

import numpy as np

from . import _umbra
from ._umbra import InputError, OptionError

__all__ = ["render", "check", "repair", "load", "Renderer", "Mesh", "InputError", "OptionError", "UmbraWarning", "__version__"]

__version__ = _umbra.__version__  # the umbra command's own: umbra --version


class UmbraWarning(UserWarning):
    """What umbra read past or changed: a file's quirk, a mesh that is not closed."""


# The GL does not survive fork(): once Mesa (or a GPU's driver) has drawn in
# a process, its threads are gone from a child made by fork, and a render
# there waits for them forever, even in a new context. So a child forked
# after this process drew refuses to draw, and says how to start workers.
_drew = False            # this process has drawn
_drew_before_fork = False  # the process this one was forked from had


def _forked():
    global _drew_before_fork
    _drew_before_fork = _drew_before_fork or _drew


os.register_at_fork(after_in_child=_forked)


def _about_to_draw():
    global _drew
    if _drew_before_fork:
        raise RuntimeError("umbra cannot draw in a process forked from one that had drawn: the GL's threads do not survive "
                           "fork(). Start the workers with multiprocessing's 'spawn' or 'forkserver' method "
                           "(multiprocessing.get_context('spawn')), or draw nothing before the workers start")
    _drew = True


class Mesh:
    """A mesh file's content, as load() reads it: vertices (n, 3) float64 as
    written, faces (m, 3) uint32 (a polygon of k corners split into a fan of
    k - 2 triangles), polygon_of_face (m,), the file's polygon count, format,
    vertex_colors ((n, 3) float32 or None), material names and warnings. Any
    function here takes it as a mesh."""

    def __init__(self, fields):
        self.__dict__.update(fields)

    def __repr__(self):
        return f"umbra.Mesh({self.format}, {len(self.vertices)} vertices, {len(self.faces)} faces)"


def _path(path):
    """A path as _umbra takes it; a NUL byte would end it early in C's calls."""
    text = os.fsdecode(path)
    if "\0" in text:
        raise ValueError(f"{text!r}: a path cannot hold a NUL byte")
    return text


def _number(name, value, *, least=0.0, most=None, whole=False):
    """`value` as a float (an int where `whole`), from `least` to `most`; else
    a TypeError or ValueError in umbra's words, as the command's options get."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name} expects a number, got {type(value).__name__} {value!r}")
    number = float(value)
    if not np.isfinite(number) or number < least or (most is not None and number > most) or (whole and number != int(number)):
        kind = "a whole number" if whole else "a number"
        plain = lambda x: str(int(x)) if float(x).is_integer() else f"{x:g}"  # 1000000, not 1e+06
        span = f"from {plain(least)} to {plain(most)}" if most is not None else f"of {plain(least)} or more"
        raise ValueError(f"{name} expects {kind} {span}, got {value!r}")
    return int(number) if whole else number


def _size(name, size):
    """(width, height) in whole pixels, as --size takes them."""
    if not isinstance(size, (tuple, list, np.ndarray)) or len(size) != 2:
        raise TypeError(f"{name} expects (width, height) in pixels, got {size!r}")
    return (_number(f"{name}'s width", size[0], least=1, most=_umbra.largest_picture_side, whole=True),
            _number(f"{name}'s height", size[1], least=1, most=_umbra.largest_picture_side, whole=True))


def _source(mesh, name="arrays"):
    """The mesh as _umbra takes it: a path, or its arrays."""
    if isinstance(mesh, (str, bytes, os.PathLike)):
        return _path(mesh)
    if isinstance(mesh, tuple) and len(mesh) == 2:
        vertices, faces = mesh
    elif hasattr(mesh, "vertices") and hasattr(mesh, "faces"):
        vertices, faces = mesh.vertices, mesh.faces
        name = type(mesh).__name__
    else:
        raise TypeError("a mesh is a path, a (vertices, faces) pair of arrays, or an object with .vertices and .faces; "
                        f"got {type(mesh).__name__}")
    # Read in place where NumPy can hand the memory over as it is (any
    # strides, any of the usual number types); only another byte order is
    # converted first.
    arrays = []
    for what, values in (("vertices", vertices), ("faces", faces)):
        array = np.asarray(values)
        if array.dtype.kind not in "fiu":
            raise InputError(f"{name}: {what} must hold numbers, got {array.dtype}")
        if not array.dtype.isnative:
            array = array.astype(array.dtype.newbyteorder("="))
        arrays.append(array)
    return _umbra.ArraysMesh(arrays[0], arrays[1], name)


_OPTION = re.compile(r"--([a-z][a-z-]*)")


def _words(size, options):
    """render()'s keyword arguments as umbra render's options:
    camera_azimuth=20 is --camera-azimuth 20, eye=(1, 2, 3) is --eye 1,2,3,
    flat=True is --flat."""
    words = []
    if size is not None:
        width, height = _size("size", size)
        words = ["--size", f"{width}x{height}"]
    for key, value in options.items():
        if value is None or value is False:
            continue
        words.append("--" + key.replace("_", "-"))
        if value is True:
            continue
        if isinstance(value, (tuple, list, np.ndarray)):
            words.append(",".join(repr(float(v)) for v in value))
        else:
            words.append(str(value))
    return words


def _python_words(message):
    """An option's message in keyword arguments' words: --camera-azimuth is camera_azimuth."""
    return _OPTION.sub(lambda m: m.group(1).replace("-", "_"), message)


class Renderer:
    """One GL context kept for many renders (a context manager; close()
    frees it). Renders from several threads take turns; each releases the
    GIL while it draws. gl: "auto", "egl" or "osmesa", as umbra render --gl."""

    def __init__(self, gl="auto"):
        if not isinstance(gl, str):
            raise TypeError(f"gl expects a name (auto, egl or osmesa), got {type(gl).__name__} {gl!r}")
        self._native = _umbra.Renderer(gl)

    def render(self, mesh, size=None, *, mask=False, depth=False, views=None, views_on="ring", cameras=None, passes=(),
               turntable=None, orbit="model", **options):
        """The picture umbra render draws of `mesh`, as an (h, w, 4) uint8
        RGBA array; with mask=True also light 1's shadow mask ((h, w) uint8:
        255 lit, 0 in shadow or facing away, 128 no surface), with
        depth=True also the view depth ((h, w) float32: distance along the
        camera's axis, inf where no surface), returned after the image in
        that order. `options` are umbra render's options as keyword
        arguments (umbra render --help lists them): --camera-azimuth 20 is
        camera_azimuth=20, --eye 1,2,3 is eye=(1, 2, 3), --flat is
        flat=True, --background transparent is background="transparent".

        With views=N, N views of a mesh as umbra render --views N draws
        them (views_on="sphere" spreads them over the sphere), the model
        loaded once: a dict of arrays stacked over the views, "color"
        (N, h, w, 4) uint8, and for each of `passes` asked: "depth" (N, h,
        w) float32 (along the view axis, in the mesh file's units, inf off
        the model), "normal" (N, h, w, 3) float32 (unit, in the file's axes,
        0 off the model), "object" (N, h, w) uint8 (255 on the model),
        "shadow" (N, h, w) uint8 (light 1's mask; with several lights
        "shadows" (N, lights, h, w) too); and "cameras", the content of
        the transforms.json the command writes (docs/rendering.md).

        With cameras= a transforms.json's path or its content as a dict
        (the "cameras" a views render returned, or a dataset tool's), the
        views it names, as umbra render --cameras draws them, at its w x h
        unless size is given.

        With turntable=N, the N frames umbra render --turntable N draws (the
        model turning a whole turn under a studio that holds still; with
        orbit="light", the light orbiting instead, its shadow sweeping), as
        views are returned: "color" (N, h, w, 4) and "cameras", each
        frame's camera and light positions. Writing a video is the
        command's job.

        size: (width, height); unless given, a scene's size statement, or
        800 x 800."""
        return self._draw(mesh, size, mask, depth, options, views, views_on, cameras, passes, turntable, orbit)

    def _draw(self, mesh, size, mask, depth, options, views=None, views_on="ring", cameras=None, passes=(), turntable=None,
              orbit="model"):
        if "gl" in options:
            raise TypeError("gl is the Renderer's: umbra.Renderer(gl=...)")
        many = views is not None or cameras is not None or turntable is not None
        named = [name for name, given in (("views=N", views), ("cameras=", cameras), ("turntable=N", turntable)) if given is not None]
        if len(named) > 1:
            raise TypeError(f"{named[0]} and {named[1]} each say which pictures to draw: give one or the other")
        if orbit != "model" and turntable is None:
            raise TypeError("orbit says what turntable=N turns: render(mesh, size, turntable=24, orbit=\"light\")")
        if not many and (passes or views_on != "ring"):
            raise TypeError("passes and views_on are for views=N: render(mesh, size, views=12, passes=(\"depth\",))")
        if many and (mask or depth):
            raise TypeError("mask and depth are one picture's; with views=N ask passes=(\"shadow\", \"depth\")")
        if isinstance(passes, str):
            passes = (passes,)
        cameras_text, cameras_name = "", ""
        if isinstance(cameras, dict):
            cameras_text, cameras_name = json.dumps(cameras), "cameras"
        elif cameras is not None:
            cameras_name = _path(cameras)
            with open(cameras_name, encoding="utf-8") as file:
                cameras_text = file.read()
        _about_to_draw()
        try:
            if many:
                count = (_number("turntable", turntable, least=1, most=100000, whole=True) if turntable is not None
                         else 1 if views is None else _number("views", views, least=1, most=100000, whole=True))
                arrays, cameras, said = self._native.render_views(_source(mesh), _words(size, options), count, views_on,
                                                                  ",".join(passes), cameras_text, cameras_name,
                                                                  "" if turntable is None else orbit)
            else:
                image, mask_array, depth_array, said = self._native.render(_source(mesh), _words(size, options), mask, depth)
        except OptionError as e:
            message = _python_words(str(e))
            if message.startswith("unknown option"):
                raise TypeError("render() got an " + message.replace("unknown option", "unknown keyword argument", 1)) from None
            raise OptionError(message) from None
        for line in said:
            _warnings.warn(line, UmbraWarning, stacklevel=3)  # the caller of render()
        if many:
            if "shadows" in arrays:  # (N, lights, h, w): light 1's as "shadow", all of them only where there are several
                arrays["shadow"] = arrays["shadows"][:, 0].copy()
                if arrays["shadows"].shape[1] == 1:
                    del arrays["shadows"]
            arrays["cameras"] = json.loads(cameras)
            return arrays
        extra = [a for a, wanted in ((mask_array, mask), (depth_array, depth)) if wanted]
        return (image, *extra) if extra else image

    @property
    def platform(self):
        """The GL it draws with, once it has drawn: "EGL ..., Mesa's software device: ..."."""
        return self._native.platform

    def close(self):
        self._native.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


_renderers = threading.local()  # render()'s: one context per thread


def render(mesh, size=None, *, mask=False, depth=False, views=None, views_on="ring", cameras=None, passes=(), turntable=None,
           orbit="model", **options):
    if not hasattr(_renderers, "default"):
        _renderers.default = Renderer()
    return _renderers.default._draw(mesh, size, mask, depth, options, views, views_on, cameras, passes, turntable, orbit)


render.__doc__ = ("Renderer.render on this thread's own Renderer, made on first use (one GL context per thread).\n\n"
                  + Renderer.render.__doc__)


def check(mesh, *, time_limit=60.0, picture=None):
    """The report umbra check --json prints, as a dict, with "defects": every
    offending element as index arrays (border_edges (k, 2) vertex pairs,
    non_manifold_edges (k, 2), non_manifold_vertices (k,), duplicate_faces
    (k, 2) face and the face it repeats, degenerate_faces (k,),
    faces_to_flip (k,), self_intersections (k, 2) face pairs). Vertices and
    faces are numbered as the file or the arrays number them. The
    self-intersection search stops after time_limit seconds (0 skips it).
    With picture=(width, height), also "picture": the defect picture that
    umbra check --picture draws, an (h, w, 4) uint8 array."""
    import json
    size = None if picture is None else _size("picture", picture)
    time_limit = _number("time_limit", time_limit)
    source = _source(mesh)
    if size is not None:
        _about_to_draw()
    text, defects, image = _umbra.check(source, time_limit, size)
    report = json.loads(text)
    report["defects"] = defects
    if image is not None:
        report["picture"] = image
    return report


def repair(mesh, *, max_hole_edges=_umbra.max_hole_edges, merge_tolerance=0.0, time_limit=60.0):
    """umbra check --repair in memory: returns (vertices, faces, report),
    the repaired mesh as (n, 3) float64 and (m, 3) uint32 arrays and its
    check report (as check() returns it, without defects), with "changes":
    what the repair did, a line each."""
    import json
    max_hole_edges = _number("max_hole_edges", max_hole_edges, most=1_000_000, whole=True)
    merge_tolerance = _number("merge_tolerance", merge_tolerance)
    time_limit = _number("time_limit", time_limit)
    vertices, faces, changes, text = _umbra.repair(_source(mesh), max_hole_edges, merge_tolerance, time_limit)
    report = json.loads(text)
    report["changes"] = changes
    return vertices, faces, report


def load(path):
    """The mesh file at `path` as a Mesh (see Mesh)."""
    return Mesh(_umbra.load(_path(path)))
