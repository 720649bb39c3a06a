#!/usr/bin/env python3
"""Every picture the README and docs/ show is in the source tree.

A picture left out of the repository (a .gitignore rule, a forgotten `git
add`) shows as a broken image to every reader but the one who made it; on a
clean clone, as CI makes, it is missing here too.
Usage: doc_pictures.py SOURCE_DIR
"""
import pathlib
import re
import shutil
import subprocess
import sys

source = pathlib.Path(sys.argv[1])


def ignored_by_git(path):
    """True when git ignores the file and does not track it: it is here, but a
    clone will not have it. Outside a git checkout nothing counts as ignored."""
    if shutil.which("git") is None or not (source / ".git").exists():
        return False
    return subprocess.run(["git", "-C", str(source), "check-ignore", "-q", str(path)]).returncode == 0


missing = []
docs = [source / "README.md", *sorted((source / "docs").glob("*.md"))]
for doc in docs:
    for target in re.findall(r"!\[[^\]]*\]\(([^)\s]+\.(?:png|jpg|webp|gif))\)", doc.read_text(encoding="utf-8")):
        picture = doc.parent / target
        if not picture.is_file():
            missing.append(f"{doc.relative_to(source)} shows {target}, which is not in the source tree")
        elif ignored_by_git(picture):
            missing.append(f"{doc.relative_to(source)} shows {target}, which git ignores: a clone will not have it")
print("\n".join(missing) if missing else f"{len(docs)} documents checked: every picture they show is there")
sys.exit(1 if missing else 0)
