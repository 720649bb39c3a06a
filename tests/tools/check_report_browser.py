#!/usr/bin/env python3
"""umbra check --report's page, opened in a real browser: Debian's headless
Chromium loads it from the disk and its DOM, once the page's script has run,
is read back.

  check_report_browser.py UMBRA MESH_FOLDER WORK_FOLDER

Checks, on a folder of real meshes (CGAL's data): a row per mesh, a picture
per mesh that has one, the sort the address asks for (by triangles,
descending) and the verdict filter; and that a page of 10,000 meshes makes
its 10,000 rows. Exits 77 (skipped) where Chromium is not installed."""
import html
import os
import json
import pathlib
import re
import shutil
import subprocess
import sys
import urllib.parse

umbra, meshes, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
browser = shutil.which("chromium")
if not browser:
    print("skipped: needs Debian's chromium (build.sh test installs it)")
    sys.exit(77)
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
failures = []


def expect(condition, message):
    if not condition:
        failures.append(message)


def dom(page, fragment=""):
    """The page's DOM once its script has run, from headless Chromium."""
    run = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", f"--user-data-dir={work / 'profile'}",
                          "--dump-dom", page.resolve().as_uri() + fragment], capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        sys.exit(f"chromium failed on {page}: {run.stderr[-2000:]}")
    return run.stdout


def rows(text):
    """(path, hidden) of each row, in the page's order."""
    return [(html.unescape(path), "hidden" in attributes)
            for path, attributes in re.findall(r'<tr data-path="([^"]*)"([^>]*)>', text)]


def linked_file(folder, url):
    """The file a relative link in the page leads to, as the browser finds it."""
    return folder / os.fsdecode(urllib.parse.unquote_to_bytes(html.unescape(url)))


def embedded_reports(page):
    text = page.read_text()
    data = re.search(r'<script type="application/json" id="reports">(.*?)</script>', text, re.S).group(1)
    return json.loads(data)


# CGAL's data folder, with its pictures.
report = work / "report.html"
run = subprocess.run([umbra, "check", "--brief", str(meshes), "--report", str(report)], capture_output=True, text=True)
expect(run.returncode in (1, 2), f"umbra check exited {run.returncode}: {run.stderr[-2000:]}")
reports = embedded_reports(report)
count = len(list(p for p in meshes.iterdir() if p.is_file() and p.suffix in (".off", ".ply", ".obj", ".stl")))
expect(len(reports) == count, f"{len(reports)} reports for {count} meshes")

page = dom(report, "#sort=triangles&order=descending")
shown = rows(page)
expect(len(shown) == count, f"{len(shown)} rows for {count} meshes")
by_triangles = sorted(range(len(reports)), key=lambda i: (-reports[i].get("triangles", -1), i))
expect([p for p, _ in shown] == [reports[i]["path"] for i in by_triangles], "the rows are not sorted by triangles, most first")
pictures = re.findall(r'<img [^>]*src="([^"]*)"', page)
drawn = sum(1 for p in (report.parent / "report-pictures").rglob("*.png"))
expect(len(pictures) == drawn and drawn >= count - 1, f"{len(pictures)} pictures shown, {drawn} drawn, for {count} meshes")
expect(all(linked_file(report.parent, p).is_file() for p in pictures), "a picture's link leads nowhere")
expect('aria-sort="descending"' in page, "the triangles heading does not say it sorts")

page = dom(report, "#verdict=closed")
closed = sum(1 for r in reports if r.get("closed_manifold"))
visible = [p for p, hidden in rows(page) if not hidden]
expect(len(visible) == closed, f"{len(visible)} rows shown for {closed} closed 2-manifolds")
summary = re.search(r'id="summary">([^<]*)<', page).group(1)
expect(f"{count} meshes" in summary and f"{closed} closed 2-manifolds" in summary, f"the summary says: {summary}")

# Hostile and awkward file names, each picture drawn into the report's own
# folder (--picture): a name once became a "javascript:" link, and '#', '?',
# '%' and bytes that are not UTF-8 made thumbnails that lead nowhere.
tetrahedron = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
hostile = work / "hostile"
hostile.mkdir()
names = [b"javascript:alert(document.title).off", b"a#b.off", b"c?d.off", b"e%41.off", b"f\xff.off", b"g h&amp;.off"]
for name in names:
    (hostile / os.fsdecode(name)).write_text(tetrahedron)
shown_folder = work / "hostile-report"
run = subprocess.run([umbra, "check", "--brief", str(hostile), "--picture", str(shown_folder), "--report",
                      str(shown_folder / "report.html")], capture_output=True, text=True, errors="replace")
expect(run.returncode == 0, f"umbra check of the hostile names exited {run.returncode}: {run.stderr[-2000:]}")
page = dom(shown_folder / "report.html")
links = re.findall(r'<a href="([^"]*)"', page)
sources = re.findall(r'<img [^>]*src="([^"]*)"', page)
expect(len(links) == len(names) and links == sources, f"{len(links)} links and {len(sources)} pictures for {len(names)} meshes")
for url in links:
    expect(urllib.parse.urlsplit(html.unescape(url)).scheme == "", f"the link {url!r} has a scheme: clicking it would not open a picture")
    expect(linked_file(shown_folder, url).is_file(), f"the link {url!r} leads nowhere")

# 10,000 meshes (tetrahedra, every hundredth with a face missing), without pictures.
many = work / "many"
many.mkdir()
for i in range(10_000):
    faces = ["3 0 2 1", "3 0 1 3", "3 0 3 2", "3 1 2 3"][: 3 if i % 100 == 0 else 4]
    (many / f"t{i:05}.off").write_text(f"OFF\n4 {len(faces)} 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + "\n".join(faces) + "\n")
big = work / "many.html"
run = subprocess.run([umbra, "check", "--brief", str(many), "--report", str(big), "--no-pictures"],
                     capture_output=True, text=True)
expect(run.returncode == 1, f"umbra check on 10,000 meshes exited {run.returncode}: {run.stderr[-2000:]}")
page = dom(big, "#sort=border-edges&order=descending&verdict=not-closed")
shown = rows(page)
expect(len(shown) == 10_000, f"{len(shown)} rows for 10,000 meshes")
open_ones = [p for p, hidden in shown if not hidden]
expect(len(open_ones) == 100 and all(p.endswith("00.off") for p in open_ones),
       f"{len(open_ones)} open meshes shown, not the 100 with a face missing")
expect(re.search(r'data-ready-ms="\d+"', page) is not None, "the page did not finish its script")

for f in failures:
    print("FAILED:", f)
print(f"{count} meshes of {meshes} and 10,000 generated ones: {len(failures)} failures")
sys.exit(1 if failures else 0)
