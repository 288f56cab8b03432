#!/usr/bin/env python3
"""Compares two reference sets (tests/layout/reference_outputs.sh): the same files, the same
bytes, JSON compared with its wall-clock fields left out. Exit 1 and one line per difference.

Usage: compare_outputs.py A B
"""
import json
import os
import sys

# Keys whose values are wall-clock measurements, the machine's or the build's (the commit), not
# results.
CLOCK_KEYS = {"commit", "seconds", "wall_seconds", "elapsed_seconds", "time_s", "threads", "started", "finished"}


def strip(value):
    if isinstance(value, dict):
        return {k: strip(v) for k, v in value.items()
                if k not in CLOCK_KEYS and not k.endswith("_seconds")
                and not k.startswith("seconds_")}
    if isinstance(value, list):
        return [strip(v) for v in value]
    return value


def load_json(text):
    try:
        return strip(json.loads(text))
    except ValueError:
        return None


def files(root):
    found = set()
    for base, _, names in os.walk(root):
        for name in names:
            found.add(os.path.relpath(os.path.join(base, name), root))
    return found


def main():
    a, b = sys.argv[1], sys.argv[2]
    fa, fb = files(a), files(b)
    problems = [f"only in {a}: {f}" for f in sorted(fa - fb)]
    problems += [f"only in {b}: {f}" for f in sorted(fb - fa)]
    for f in sorted(fa & fb):
        with open(os.path.join(a, f), "rb") as x, open(os.path.join(b, f), "rb") as y:
            da, db = x.read(), y.read()
        # Paths the outputs name (a manifest's source) start with their set's folder.
        da = da.replace(os.path.abspath(a).encode(), b"<OUT>")
        db = db.replace(os.path.abspath(b).encode(), b"<OUT>")
        if da == db:
            continue
        ja = load_json(da.decode("utf-8", "replace"))
        if ja is not None and ja == load_json(db.decode("utf-8", "replace")):
            continue
        problems.append(f"differs: {f}")
    for p in problems:
        print(p)
    print(f"compare_outputs: {len(fa & fb)} files in both, {len(problems)} differences")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
