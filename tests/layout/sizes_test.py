#!/usr/bin/env python3
"""The size check's own test: on a small tree it must flag a function whose signature spans
several lines, a member function defined in its class, a constructor with an initialiser list and
a namespace-scope lambda, each of 121 lines, and pass the same shapes at 120 lines; the line
pattern the check used before saw none of the first three.

Usage: sizes_test.py PATH/TO/sizes.py
"""
import os
import subprocess
import sys
import tempfile


def body(n):
    """n lines of statements."""
    return "".join(f"  x += {i};\n" for i in range(n))


def sources(lines):
    """Four definitions of `lines` lines each (first line to closing brace)."""
    inner = lines - 2  # the opening and the closing line
    return {
        "geom/multi_line.cpp": (
            "namespace clumpkit {\n"
            "int long_signature(int a,\n"
            "                   int b) {\n" + body(inner - 3) + "  int x = a + b;\n  return x;\n}\n"
            "}  // namespace clumpkit\n"),
        "dem/member.h": (
            "struct Holder {\n"
            "  int member(int x) const {\n" + body(inner - 1) + "    return x;\n  }\n"
            "};\n"),
        "io/constructor.cpp": (
            "struct Built {\n  Built(int v);\n  int x;\n};\n"
            "Built::Built(int v)\n"
            "    : x(v) {\n" + body(inner - 1) + "}\n"),
        "python/lambda.cpp": (
            "auto handler = [](int x) {\n" + body(inner - 1) + "  return x;\n};\n"),
    }


def run(checker, lines):
    with tempfile.TemporaryDirectory() as root:
        for rel, text in sources(lines).items():
            os.makedirs(os.path.join(root, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w") as f:
                f.write(text)
        r = subprocess.run([sys.executable, checker, root], capture_output=True, text=True)
        return r.returncode, r.stdout


def main():
    checker = sys.argv[1]
    failures = []
    code, out = run(checker, 121)
    for name in ("long_signature", "member", "Built", "__anon"):
        if f"function of 121 lines (at most 120): {name}" not in out:
            failures.append(f"121 lines: {name} not flagged")
    if code != 1:
        failures.append(f"121 lines: exit {code}, expected 1")
    code, out = run(checker, 120)
    if code != 0 or "function of" in out:
        failures.append(f"120 lines: exit {code}, flagged:\n{out}")
    for f in failures:
        print(f)
    print("sizes_test:", "failed" if failures else "passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
