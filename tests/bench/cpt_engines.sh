#!/usr/bin/env bash
# The same CPT in both engines (issue 56): a specimen of CTGU 2017's group GROUP built from
# assets/recipes/cpt-GROUP.toml with seed SEED, pushed by `clumpkit test cpt` (its consolidated
# state saved), then by the LAMMPS deck exported from that state (`clumpkit export lammps
# DIR/consolidated --test cpt`, the same masses, step and probe) on each of RANKS. Prints mean qc
# over 5–8 D_c of every push, `compare-curves` of each LAMMPS push against clumpkit's (and np 1
# against np 2), and the seconds per push step of each; draws qc–depth of each pair.
#   tests/bench/cpt_engines.sh [OUT]   (default /tmp/clumpkit-cpt-engines)
# Environment: GROUP (A), SEED (1), DENSITY_SCALING (100, as tests/bench/cpt_groups.sh's runs),
# DEPTH (push depth, default the recipe's 0.144 m), THREADS (2), RANKS ("1 2"). Needs
# build/io/clumpkit and lmp (+ mpirun for more than one rank). Group A at λ = 100: about 15 min
# for clumpkit's push on 2 threads and 25–45 min per LAMMPS push.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/tests/bench  # clumpkit_csv.py: CSV columns by bare name
bin=${CLUMPKIT:-$root/build/io/clumpkit}
out=${1:-/tmp/clumpkit-cpt-engines}
group=${GROUP:-A}
seed=${SEED:-1}
lambda=${DENSITY_SCALING:-100}
depth=${DEPTH:-0.144}
threads=${THREADS:-2}
ranks=${RANKS:-1 2}
command -v lmp > /dev/null || { echo "cpt_engines.sh: needs lmp (apt-get install lammps)" >&2; exit 2; }
mkdir -p "$out" && cd "$out"
sed -e "s/^depth = .*/depth = $depth/" \
    -e "s/^\[test\]/[test]\ndensity_scaling = $lambda/" "$root/assets/recipes/test-cpt.toml" > test.toml
sed -e "s/^seed = .*/seed = $seed/" "$root/assets/recipes/cpt-$group.toml" > spec.toml
[ -d spec ] || "$bin" specimen --quiet --threads "$threads" --recipe spec.toml --out spec
if [ ! -f ck/curve.csv ]; then
  rm -rf ck ck.partial
  t0=$(date +%s.%N)
  "$bin" test cpt --quiet --threads "$threads" --specimen spec --recipe test.toml --out ck \
    --save-consolidated
  python3 -c "print($(date +%s.%N) - $t0)" > ck/seconds
fi
for n in $ranks; do
  [ -f "lmp$n/cpt.csv" ] && [ -f "lmp$n/seconds" ] && continue
  rm -rf "lmp$n"
  "$bin" export lammps ck/consolidated --test cpt --recipe test.toml --out "lmp$n" > /dev/null
  (cd "lmp$n" && t0=$(date +%s.%N) &&
   if [ "$n" -gt 1 ]; then
     mpirun --allow-run-as-root --oversubscribe -np "$n" lmp -in in.clumpkit -log log.txt > run.txt
   else
     lmp -in in.clumpkit -log log.txt > run.txt
   fi && python3 -c "print($(date +%s.%N) - $t0)" > seconds)
done
first=${ranks%% *}
for n in $ranks; do
  "$bin" compare-curves ck/curve.csv "lmp$n/cpt.csv" --png "clumpkit-vs-lammps-np$n.png" --json \
    > "residual-np$n.json"
  [ "$n" != "$first" ] &&
    "$bin" compare-curves "lmp$first/cpt.csv" "lmp$n/cpt.csv" --json > "residual-np$first-np$n.json"
done
PYTHONPATH="$here" python3 - "$ranks" <<'PY'
import clumpkit_csv, json, re, sys
ranks = sys.argv[1].split()
def mean_qc(path, lo=5 * 0.018, hi=8 * 0.018):
    rows = [r for r in clumpkit_csv.rows(path) if lo <= float(r["depth"]) <= hi]
    return sum(float(r["qc"]) for r in rows) / len(rows) if rows else float("nan")
rep = json.load(open("ck/report.json"))
ck_steps = rep["consolidation_steps"] + rep["steps"]
ck_seconds = float(open("ck/seconds").read())
print("| push | mean qc 5–8 D_c [MPa] | residual_rel vs clumpkit | push steps | s per push step |")
print("|---|---|---|---|---|")
# clumpkit's seconds cover consolidation and push, steps of the same world: per step over both.
print(f"| clumpkit ({ck_steps} steps, {ck_seconds:.0f} s) | {mean_qc('ck/curve.csv') / 1e6:.3f} | "
      f"0 | {rep['steps']} | {ck_seconds / ck_steps:.3e} |")
for n in ranks:
    log = open(f"lmp{n}/log.txt").read()
    loops = re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps", log)
    secs, steps = float(loops[-1][0]), int(loops[-1][1])
    r = json.load(open(f"residual-np{n}.json"))
    print(f"| LAMMPS np {n} | {mean_qc(f'lmp{n}/cpt.csv') / 1e6:.3f} | {r['residual_rel']:.4g} | "
          f"{steps} | {secs / steps:.3e} |")
for n in ranks[1:]:
    r = json.load(open(f"residual-np{ranks[0]}-np{n}.json"))
    print(f"LAMMPS np {n} against np {ranks[0]}: residual_rel {r['residual_rel']:.4g}")
PY
