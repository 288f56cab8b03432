#!/usr/bin/env python3
"""The page's data contract (docs/pages.md) holds on both sides: the names the C++ job writes
(io/pipeline/page*.cpp) are the names the page's scripts read (assets/page/*.js), the asset files
are the ones io/CMakeLists.txt compiles in and index.html loads, and docs/pages.md names each.
A rename on one side only (a callback, a data.js key, a kind, a script file) fails here instead of
leaving a page that opens blank. Exit 0 when it holds, 1 with one line per break.

Usage: page_contract.py REPO_ROOT
"""
import glob
import os
import re
import sys


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def call_arguments(text, function):
    """The argument lists of every call of `function` in JS text, split at top-level commas."""
    calls = []
    for m in re.finditer(r"(?<!function )\b%s\(" % re.escape(function), text):
        depth, start, args, i = 1, m.end(), [], m.end()
        while i < len(text) and depth:
            c = text[i]
            if c in "([{":
                depth += 1
            elif c in ")]}":
                depth -= 1
            elif c in "'\"":  # skip a string literal (the page's own code escapes no quote)
                i = text.index(c, i + 1)
            if (c == "," and depth == 1) or depth == 0:
                args.append(text[start:i].strip())
                start = i + 1
            i += 1
        calls.append(args)
    return calls


def cpp_side(root):
    """What the job writes: data globals, callbacks, per-item folders, data.js keys, kinds."""
    sources = sorted(glob.glob(os.path.join(root, "io", "pipeline", "page*.cpp")))
    text = "\n".join(read(p) for p in sources)
    kind_of = re.search(r"std::string kind_of\(.*?\n}\n", text, re.S)
    return {
        "globals": set(re.findall(r'page_script\("(\w+)"', text)),
        # "clumpkit_part(" + part.dump() + ");\n": the callback a per-item script calls.
        "callbacks": set(re.findall(r'"(\w+)\(" \+', text)),
        "folders": set(re.findall(r'\{"(\w+)/" \+ name \+ "\.js"', text)),
        "keys": set(re.findall(r'\bdata\["(\w+)"\]', text)),
        "kinds": set(re.findall(r'return "(\w+)";', kind_of.group(0))) if kind_of else set(),
    }


def js_side(root):
    """What the page's scripts read: data globals, callbacks, data.js keys, kinds."""
    scripts = sorted(glob.glob(os.path.join(root, "assets", "page", "*.js")))
    text = "\n".join(read(p) for p in scripts)
    callbacks, loose = set(), []
    for args in call_arguments(text, "loadPart"):  # loadPart(id, src, callback, onData)
        m = re.fullmatch(r"'(\w+)'", args[2]) if len(args) == 4 else None
        if m:
            callbacks.add(m.group(1))
        else:
            loose.append(", ".join(args))
    return {
        # Data globals are upper case (CLUMPKIT_PAGE); the page's own are camel case.
        "globals": set(re.findall(r"\bwindow\.([A-Z][A-Z0-9_]+)\b", text)),
        "callbacks": callbacks,
        "loose": loose,
        "keys": set(re.findall(r"\bD\.(\w+)", text)),
        "kinds": set(re.findall(r"\bkinds\.(\w+)\s*=", text)),
    }


def asset_lists(root):
    """assets/page's files, io/CMakeLists.txt's asset list, and the page/ files index.html loads."""
    paths = glob.glob(os.path.join(root, "assets", "page", "*"))
    files = sorted(os.path.basename(p) for p in paths)
    m = re.search(r"foreach\(asset\s+([^)]*)\)", read(os.path.join(root, "io", "CMakeLists.txt")))
    listed = m.group(1).split() if m else []
    index = read(os.path.join(root, "assets", "page", "index.html"))
    loaded = re.findall(r'(?:src|href)="page/([^"]+)"', index)
    return files, listed, loaded


def documented(doc, name):
    """`name` appears inside a `code span` of the doc, as a whole word."""
    pattern = re.compile(r"(?<![\w.])%s(?![\w])" % re.escape(name))
    return any(pattern.search(span) for span in re.findall(r"`([^`\n]+)`", doc))


def check(root):
    cpp, js = cpp_side(root), js_side(root)
    doc = read(os.path.join(root, "docs", "pages.md"))
    problems = []

    def both(what, written, read_):
        for n in sorted(written - read_):
            problems.append("%s '%s': written by io/pipeline/page*.cpp, read by no script of "
                            "assets/page" % (what, n))
        for n in sorted(read_ - written):
            problems.append("%s '%s': read by assets/page, written by no io/pipeline/page*.cpp"
                            % (what, n))
        if not written and not read_:
            problems.append("%s: none found on either side (the patterns of page_contract.py "
                            "no longer match the code)" % what)

    both("data global", cpp["globals"], js["globals"])
    both("callback", cpp["callbacks"], js["callbacks"])
    both("data.js key", cpp["keys"], js["keys"])
    both("page kind", cpp["kinds"], js["kinds"])
    for call in js["loose"]:
        problems.append("loadPart(%s): its callback is not a string literal, so it cannot be "
                        "checked" % call)

    files, listed, loaded = asset_lists(root)
    for f in sorted(set(files) - set(listed)):
        problems.append("assets/page/%s: not in io/CMakeLists.txt's foreach(asset ...), so no page "
                        "gets it" % f)
    for f in sorted(set(listed) - set(files)):
        problems.append("io/CMakeLists.txt lists asset %s, which assets/page lacks" % f)
    own = {f for f in files if f != "index.html"}
    written = {"three.min.js", "data.js"}  # by the job (page_files.cpp, page.cpp), not assets
    for f in sorted(own - set(loaded)):
        problems.append("assets/page/%s: index.html does not load page/%s" % (f, f))
    for f in sorted(set(loaded) - own - written):
        problems.append("index.html loads page/%s, which neither assets/page nor the job writes"
                        % f)
    scripts = [f for f in loaded if f.endswith(".js")]
    if scripts[:3] != ["three.min.js", "data.js", "base.js"] or scripts[-1:] != ["page.js"]:
        problems.append("index.html loads %s: three.min.js, data.js and base.js must come first "
                        "(the others use them) and page.js last (it starts the page)"
                        % ", ".join(scripts))

    names = (cpp["globals"] | js["globals"] | cpp["callbacks"] | js["callbacks"] | cpp["keys"] |
             js["keys"] | cpp["kinds"] | js["kinds"] | set(files) | {"data.js"})
    for n in sorted(names):
        if not documented(doc, n):
            problems.append("docs/pages.md does not name `%s`" % n)
    for folder in sorted(cpp["folders"]):
        if not documented(doc, folder + "/NNNNN.js"):
            problems.append("docs/pages.md does not name `%s/NNNNN.js`" % folder)
    if not cpp["folders"]:
        problems.append("per-item scripts: none found in io/pipeline/page*.cpp")
    return problems, names


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.split("\n\n")[-1])
    problems, names = check(sys.argv[1])
    for p in problems:
        print("page_contract: " + p)
    if problems:
        return 1
    print("page_contract: %d names agree between io/pipeline/page*.cpp, assets/page and "
          "docs/pages.md" % len(names))
    return 0


if __name__ == "__main__":
    sys.exit(main())
