#!/usr/bin/env python3
"""Checks that the run records of a campaign made again are those of an earlier archive but
for what the newer binary adds (the ridge columns and strips, issue 34) and the wall time: every record
of NEW must have its twin in OLD with the same scene, digest of the scene, summary, metrics,
samples and profile, bit for bit (JSON numbers compared as written).

    scripts/same-records.py OLD_DIR NEW_DIR

Exit status 0 when every run of NEW matches, 1 otherwise (each difference printed).
"""
import json
import sys
from pathlib import Path

ADDED_PROFILE = {"ridge_ice", "ridge_envelope"}
ADDED_SAMPLE = {"ridge", "ridge_strips"}


def strip(rec):
    rec = dict(rec)
    rec["summary"] = {k: v for k, v in rec["summary"].items() if k != "wall_seconds"}
    rec["profile"] = {k: v for k, v in rec["profile"].items() if k not in ADDED_PROFILE}
    rec["samples"] = [
        {k: v for k, v in s.items() if k not in ADDED_SAMPLE} for s in rec["samples"]
    ]
    rec["digest"] = rec["digest"]["scene"] if rec.get("digest") else None
    return rec


def main(old, new):
    old, new = Path(old), Path(new)
    runs = sorted(new.glob("runs/*/*/run.json"))
    bad = 0
    for path in runs:
        rel = path.relative_to(new)
        twin = old / rel
        if not twin.exists():
            print(f"{rel}: not in {old}")
            bad += 1
            continue
        a = strip(json.loads(twin.read_text()))
        b = strip(json.loads(path.read_text()))
        diff = sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
        if diff:
            print(f"{rel}: differs in {', '.join(diff)}")
            bad += 1
    print(f"{len(runs) - bad} of {len(runs)} runs of {new} are those of {old}")
    return 1 if bad or not runs else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(*sys.argv[1:]))
