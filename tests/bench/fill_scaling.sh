#!/usr/bin/env bash
# Fill at scan scale (issue 17 acceptance 1): `clumpkit fill --spheres 50` on a 2:1:1 ellipsoid
# at 20,480 / 81,920 / 327,680 / 1,310,720 triangles (icosphere levels 5–8), whole process on
# one core (taskset -c 0): wall time and peak memory (/usr/bin/time), and the phases the fill
# reports (--json seconds_by_phase: read, index, field, fill, fidelity), each the best of RUNS.
#   tests/bench/fill_scaling.sh [OUT]   (default /tmp/clumpkit-fill-scaling; about a minute)
# Needs build/io/clumpkit (scripts/build) and /usr/bin/time (Debian package time).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${CLUMPKIT:-$root/build/io/clumpkit}
out=${1:-/tmp/clumpkit-fill-scaling}
runs=${RUNS:-3}
mkdir -p "$out" && cd "$out"
echo "| triangles | whole process [s] | peak [MB] | read | index | field | fill | fidelity | covered | overshoot |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for level in 5 6 7 8; do
  "$bin" shape ellipsoid --axes 2,1,1 --level "$level" -o "e$level.stl" > /dev/null
  best=""
  for r in $(seq "$runs"); do
    /usr/bin/time -f "%e %M" -o time.txt taskset -c 0 "$bin" fill "e$level.stl" -o "c$level.csv" \
      --spheres 50 --json > "fill$level.json"
    read -r wall kb < time.txt
    if [ -z "$best" ] || awk -v a="$wall" -v b="$best" 'BEGIN{exit !(a < b)}'; then
      best=$wall
      cp "fill$level.json" "best$level.json"
      echo "$wall $kb" > "best$level.txt"
    fi
  done
  read -r wall kb < "best$level.txt"
  python3 - "best$level.json" "$wall" "$kb" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
p = j["seconds_by_phase"]
print("| %d | %s | %.0f | %.3f | %.3f | %.3f | %.3f | %.3f | %.4f | %.4f |" % (
    j["triangles"], sys.argv[2], int(sys.argv[3]) / 1024, p["read"], p["index"], p["field"],
    p["fill"], p["fidelity"], j["covered_fraction"], j["overshoot_fraction"]))
PY
done
