#!/bin/bash
# The reference set of a restructure: every command the project has, on small inputs, written by
# the binary BIN into OUT. Two binaries whose sets compare equal (tests/layout/compare_outputs.py,
# wall-clock fields left out) write the same bytes.
# usage: tests/layout/reference_outputs.sh BIN OUT   (about two minutes on 2 cores)
set -euo pipefail
bin=$(realpath "$1")
out=$2
src=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$out"
mkdir -p "$out/in"
cd "$out"
run() {
  echo "+ clumpkit $*" >>commands.txt
  n=$((n + 1))
  "$bin" "$@" >"stdout-$n.txt" 2>err.txt || { echo "failed: clumpkit $*: $(cat err.txt)" >&2; exit 1; }
  rm -f err.txt
}
bad() { echo "+ clumpkit $* (must fail)" >>commands.txt;
  n=$((n + 1)); set +e; "$bin" "$@" >/dev/null 2>"stderr-$n.txt"; echo "exit $?" >>"stderr-$n.txt"; set -e; }
n=0
cp "$src"/tests/cli/tiny/*.toml in/
# Geometry commands.
run shape block --L 75.1 --W 58.0 --H 49.8 --seed 1 -o in/block.stl
run shape hull --diameter 1 --seed 4 -o in/hull.stl
run shape polyhedron --diameter 0.02 --seed 5 -o in/poly.stl
run describe in/block.stl --json
run repair in/block.stl -o in/block-repaired.stl --json
run fill in/block.stl -o fill.csv --spheres 30 --json --png fill.png --vtp fill.vtp
run fill in/hull.stl -o fill-hull.csv --spheres 12 --check-resolution --json
run volume fill.csv --method all --json
run cells in/poly.stl --count 12 --seed 2 --out cells --json
# Libraries, specimens, tests, crushing.
run shapes --recipe in/rocks.toml --out shapes --quiet --json
run library --recipe in/rocks.toml --out lib --quiet --json
run specimen --recipe in/tiny.toml --out spec --quiet --json
cat >in/tri.toml <<'T'
[test]
confining = 100e3
strain_rate = 0.5
max_axial_strain = 0.01
record_every = 400
T
cat >in/cpt.toml <<'T'
[test]
confining = 100e3
record_every = 2000

[probe]
diameter = 0.012
velocity = 0.08
depth = 0.004
T
run test triaxial --specimen spec --recipe in/tri.toml --out tri --quiet --json
run test cpt --specimen spec --recipe in/cpt.toml --out cpt --quiet --json
run compare-curves tri/curve.csv tri/curve.csv --x axial_strain --y q_pa --json
run specimen-scale spec --factor 2 --out spec2
run crush --recipe "$src/assets/recipes/crush-quick.toml" --out crush --quiet --json
for e in lammps liggghts yade pfc vtk; do run export $e spec --out export-$e --json; done
run export lammps lib --density 2650 --out export-lib --json
run export lammps spec --test oedometer --out export-oed --json
# Bad input: one line and the exit code.
bad fill missing.stl -o x.csv
bad specimen --recipe in/missing.toml --out never
bad volume in/tiny.toml
echo "reference set: $n commands"
