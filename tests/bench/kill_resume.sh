#!/usr/bin/env bash
# Fault bench (issue 15): N SIGTERMs at random times into `specimen` on the bundled quick recipe
# and `library` on its rock recipe, each run then resumed (specimen: --resume; library: the same
# command), and its outputs compared file by file with a run never stopped (JSON files with their
# wall-clock "seconds" fields left out). Prints one row per stop and a summary per job; exits 1 if
# any output differs. Minutes: (N + 1) quick specimens and libraries.
#   tests/bench/kill_resume.sh [N=10] [BINARY=build/io/clumpkit]
set -euo pipefail
cd "$(dirname "$0")/../.."
n=${1:-10}
bin=$(realpath "${2:-build/io/clumpkit}")
recipes=$(pwd)/assets/recipes
work=$(mktemp -d "${TMPDIR:-/tmp}/clumpkit-kill-resume.XXXXXX")
trap 'rm -rf "$work"' EXIT

same_outputs() {  # DIR_A DIR_B: 0 when every file is the same (JSON: "seconds" aside)
  python3 - "$1" "$2" <<'PY'
import json, os, sys
def files(root):
    return sorted(os.path.relpath(os.path.join(d, f), root)
                  for d, _, fs in os.walk(root) for f in fs)
def strip(o):
    if isinstance(o, dict):
        return {k: strip(v) for k, v in o.items() if k != "seconds"}
    if isinstance(o, list):
        return [strip(v) for v in o]
    return o
a, b = sys.argv[1:]
if files(a) != files(b):
    sys.exit("different files")
for f in files(a):
    pa, pb = os.path.join(a, f), os.path.join(b, f)
    if f.endswith(".json"):
        same = strip(json.load(open(pa))) == strip(json.load(open(pb)))
    else:
        same = open(pa, "rb").read() == open(pb, "rb").read()
    if not same:
        sys.exit(f + " differs")
PY
}

bench() {  # NAME ARGS...: the clean run, then N stopped and resumed runs
  local name=$1 resume=$2
  shift 2
  local start end whole identical=0
  mkdir -p "$work/$name"
  start=$(date +%s.%N)
  "$bin" "$@" --quiet --out "$work/$name/out" >/dev/null
  end=$(date +%s.%N)
  whole=$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')
  mv "$work/$name/out" "$work/$name/clean"
  printf '%s: run never stopped %.1f s\n' "$name" "$whole"
  printf '%-9s %4s %10s %5s %12s %s\n' job stop "sigterm_s" exit "resumed_s" outputs
  for i in $(seq "$n"); do
    local when rc resumed verdict
    when=$(awk -v w="$whole" -v r="$(od -An -N4 -tu4 /dev/urandom)" \
      'BEGIN { printf "%.3f", w * (0.02 + 0.96 * r / 4294967295) }')
    rm -rf "$work/$name/out" "$work/$name/out.partial"
    "$bin" "$@" --quiet --out "$work/$name/out" >/dev/null 2>"$work/$name/stop.err" &
    local pid=$!
    sleep "$when"
    kill -TERM "$pid" 2>/dev/null || true
    rc=0
    wait "$pid" || rc=$?
    resumed=0
    if [ "$rc" != 0 ]; then  # 130: stopped at a safe point; 143: killed before it began
      start=$(date +%s.%N)
      # shellcheck disable=SC2086
      "$bin" "$@" $resume --quiet --out "$work/$name/out" >/dev/null
      end=$(date +%s.%N)
      resumed=$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')
    fi
    if verdict=$(same_outputs "$work/$name/clean" "$work/$name/out" 2>&1); then
      verdict=identical
      identical=$((identical + 1))
    fi
    printf '%-9s %4d %10s %5s %12.1f %s\n' "$name" "$i" "$when" "$rc" "$resumed" "$verdict"
  done
  printf '%s: %d of %d stopped runs byte-identical after resuming\n\n' "$name" "$identical" "$n"
  [ "$identical" = "$n" ]
}

status=0
bench specimen --resume specimen --recipe "$recipes/quick-specimen.toml" || status=1
bench library "" library --recipe "$recipes/quick-rocks.toml" || status=1
exit $status
