#!/usr/bin/env bash
# The small outputs the browser tests open, each with its page (--page, or clumpkit page): a
# library of six blocks, a specimen of them, a triaxial test and a CPT of it, the two tests side
# by side, a quick crushing run, and a copy of the library page that requests a file from the
# network (the check must catch it), and the library as written before units. About 25 s on 2 cores.
#   make_outputs.sh CLUMPKIT OUT_DIR SOURCE_DIR
set -euo pipefail
clumpkit=$1 out=$2 src=$3
here=$src/tests/browser
rm -rf "$out"
mkdir -p "$out"
cd "$out"
tiny=$src/tests/cli/tiny  # the CLI tests' six blocks and their 60 mm specimen
"$clumpkit" library --recipe "$tiny/rocks.toml" --out lib --quiet --png --page
"$clumpkit" specimen --recipe "$tiny/tiny.toml" --out spec --quiet --page
"$clumpkit" test triaxial --specimen spec --recipe "$here/triaxial.toml" --out tri --quiet --page
"$clumpkit" test cpt --specimen spec --recipe "$here/cpt.toml" --out cpt --quiet --allow-dynamic
"$clumpkit" page cpt
"$clumpkit" page tri cpt --out mixed 2>/dev/null && { echo "a mixed comparison was accepted"; exit 1; }
# The comparison page needs a second test folder, not a second run (the CLI tests check that one
# and two threads give the same bytes): a copy of the first, its page left out.
cp -r tri tri2
rm -rf tri2/page tri2/index.html
"$clumpkit" page tri tri2 --out compare
"$clumpkit" crush --recipe "$src/assets/recipes/crush-quick.toml" --out crush --quiet --page

cp -r lib/. leaky/
# The library as written before units were recorded: headers and manifest without units.
cp -r lib old
rm -rf old/page old/index.html
python3 - old <<'PY'
import json, pathlib, re, sys
for f in pathlib.Path(sys.argv[1]).rglob("*"):
    if f.name in ("manifest.json", "report.json"):  # records keep theirs: checksummed
        j = json.loads(f.read_text()); j.pop("units", None); f.write_text(json.dumps(j, indent=1))
    elif f.suffix == ".csv":
        f.write_text("".join(re.sub(r"\[[^\],]*\]", "", l) if not l.startswith("#") else l
                             for l in f.read_text().splitlines(True)))
PY
"$clumpkit" page old
sed -i 's|<main></main>|<main></main><img src="http://127.0.0.1:9/outside.png" alt="">|' leaky/index.html
