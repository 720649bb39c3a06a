#!/usr/bin/env python3
"""The layer rules of docs/design.md, checked against the build's own targets.

Each argument is FOLDER=TARGET:LINKED, where LINKED is the comma-separated
list of what TARGET links (CMake's LINK_LIBRARIES); TARGET may be
TARGET,OTHER,... where the folder's files make several targets (tools/: the
command and its library umbra_picture), and linking any of them lets a
folder include the folder's headers. A file in FOLDER may
include headers of its own folder and of the folders whose targets TARGET
links, nothing else of the project; CGAL only in mesh/predicates and
mesh/check; OpenGL and its loaders only in render/. Prints every breach and
exits 1 if there is one.

  layer_includes.py SOURCE_DIR mesh/io=umbra_mesh_io:umbra_mesh_common,TBB::tbb ...
"""
import pathlib
import re
import sys

# System headers that belong to one layer alone: (pattern, folders allowed).
PRIVATE_LIBRARIES = [
    (re.compile(r"^CGAL/"), {"mesh/predicates", "mesh/check"}),
    (re.compile(r"^(glad/|GL/|GLFW/|EGL/)"), {"render"}),
]
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)


def main():
    source = pathlib.Path(sys.argv[1])
    layers = {}  # folder -> (target, linked targets)
    for arg in sys.argv[2:]:
        folder, rest = arg.split("=", 1)
        targets, linked = rest.split(":", 1)
        layers[folder] = (targets.split(","), {t for t in linked.split(",") if t})
    folder_of_target = {target: folder for folder, (targets, _) in layers.items() for target in targets}

    def layer_of(path):  # the deepest layer folder holding `path`
        best = None
        for folder in layers:
            if path.startswith(folder + "/") and (best is None or len(folder) > len(best)):
                best = folder
        return best

    breaches = []
    for folder, (targets, linked) in sorted(layers.items()):
        target = targets[0]
        allowed = {folder} | {folder_of_target[t] for t in linked if t in folder_of_target}
        files = [f for f in (source / folder).iterdir() if f.suffix in (".cpp", ".hpp")]
        if not files:
            breaches.append(f"{folder}: no source files (is the layer table out of date?)")
        for f in sorted(files):
            for quote, name in INCLUDE.findall(f.read_text()):
                where = f"{folder}/{f.name}"
                if quote == '"':
                    layer = layer_of(name)
                    if layer is not None and layer not in allowed:
                        breaches.append(f'{where} includes "{name}", but {target} does not link '
                                        f"{layers[layer][0][0]} ({layer}/)")
                for pattern, owners in PRIVATE_LIBRARIES:
                    if pattern.match(name) and folder not in owners:
                        breaches.append(f"{where} includes <{name}>, which only {', '.join(sorted(owners))} may")
    for b in breaches:
        print(b)
    print(f"{len(layers)} layers checked, {len(breaches)} breaches")
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main())
