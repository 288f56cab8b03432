#!/usr/bin/env bash
# CTGU 2017's ranking in the full 600 mm chambers (assets/recipes/cpt-X-full.toml) as LAMMPS runs
# for a cluster: `prepare` builds each specimen with clumpkit (seed s; A′ is A with seed s + 100),
# consolidates it to the test's confining stress (`clumpkit test cpt --save-consolidated` with a
# 0.1 mm push), exports the CPT deck of that state and writes jobs.txt, one line per run: its
# directory, the command and the estimated hours on RANKS ranks. After the runs, `collect`
# imports each finished cpt.csv into X{s}-test/ (as `clumpkit test cpt` names its output) and
# prints the ranking with its bootstrap intervals (tests/bench/cpt_ranking.py).
#   tests/bench/cpt_full_plan.sh prepare|collect [OUT]   (default /tmp/clumpkit-cpt-full)
# Environment: SEEDS ("1 2 3 4 5 6 7 8"), CPT_GROUPS ("A B C D E"), APRIME (1; 0: no A′ runs), DENSITY_SCALING (100, as the
# segment runs), RANKS (64), THREADS (2, clumpkit's), RANK_SECONDS (rank-seconds per push step
# per sphere: 3.9e-7, measured on this project's 2-core machine with the A-full deck at np 2, 100
# push steps of 342,638 spheres in 6.72 s; decks with stiffness classes (D, E: pair_style
# granular) take 1.71 times that, measured with D-full's; a cluster core is usually faster, and
# rank counts beyond about one per 2,000 spheres stop scaling). Building A-full took 53 min and
# its consolidation about 5 min on 2 cores: the A and A′ specimens are most of `prepare`.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${CLUMPKIT:-$root/build/io/clumpkit}
mode=${1:?usage: cpt_full_plan.sh prepare|collect [OUT]}
out=${2:-/tmp/clumpkit-cpt-full}
seeds=${SEEDS:-1 2 3 4 5 6 7 8}
groups=${CPT_GROUPS:-A B C D E}
lambda=${DENSITY_SCALING:-100}
ranks=${RANKS:-64}
threads=${THREADS:-2}
rank_seconds=${RANK_SECONDS:-3.9e-7}
mkdir -p "$out" && cd "$out"

names() {  # NAME GROUP SEED for every run
  for s in $seeds; do
    for g in $groups; do echo "$g$s $g $s"; done
    [ "${APRIME:-1}" = 0 ] || echo "Aprime$s A $((s + 100))"
  done
}

if [ "$mode" = prepare ]; then
  sed -e "s/^\[test\]/[test]\ndensity_scaling = $lambda/" "$root/assets/recipes/test-cpt.toml" \
    > test.toml
  sed -e "s/^depth = .*/depth = 0.0001/" test.toml > consolidate.toml
  : > jobs.txt
  names | while read -r name group seed; do
    sed -e "s/^seed = .*/seed = $seed/" "$root/assets/recipes/cpt-$group-full.toml" > "$name.toml"
    [ -f "$name/report.json" ] ||
      "$bin" specimen --quiet --threads "$threads" --recipe "$name.toml" --out "$name"
    [ -f "$name-c/consolidated/report.json" ] ||
      "$bin" test cpt --quiet --threads "$threads" --specimen "$name" --recipe consolidate.toml \
        --out "$name-c" --save-consolidated
    [ -f "$name-lmp/in.clumpkit" ] ||
      "$bin" export lammps "$name-c/consolidated" --test cpt --recipe test.toml \
        --out "$name-lmp" > /dev/null
    python3 - "$name" "$ranks" "$rank_seconds" >> jobs.txt <<'PY'
import json, math, sys, tomllib
name, ranks, per = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
m = json.load(open(f"{name}-lmp/manifest.json"))
rep = json.load(open(f"{name}-c/consolidated/report.json"))
test = tomllib.load(open("test.toml", "rb"))  # the push the deck runs (as npush counts it)
v, depth = test["probe"]["velocity"], test["probe"]["depth"]
every = test["test"]["record_every"]
steps = every * math.ceil(depth / (v * rep["test_timestep"] * every))
per *= 1.71 if "stiffness_classes" in m else 1.0  # pair_style granular (measured, D-full)
hours = steps * m["spheres"] * per / ranks / 3600
print(f"{name}-lmp\tmpirun -np {ranks} lmp -in in.clumpkit -log log.txt\t"
      f"{m['spheres']} spheres, {steps} steps, about {hours:.1f} h on {ranks} ranks")
PY
  done
  echo "jobs.txt: one run per line (directory, command, estimate); then: $0 collect $out"
elif [ "$mode" = collect ]; then
  names | while read -r name group seed; do
    [ -f "$name-lmp/cpt.csv" ] || { echo "$name: not run yet" >&2; continue; }
    [ -f "$name-test/curve.csv" ] ||
      "$bin" import lammps "$name-lmp" --specimen "$name-c/consolidated" --out "$name-test" \
        > /dev/null
  done
  for start in 0 0.018; do
    python3 "$root/tests/bench/cpt_ranking.py" --clumpkit "$bin" --from "$start" \
      --json "ranking-from-$start.json" . || echo "(no group beside A finished yet)"
    echo
  done
else
  echo "cpt_full_plan.sh: unknown mode '$mode' (prepare or collect)" >&2
  exit 2
fi
