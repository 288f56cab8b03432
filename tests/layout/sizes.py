#!/usr/bin/env python3
"""Sizes a reader can hold: no source file over 600 lines, no function over 120 (geom, dem, io,
python). A function is a definition that opens at column 0 and closes with a '}' at column 0 (the
project's format: namespaces are not indented).

Usage: sizes.py REPO_ROOT [--list N]   (exit 1 and one line per violation when it fails)
"""
import os
import re
import sys

MAX_FILE, MAX_FUNCTION = 600, 120
OPENING = re.compile(r"^[A-Za-z_].*\)\s*(const)?\s*(noexcept)?\s*(->.*)?\{\s*$|^[A-Za-z_].*\)\s*:\s.*$")


def functions(lines):
    """(first line, length, signature) of every column-0 function definition."""
    found, start = [], None
    for i, line in enumerate(lines):
        if start is None:
            if (OPENING.match(line) and not line.startswith(("namespace", "struct", "class", "enum",
                                                              "union", "extern", "#"))):
                start = i
        elif line.startswith("}"):
            found.append((start + 1, i - start + 1, lines[start].strip()))
            start = None
        elif line and not line[0].isspace() and not line.startswith(("#", "//", ":", "{", ")")):
            start = None  # not a body after all (a declaration over several lines)
    return found


def main():
    root = sys.argv[1]
    problems, all_functions = [], []
    for top in ("geom", "dem", "io", "python"):
        for base, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                if not name.endswith((".h", ".cpp")):
                    continue
                path = os.path.join(base, name)
                rel = os.path.relpath(path, root)
                with open(path, encoding="utf-8") as f:
                    lines = f.read().split("\n")
                if len(lines) - 1 > MAX_FILE:
                    problems.append(f"{rel}: {len(lines) - 1} lines (at most {MAX_FILE})")
                for first, length, signature in functions(lines):
                    all_functions.append((length, rel, first, signature))
                    if length > MAX_FUNCTION:
                        problems.append(f"{rel}:{first}: function of {length} lines (at most "
                                        f"{MAX_FUNCTION}): {signature[:60]}")
    if "--list" in sys.argv:
        n = int(sys.argv[sys.argv.index("--list") + 1])
        for length, rel, first, signature in sorted(all_functions, reverse=True)[:n]:
            print(f"{length:5d} {rel}:{first} {signature[:70]}")
    for p in problems:
        print(p)
    print(f"sizes: {len(all_functions)} functions, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
