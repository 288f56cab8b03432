#!/usr/bin/env bash
# Libraries of scan-sized meshes (issue 17 acceptance 4): the bundled 400-particle rock-block
# recipe (assets/recipes/srm-rock-blocks.toml, 48 triangles a block) built as it is and with
# refine_triangles = TRI (default 100000: 98,304 or 196,608 triangles a block after midpoint
# subdivision), pictures off, all cores; wall time of each and their ratio, and the mean
# coverage of each library.
#   tests/bench/library_refined.sh [OUT]   (default /tmp/clumpkit-library-refined; minutes)
# Needs build/io/clumpkit (scripts/build).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${CLUMPKIT:-$root/build/io/clumpkit}
out=${1:-/tmp/clumpkit-library-refined}
tri=${TRI:-100000}
mkdir -p "$out" && cd "$out"
cp "$root/assets/recipes/srm-rock-blocks.toml" original.toml
{ echo "refine_triangles = $tri"; cat original.toml; } > refined.toml
for name in original refined; do
  rm -rf "$name"
  start=$(date +%s.%N)
  "$bin" library --quiet --recipe "$name.toml" --out "$name" --json > "$name.json"
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN{printf "%.1f\n", b - a}' > "$name.seconds"
done
python3 - <<'PY'
import json
o = float(open("original.seconds").read()); r = float(open("refined.seconds").read())
mo = json.load(open("original/manifest.json")); mr = json.load(open("refined/manifest.json"))
print("| library | particles | wall [s] | mean covered | mean overshoot |")
print("|---|---|---|---|---|")
for name, s, m in (("original (48 triangles)", o, mo), ("refined", r, mr)):
    print("| %s | %d | %.1f | %.4f | %.4f |" % (name, sum(f["count"] for f in m["fractions"]), s,
          m["mean_covered_fraction"], m["mean_overshoot_fraction"]))
print("ratio refined / original: %.2f" % (r / o))
PY
