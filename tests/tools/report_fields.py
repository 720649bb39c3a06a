#!/usr/bin/env python3
"""The fields of `umbra check --json` reports that say what a mesh is, one
tab-separated row per mesh under a header: its path relative to ROOT, then
counts a reader can check against the mesh (or against another tool, such
as CGAL's or admesh's), and how the renderer casts its shadow.

  umbra check --json FOLDER | report_fields.py FOLDER > reports.tsv

tests/data/cgal_check_reports.tsv holds these rows for CGAL's data meshes; a
change to what the check reports shows as a changed row, and the file is
made again with this script once the change is meant."""
import json
import os
import sys

COLUMNS = [
    ("triangles", lambda r: r["triangles"]),
    ("vertices", lambda r: r["vertices"]),
    ("edges", lambda r: r["edges"]),
    ("components", lambda r: r["components"]),
    ("closed", lambda r: r["closed_components"]),
    ("silhouette", lambda r: sum(c["shadow_method"] == "silhouette" for c in r["component_list"])),
    ("border", lambda r: r["border_edges"]),
    ("holes", lambda r: r["border_loops"]),
    ("nm_edges", lambda r: r["non_manifold_edges"]),
    ("nm_vertices", lambda r: r["non_manifold_vertices"]),
    ("duplicates", lambda r: r["duplicate_faces"]),
    ("degenerate", lambda r: r["degenerate_faces"]),
    ("inconsistent", lambda r: r["inconsistent_edges"]),
    ("to_flip", lambda r: r["faces_to_flip"]),
    ("non_orientable", lambda r: r["non_orientable_components"]),
    ("inward", lambda r: r["inward_components"]),
    ("undecided", lambda r: r["undecided_components"]),
    ("crossing_pairs", lambda r: r["self_intersections"]["face_pairs"]
     if r["self_intersections"]["complete"] else "incomplete"),
    ("euler", lambda r: r["euler_characteristic"]),
    ("shadow_method", lambda r: r["shadow_method"]),
]

root = os.path.abspath(sys.argv[1])
print("\t".join(["path"] + [name for name, _ in COLUMNS]))
for line in sys.stdin:
    report = json.loads(line)
    path = os.path.relpath(report["path"], root)
    if "error" in report:
        print(path + "\terror: " + report["error"])
        continue
    print("\t".join([path] + [str(value(report)) for _, value in COLUMNS]))
