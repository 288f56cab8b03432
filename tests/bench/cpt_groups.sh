#!/usr/bin/env bash
# CTGU 2017's CPT groups A–E and A′ (A with another seed): each specimen built from
# assets/recipes/cpt-X.toml with the seed set, pushed with assets/recipes/test-cpt.toml, then
# the residual of each qc–depth curve against A's of the same seed (`clumpkit compare-curves`,
# 200 points), the mean qc at depths 5–8 D_c, and wall times; then CTGU 2017's ranking with its
# 90 % bootstrap intervals over the seeds (tests/bench/cpt_ranking.py, from the surface and from
# 1 D_c; RESIDUALS=tests/bench/cpt_residuals_recorded.csv pools the recorded seeds 1–3).
#   tests/bench/cpt_groups.sh [OUT]   (default /tmp/clumpkit-cpt-groups)
# Environment: SEEDS (default "1 2 3"), CPT_GROUPS (default "A B C D E"), DENSITY_SCALING (default 1:
# none; the masses × λ shorten the push by √λ steps — check it against λ = 1 first), DEPTH (push
# depth, default the recipe's 0.144 m), THREADS (default 2). Hours on 2 cores at λ = 1.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/tests/bench  # clumpkit_csv.py: CSV columns by bare name
bin=${CLUMPKIT:-$root/build/io/clumpkit}
out=${1:-/tmp/clumpkit-cpt-groups}
seeds=${SEEDS:-1 2 3}
groups=${CPT_GROUPS:-A B C D E}
lambda=${DENSITY_SCALING:-1}
depth=${DEPTH:-0.144}
threads=${THREADS:-2}
recorded=${RESIDUALS:+$(realpath "$RESIDUALS")}
mkdir -p "$out" && cd "$out"
sed -e "s/^depth = .*/depth = $depth/" \
    -e "s/^\[test\]/[test]\ndensity_scaling = $lambda/" "$root/assets/recipes/test-cpt.toml" > test.toml

run() {  # GROUP SEED NAME
  [ -f "$3-test/curve.csv" ] && return 0  # done by an earlier run of this script
  sed -e "s/^seed = .*/seed = $2/" "$root/assets/recipes/cpt-$1.toml" > "$3.toml"
  # A run killed part way (the session ended) resumes its checkpoint; a resumed push's seconds
  # count only its last part.
  local resume=()
  [ -d "$3.partial" ] && resume=(--resume)
  [ -d "$3" ] || "$bin" specimen --quiet --threads "$threads" --recipe "$3.toml" --out "$3" "${resume[@]}"
  resume=()
  [ -d "$3-test.partial" ] && resume=(--resume)
  local t0=$(date +%s.%N)
  "$bin" test cpt --quiet --threads "$threads" --specimen "$3" --recipe test.toml --out "$3-test" \
    "${resume[@]}"
  python3 -c "print($(date +%s.%N) - $t0)" > "$3-test/seconds"
}
for s in $seeds; do
  for g in $groups; do run "$g" "$s" "$g$s"; done
  run A $((s + 100)) "Aprime$s"
done

PYTHONPATH="$here" python3 - "$bin" "$seeds" "$groups" <<'PY'
import json, subprocess, sys, clumpkit_csv
bin, seeds, groups = sys.argv[1], sys.argv[2].split(), sys.argv[3].split()
def residual(a, b):
    r = subprocess.run([bin, "compare-curves", a, b, "--x", "depth_m", "--y", "qc_pa",
                        "--points", "200", "--json"], capture_output=True, text=True, check=True)
    return json.loads(r.stdout)["residual_rel"]
def mean_qc(path, lo=5 * 0.018, hi=8 * 0.018):
    rows = [r for r in clumpkit_csv.rows(path) if lo <= float(r["depth"]) <= hi]
    return sum(float(r["qc"]) for r in rows) / len(rows) if rows else float("nan")
print("| seed | group | e(X, A) rel | mean qc 5–8 D_c [MPa] | seconds |")
print("|---|---|---|---|---|")
for s in seeds:
    a = f"A{s}-test/curve.csv"
    for g in groups + ["Aprime"]:
        c = f"{g}{s}-test/curve.csv"
        e = residual(a, c) if g != "A" else 0.0
        print(f"| {s} | {g if g != 'Aprime' else 'A′'} | {e:.4g} | {mean_qc(c) / 1e6:.3f} | "
              f"{float(open(f'{g}{s}-test/seconds').read()):.0f} |")
PY
for start in 0 0.018; do
  echo
  python3 "$root/tests/bench/cpt_ranking.py" --clumpkit "$bin" --from "$start" \
    ${recorded:+--residuals "$recorded"} --json "ranking-from-$start.json" .
done
