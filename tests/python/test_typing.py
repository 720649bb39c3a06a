"""The module's version, help and type stubs: umbra.__version__ is the
command's, help() says what render() does, and the stubs installed beside
the module (__init__.pyi, py.typed) agree with it and type-check a user's
code with mypy (Debian's mypy)."""

import ast
import inspect
import pathlib
import subprocess
import sys

import umbra
from conftest import UMBRA

STUBS = pathlib.Path(umbra.__file__).with_name("__init__.pyi")


def test_the_version_is_the_commands():
    said = subprocess.run([UMBRA, "--version"], check=True, capture_output=True, text=True).stdout
    assert said.splitlines()[0] == f"umbra {umbra.__version__}"


def test_help_says_what_render_does_with_views():
    text = inspect.getdoc(umbra.render)
    assert "this thread's own Renderer" in text and "views=N" in text and "cameras=" in text


def test_the_stubs_name_every_public_function_with_its_parameters():
    assert (STUBS.parent / "py.typed").exists()
    tree = ast.parse(STUBS.read_text())
    stubbed = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            args = node.args
            stubbed.setdefault(node.name, [a.arg for a in args.posonlyargs + args.args + args.kwonlyargs])
        elif isinstance(node, ast.ClassDef):
            stubbed.setdefault(node.name, [])
    for name in umbra.__all__:
        if name == "__version__":
            continue
        assert name in stubbed, f"{name} has no stub"
        value = getattr(umbra, name)
        if inspect.isfunction(value):
            parameters = [p for p, v in inspect.signature(value).parameters.items() if v.kind != v.VAR_KEYWORD]
            assert stubbed[name] == parameters, name


def run_mypy(tmp_path, code):
    (tmp_path / "uses.py").write_text(code)
    return subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-incremental", "--cache-dir", str(tmp_path / "cache"),
                           str(tmp_path / "uses.py")], capture_output=True, text=True,
                          env={"MYPYPATH": str(STUBS.parent.parent), "PATH": "/usr/bin:/bin"})


def test_mypy_reads_the_stubs_types_of_a_users_code(tmp_path):
    result = run_mypy(tmp_path, """
import umbra
image = umbra.render("m.obj", (64, 64))
reveal_type(image)
views = umbra.render("m.obj", (64, 64), views=12, passes=("depth", "normal"))
reveal_type(views["depth"])
with umbra.Renderer("egl") as r:
    reveal_type(r.render("m.obj", mask=True, depth=True))
""")
    assert result.returncode == 0, result.stdout + result.stderr
    revealed = [line.split("Revealed type is ")[1] for line in result.stdout.splitlines() if "Revealed type is" in line]
    assert "numpy._typing._8Bit" in revealed[0] and revealed[0].startswith('"numpy.ndarray')
    assert "numpy.floating[numpy._typing._32Bit]" in revealed[1]
    assert revealed[2].startswith('"Tuple[') and revealed[2].count("numpy.ndarray") == 3


def test_mypy_finds_a_misused_keyword(tmp_path):
    result = run_mypy(tmp_path, """
import umbra
umbra.render("m.obj", views="twelve")
umbra.render("m.obj", (64, 64), views=3, passes=("colour",))
""")
    assert result.returncode == 1
    assert result.stdout.count("error:") == 2, result.stdout
