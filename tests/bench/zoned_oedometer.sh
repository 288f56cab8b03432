#!/usr/bin/env bash
# Zoned oedometer (CTGU 2017's parallel check): a cylinder with 5 mm spheres to r = R/2 and 10 mm
# spheres beyond, beside uniform 5 mm and uniform 10 mm cylinders of the same size, each built
# by compression to n = 0.36 away from the walls; oedometer 100 -> 400 kPa with rigid platens,
# constrained modulus M (σ_a against ε_a) under kn ∝ d ("linear", d_ref 5 mm) and constant kn
# ("none"). Linear: M_zoned against M_d; none: M_zoned against 0.25·M_d + 0.75·M_2d.
# Each test reports the modulus from the platens and from the middle half of the height
# (constrained_modulus_interior). CONSOLIDATION_FRICTION (default 0.5, the test's μ) = 0
# consolidates frictionless, which makes the interior modulus independent of the cell's height
# in diameters (RESULTS.md) but takes far more steps to equilibrium.
#   tests/bench/zoned_oedometer.sh [OUT]   (default /tmp/clumpkit-zoned-oedometer; ~7 min on 2
#   cores at DIAMETER 0.160, HEIGHT 0.090: 17,000, 2,100 and 6,000 spheres; with
#   CONSOLIDATION_FRICTION=0, 5 min at 0.080 x 0.060 and over an hour at the default size)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${CLUMPKIT:-$root/build/io/clumpkit}
out=${1:-/tmp/clumpkit-zoned-oedometer}
diameter=${DIAMETER:-0.160}
height=${HEIGHT:-0.090}
rm -rf "$out" && mkdir -p "$out" && cd "$out"

recipe() {  # NAME SIEVE_HI SIEVE_LO ZONES
  cat > "$1.toml" <<TOML
soil_rock_threshold = 1.0
rock_mass_fraction = 0.0
[container]
diameter = $diameter
height = $height
[preparation]
method = "compression"
porosity = 0.36
friction = 0.0
[density]
soil = 2650
[contact]
kn = 5e6
ks = 5e6
friction = 0.5
[gradation]
sieves = [$2, $3]
passing = [100, 0]
[zones]
$4
TOML
  "$bin" specimen --quiet --recipe "$1.toml" --out "$1"
}
one='[[zones.region]]
outer = 1
scale = 1'
two="[[zones.region]]
outer = $(python3 -c "print($diameter / 4)")
scale = 1
[[zones.region]]
outer = 1
scale = 2"
recipe d 0.00505 0.00495 "$one"
recipe d2 0.0101 0.0099 "$one"
recipe zoned 0.00505 0.00495 "$two"
for law in linear none; do
  cat > "test-$law.toml" <<TOML
[test]
confining = 100e3
final_stress = 400e3
strain_rate = 0.5
record_every = ${RECORD_EVERY:-50}
friction = 0.5
consolidation_friction = ${CONSOLIDATION_FRICTION:-0.5}
[contact]
stiffness_scaling = "$law"
kn_ref = 5e6
d_ref = 0.005
ks_over_kn = 1.0
TOML
  for s in d d2 zoned; do
    "$bin" test oedometer --quiet --specimen "$s" --recipe "test-$law.toml" --out "o-$s-$law"
  done
done
python3 - <<'PY'
import json
M = {}
for s in ("d", "d2", "zoned"):
    for law in ("linear", "none"):
        r = json.load(open(f"o-{s}-{law}/report.json"))
        M[s, law, "platens"] = r["constrained_modulus"] / 1e6
        M[s, law, "interior"] = r["constrained_modulus_interior"] / 1e6
    z = json.load(open(f"{s}/report.json"))["zones"]
    print(f"{s}: " + ", ".join(f"zone {r['zone']}: {r['count']} spheres, n {r['porosity']:.4f}"
                               for r in z["regions"]) + f"; migrated {z['mis_zoned']}")
for w in ("platens", "interior"):
    for law in ("linear", "none"):
        d, d2, zo = (M[s, law, w] for s in ("d", "d2", "zoned"))
        print(f"{w} {law}: M_d {d:.1f}, M_2d {d2:.1f}, M_zoned {zo:.1f} MPa")
    print(f"{w} linear: M_zoned / M_d = {M['zoned', 'linear', w] / M['d', 'linear', w]:.3f}"
          " (acceptance: within 5 %)")
    par = 0.25 * M["d", "none", w] + 0.75 * M["d2", "none", w]
    print(f"{w} none: M_zoned / (0.25 M_d + 0.75 M_2d) = {M['zoned', 'none', w] / par:.3f}"
          " (acceptance: within 7 %)")
PY
