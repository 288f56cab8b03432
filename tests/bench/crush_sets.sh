#!/usr/bin/env bash
# Hu et al. 2023 crushing benches: the Brazilian calibration, Table 1 (size), Table 2 (shape) and
# the numerical controls on Table 1's 27.5 mm set (rate ÷ 2, damping × 2, platen stiffness × 2,
# integration points × 4, dt ÷ 2, mass scaling ÷ 10), each a `clumpkit crush` run of a bundled
# recipe (or a variant of it written here), with its wall time.
#   tests/bench/crush_sets.sh [OUT] [WHAT...]   (default /tmp/clumpkit-crush; WHAT from
#   brazilian, table1, table2, controls; default all)
# Environment: THREADS (default 2), SAMPLES (samples per set, default the recipes' 30; 3 for the
# Brazilian disc), SCALE (the [bond] scale factor, default the recipes').
# Figures go to tests/bench/RESULTS.md with the command and date.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${CLUMPKIT:-$root/build/io/clumpkit}
out=${1:-/tmp/clumpkit-crush}
shift || true
what=${*:-brazilian table1 table2 controls}
threads=${THREADS:-2}
mkdir -p "$out" && cd "$out"

variant() {  # SOURCE NAME SED-EXPRESSIONS...: a recipe variant
  local src=$1 name=$2
  shift 2
  cp "$root/assets/recipes/$src" "$name.toml"
  [ -n "${SAMPLES:-}" ] && sed -i "s/^samples = 30/samples = $SAMPLES/" "$name.toml"
  [ -n "${SCALE:-}" ] && sed -i "s/^scale = [0-9.]*/scale = $SCALE/" "$name.toml"
  for e in "$@"; do sed -i "$e" "$name.toml"; done
}

run() {  # NAME
  [ -f "$1/report.json" ] && return 0
  local t0=$(date +%s.%N)
  "$bin" crush --quiet --threads "$threads" --recipe "$1.toml" --out "$1" > "$1.txt"
  python3 -c "print(round($(date +%s.%N) - $t0, 1))" > "$1.seconds"
  echo "== $1 ($(cat "$1.seconds") s)"
  cat "$1.txt"
}

first_set() {  # FILE: keeps the recipe's first [[set]] only
  python3 -c "import sys; t = open(sys.argv[1]).read(); i = t.find('[[set]]'); j = t.find('[[set]]', i + 1)
open(sys.argv[1], 'w').write(t if j < 0 else t[:j])" "$1"
}

for w in $what; do
  case $w in
    brazilian)
      variant crush-brazilian.toml brazilian
      run brazilian ;;
    table1)
      variant crush-table1.toml table1
      run table1 ;;
    table2)
      variant crush-table2.toml table2
      run table2 ;;
    controls)
      variant crush-table1.toml c-base
      first_set c-base.toml
      run c-base
      sed -e 's/^strain_rate = 0.4/strain_rate = 0.2/' c-base.toml > c-rate.toml && run c-rate
      sed -e 's/^local_damping = \(.*\)/local_damping = 0.7/' c-base.toml > c-damping.toml && run c-damping
      sed -e 's/^platen_stiffness = 1e7 /platen_stiffness = 2e7 /' c-base.toml > c-platen.toml && run c-platen
      sed -e 's/^lloyd = 3/lloyd = 3\nface_subdivision = 1/' c-base.toml > c-points.toml && run c-points
      sed -e 's/^timestep_safety = 0.2/timestep_safety = 0.1/' c-base.toml > c-dt.toml && run c-dt
      sed -e 's/^density_scaling = 1000/density_scaling = 100/' c-base.toml > c-lambda.toml && run c-lambda ;;
    *) echo "unknown bench $w (brazilian, table1, table2, controls)" >&2; exit 2 ;;
  esac
done
