#!/usr/bin/env bash
# Oedometer cross-check with LAMMPS (issue 16 acceptance 7): the bundled quick specimen is
# consolidated by `clumpkit test oedometer` to 10 kPa and loaded to 500 kPa; the consolidated
# state (--save-consolidated) is exported with `--test oedometer` and loaded by LAMMPS at the same
# strain rate between frictionless walls. Prints both constrained moduli (least-squares slope of
# axial stress against axial strain over 100-400 kPa, as report.json's constrained_modulus) and
# their ratio.
#   tests/bench/lammps_oedometer.sh [OUT]   (default /tmp/clumpkit-lammps-oedometer; ~15 min on
#   one core: specimen 2.5 min, clumpkit test 8 min, LAMMPS 3 min)
# SPECIMEN=DIR reuses a built quick specimen; RANKS=N runs LAMMPS on N MPI ranks (default 1).
# Needs build/io/clumpkit (scripts/build) and lmp (Debian package lammps).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/tests/bench  # clumpkit_csv.py: CSV columns by bare name
bin=${CLUMPKIT:-$root/build/io/clumpkit}
out=${1:-/tmp/clumpkit-lammps-oedometer}
ranks=${RANKS:-1}
command -v lmp > /dev/null || { echo "lammps_oedometer.sh: needs lmp (apt-get install lammps)" >&2; exit 2; }
rm -rf "$out" && mkdir -p "$out" && cd "$out"
spec=${SPECIMEN:-}
if [ -z "$spec" ]; then
  "$bin" specimen --quiet --threads 1 --recipe "$root/assets/recipes/quick-specimen.toml" --out quick
  spec=quick
fi
rate=0.2  # 1/s: inertial number 8e-4 at 100 kPa on the quick specimen
cat > oed.toml <<EOF
name = "lammps-oedometer-cross-check"
[test]
confining = 10e3
final_stress = 500e3
strain_rate = $rate
record_every = 100
modulus_range = [100e3, 400e3]
EOF
"$bin" test oedometer --quiet --threads 1 --specimen "$spec" --recipe oed.toml --out oed \
  --save-consolidated
"$bin" export lammps oed/consolidated --out lmp --test oedometer --strain-rate "$rate" \
  --max-strain 0.02
(cd lmp && if [ "$ranks" -gt 1 ]; then
   mpirun --allow-run-as-root -np "$ranks" lmp -in in.clumpkit > log.txt
 else
   lmp -in in.clumpkit > log.txt
 fi)
PYTHONPATH="$here" python3 - oed/curve.csv lmp/oedometer.csv <<'PY'
import clumpkit_csv, sys
def slope(path, xs, ys, lo=100e3, hi=400e3):
    n = sx = sy = sxx = sxy = 0.0
    for row in clumpkit_csv.rows(path):
        x, y = float(row[xs]), float(row[ys])
        if lo <= y <= hi:
            n += 1; sx += x; sy += y; sxx += x * x; sxy += x * y
    return (n * sxy - sx * sy) / (n * sxx - sx * sx), int(n)
m1, n1 = slope(sys.argv[1], "axial_strain", "axial_stress")
m2, n2 = slope(sys.argv[2], "strain", "stress")
print(f"constrained modulus 100-400 kPa: clumpkit {m1 / 1e6:.2f} MPa ({n1} rows), "
      f"LAMMPS {m2 / 1e6:.2f} MPa ({n2} rows), LAMMPS/clumpkit {m2 / m1:.3f}")
PY
