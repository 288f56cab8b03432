#!/usr/bin/env bash
# Platy shapes (issue 33 acceptance 5): `clumpkit fill --spheres 20` on slabs 1:10 and 1:20, as
# boxes (12 triangles) and rounded plates (ellipsoids, 20,480 triangles), at the default
# resolution (40 voxels across the thickness within the 1e6-voxel budget) against the same fill
# without the budget (--voxels 40: the grid before the budget), whole process on one core
# (taskset -c 0), the best of RUNS: wall time, peak memory, voxel, covered and overshoot.
#   tests/bench/platy_fill.sh [OUT]   (default /tmp/clumpkit-platy-fill; about two minutes)
# Needs build/io/clumpkit (scripts/build) and /usr/bin/time (Debian package time).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${CLUMPKIT:-$root/build/io/clumpkit}
out=${1:-/tmp/clumpkit-platy-fill}
runs=${RUNS:-3}
mkdir -p "$out" && cd "$out"
"$bin" shape box --size 10,10,1 -o box10.stl > /dev/null
"$bin" shape box --size 20,20,1 -o box20.stl > /dev/null
"$bin" shape ellipsoid --axes 5,5,0.5 --level 5 -o plate10.stl > /dev/null
"$bin" shape ellipsoid --axes 10,10,0.5 --level 5 -o plate20.stl > /dev/null
echo "| shape | grid | whole process [s] | peak [MB] | voxel | covered | overshoot (max 0.01) |"
echo "|---|---|---|---|---|---|---|"
for shape in box10 box20 plate10 plate20; do
  for grid in budget unbudgeted; do
    extra=()
    [ "$grid" = unbudgeted ] && extra=(--voxels 40)
    best=""
    for r in $(seq "$runs"); do
      /usr/bin/time -f "%e %M" -o time.txt taskset -c 0 "$bin" fill "$shape.stl" \
        -o "$shape-$grid.csv" --spheres 20 --json "${extra[@]}" > "$shape-$grid.json"
      read -r wall kb < time.txt
      if [ -z "$best" ] || awk -v a="$wall" -v b="$best" 'BEGIN{exit !(a < b)}'; then
        best=$wall
        echo "$wall $kb" > "best.txt"
      fi
    done
    read -r wall kb < best.txt
    python3 - "$shape-$grid.json" "$shape" "$grid" "$wall" "$kb" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
print(f"| {sys.argv[2]} | {sys.argv[3]} | {float(sys.argv[4]):.2f} | {int(sys.argv[5]) / 1024:.0f} | "
      f"{j['voxel']:.4f} | {j['covered_fraction']:.4f} | {j['overshoot_fraction']:.5f} |")
PY
  done
done
