#!/usr/bin/env python3
"""Sizes a reader can hold: no source file over 600 lines, no function over 120 (geom, dem, io,
python). Functions are found by Universal Ctags' C++ parser (Debian's universal-ctags), which sees
what a line pattern misses: signatures over several lines, member functions defined in a class,
functions inside namespaces, constructors with initialiser lists. A lambda counts within the
function that holds it; one at namespace scope is checked on its own.

Usage: sizes.py REPO_ROOT [--list N] [--tops DIR,DIR...]
  (exit 1 and one line per violation when it fails; --tops replaces the four folders)
"""
import json
import os
import shutil
import subprocess
import sys

MAX_FILE, MAX_FUNCTION = 600, 120
TOPS = ("geom", "dem", "io", "python")


def ctags_binary():
    for name in ("ctags-universal", "universal-ctags", "ctags"):
        path = shutil.which(name)
        if path:
            version = subprocess.run([path, "--version"], capture_output=True, text=True).stdout
            if "Universal Ctags" in version:
                return path
    sys.exit("sizes: Universal Ctags not found (Debian package universal-ctags; scripts/deps "
             "installs it)")


def functions(root, paths):
    """(length, path, first line, name) of every function ctags finds in paths."""
    if not paths:
        return []
    command = [ctags_binary(), "--output-format=json", "--fields=+neKZ", "--kinds-C++=f",
               "--language-force=C++", "-f", "-"] + paths
    result = subprocess.run(command, cwd=root, capture_output=True, text=True, check=True)
    found = []
    for line in result.stdout.splitlines():
        tag = json.loads(line)
        if tag.get("_type") != "tag" or "end" not in tag:
            continue
        if tag["name"].startswith("__anon") and tag.get("scopeKind") == "function":
            continue  # a lambda: its lines count in the function around it
        found.append((tag["end"] - tag["line"] + 1, tag["path"], tag["line"], tag["name"]))
    return found


def main():
    root = sys.argv[1]
    tops = TOPS
    if "--tops" in sys.argv:
        tops = tuple(sys.argv[sys.argv.index("--tops") + 1].split(","))
    problems, paths = [], []
    for top in tops:
        for base, dirs, names in os.walk(os.path.join(root, top)):
            dirs.sort()
            for name in sorted(names):
                if not name.endswith((".h", ".cpp")):
                    continue
                rel = os.path.relpath(os.path.join(base, name), root)
                paths.append(rel)
                with open(os.path.join(root, rel), encoding="utf-8") as f:
                    count = f.read().count("\n")
                if count > MAX_FILE:
                    problems.append(f"{rel}: {count} lines (at most {MAX_FILE})")
    found = functions(root, paths)
    for length, rel, first, name in sorted(found, key=lambda f: (f[1], f[2])):
        if length > MAX_FUNCTION:
            problems.append(f"{rel}:{first}: function of {length} lines (at most {MAX_FUNCTION}): "
                            f"{name}")
    if "--list" in sys.argv:
        n = int(sys.argv[sys.argv.index("--list") + 1])
        for length, rel, first, name in sorted(found, reverse=True)[:n]:
            print(f"{length:5d} {rel}:{first} {name}")
    for p in problems:
        print(p)
    print(f"sizes: {len(paths)} files, {len(found)} functions, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
