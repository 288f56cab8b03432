#!/usr/bin/env python3
"""The include graph of the sources (geom, dem, io, python): every folder in its layer order, no
folder pair that includes each other, no cycle between files, no include from a lower layer up.

Usage: include_graph.py REPO_ROOT [--print]   (exit 1 and one line per violation when it fails)
"""
import os
import re
import sys

# Layers, lowest first. A file may include its own folder and any folder listed before it.
LAYERS = [
    "geom",
    "dem/core", "dem/measure", "dem/run", "dem/lab", "dem/specimen",
    "io/base", "io/formats", "io/recipes", "io/reports", "io/export", "io/pipeline", "io/cli",
    "python",
]
# Headers that are private parts of another unit, not units of their own (the World's step caches,
# shared by its three source files world.cpp, world_contacts.cpp and world_integrate.cpp).
PARTS = {"dem/core/world_step_cache.h": "dem/core/world"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def folder_of(path):
    """The layer a repository path belongs to (the longest listed prefix)."""
    best = None
    for layer in LAYERS:
        if path == layer or path.startswith(layer + "/"):
            if best is None or len(layer) > len(best):
                best = layer
    return best


def sources(root):
    for top in ("geom", "dem", "io", "python"):
        for base, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                if name.endswith((".h", ".cpp")):
                    yield os.path.relpath(os.path.join(base, name), root)


def main():
    root = sys.argv[1]
    files = sorted(sources(root))
    known = set(files)
    edges = {}
    problems = []
    for f in files:
        with open(os.path.join(root, f), encoding="utf-8") as text:
            targets = [t for t in INCLUDE.findall(text.read()) if t in known]
        edges[f] = targets
        if folder_of(f) is None:
            problems.append(f"{f}: in no layer of tests/layout/include_graph.py")
    # Layer order: an include goes to the same layer or one listed before it.
    rank = {layer: i for i, layer in enumerate(LAYERS)}
    pairs = set()
    for f, targets in edges.items():
        a = folder_of(f)
        for t in targets:
            b = folder_of(t)
            if a is None or b is None or a == b:
                continue
            pairs.add((a, b))
            if rank[b] > rank[a]:
                problems.append(f"{f} includes {t}: {a} is below {b}")
    for a, b in sorted(pairs):
        if a < b and (b, a) in pairs:
            problems.append(f"folders {a} and {b} include each other")
    # File cycles (a .cpp is one node with its .h: a pair is one unit of code).
    def unit(path):
        if path in PARTS:
            return PARTS[path]
        return path[:-4] if path.endswith(".cpp") else path[:-2]
    graph = {}
    for f, targets in edges.items():
        graph.setdefault(unit(f), set()).update(unit(t) for t in targets if unit(t) != unit(f))
    state, stack = {}, []
    def visit(u):
        state[u] = 1
        stack.append(u)
        for v in sorted(graph.get(u, ())):
            if state.get(v) == 1:
                problems.append("cycle: " + " -> ".join(stack[stack.index(v):] + [v]))
            elif v not in state:
                visit(v)
        stack.pop()
        state[u] = 2
    sys.setrecursionlimit(10000)
    for u in sorted(graph):
        if u not in state:
            visit(u)
    if "--print" in sys.argv:
        for a, b in sorted(pairs):
            print(f"{a} -> {b}")
    for p in problems:
        print(p)
    print(f"include_graph: {len(files)} files, {len(pairs)} folder edges, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
