#!/usr/bin/env python3
"""Digests of `umbra check --json` reports, one line per mesh: its path
relative to ROOT, a tab, and the first 16 hex digits of the SHA-256 of the
report with its timings (every "seconds" key) removed, keys sorted and
whole numbers written alike whether the JSON wrote 60 or 60.0.

  umbra check --json FOLDER | report_digests.py FOLDER > digests.tsv

tests/data/cgal_check_reports.tsv holds the digests of CGAL's data meshes;
a change to what the check reports shows as a changed digest, and the file
is regenerated with this script once the change is meant."""
import hashlib
import json
import os
import sys


def without_timings(value):
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k != "seconds"}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    if isinstance(value, float) and value.is_integer():
        return int(value)
    return value


root = os.path.abspath(sys.argv[1])
for line in sys.stdin:
    report = without_timings(json.loads(line))
    report["path"] = os.path.relpath(report["path"], root)
    text = json.dumps(report, sort_keys=True, separators=(",", ":"))
    print(report["path"] + "\t" + hashlib.sha256(text.encode()).hexdigest()[:16])
