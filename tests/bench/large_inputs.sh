#!/usr/bin/env bash
# Large inputs (issue 15): a 1,310,720-triangle mesh through `describe` and `fill`, and 10⁶
# overlapping spheres through `volume`, each under /usr/bin/time -v: wall time and peak resident
# memory per command.
#   tests/bench/large_inputs.sh [BINARY=build/io/clumpkit]
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=$(realpath "${1:-build/io/clumpkit}")
work=$(mktemp -d "${TMPDIR:-/tmp}/clumpkit-large.XXXXXX")
trap 'rm -rf "$work"' EXIT

measure() {  # LABEL COMMAND...: runs it, prints wall seconds and peak RSS
  local label=$1
  shift
  /usr/bin/time -v "$@" >"$work/out.txt" 2>"$work/time.txt" || {
    cat "$work/time.txt"
    echo "$label: failed"
    exit 1
  }
  awk -v label="$label" '
    /Elapsed \(wall clock\)/ { n = split($NF, t, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + t[i] }
    /Maximum resident set size/ { kb = $NF }
    END { printf "%-44s %9.1f s %9.0f MiB\n", label, s, kb / 1024 }' "$work/time.txt"
}

# An ellipsoid of 20 * 4^8 triangles (level-8 icosphere): the size of a fine scan.
"$bin" shape ellipsoid --axes 3,2,1 --level 8 -o "$work/big.stl" >/dev/null
measure "describe, 1,310,720 triangles" "$bin" describe "$work/big.stl"
measure "fill --spheres 50, 1,310,720 triangles" "$bin" fill "$work/big.stl" -o "$work/big.csv" \
  --spheres 50

# 10⁶ spheres: a jittered 100³ grid of unit spacing, radii in [0.5, 0.9], so neighbours overlap.
awk 'BEGIN { srand(7); print "x,y,z,r";
  for (i = 0; i < 100; i++) for (j = 0; j < 100; j++) for (k = 0; k < 100; k++)
    printf "%.6f,%.6f,%.6f,%.6f\n", i + 0.2 * rand(), j + 0.2 * rand(), k + 0.2 * rand(),
           0.5 + 0.4 * rand() }' >"$work/million.csv"
measure "volume (exact), 10^6 spheres" "$bin" volume "$work/million.csv"
