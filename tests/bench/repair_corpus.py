#!/usr/bin/env python3
"""Every mesh of a folder through `describe`, `repair` and `fill`: what the
mesh was (triangles, whether `describe` takes it as it is), what `repair` did (steps used, volume
change, distance to the input, seconds and peak memory on one core), and whether `describe` and
`fill --spheres 20` accept the result. Any crash, signal, multi-line error or partial output is a
defect and is listed last.

    tests/bench/repair_corpus.py FOLDER [--bin build/io/clumpkit] [--out /tmp/repair-corpus]

The corpus of RESULTS.md is not in the repository: tests/bench/repair_corpus_sources.csv
names each file's public repository, commit and path (OFF files were converted to OBJ as
triangle fans). Prints a Markdown table (one row per mesh) for tests/bench/RESULTS.md. Single-threaded
(`taskset -c 0` when available) so that the seconds compare with the acceptance's one-core bound.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys

MESH = (".stl", ".obj", ".ply")


def run(cmd, timeout=600):
    """(exit code, stdout, stderr, wall s, peak MiB) of cmd under /usr/bin/time -v."""
    full = ["/usr/bin/time", "-v"] + cmd
    if shutil.which("taskset"):
        full = ["taskset", "-c", "0"] + full
    try:
        p = subprocess.run(full, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return 124, "", "timed out", float(timeout), 0.0
    err = p.stderr
    wall = peak = 0.0
    m = re.search(r"Elapsed \(wall clock\) time.*: (\S+)", err)
    if m:
        for part in m.group(1).split(":"):
            wall = wall * 60 + float(part)
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", err)
    if m:
        peak = int(m.group(1)) / 1024
    # What clumpkit itself wrote: the lines before /usr/bin/time's report.
    own = err.split("\tCommand being timed")[0]
    if "Command exited with non-zero status" in own:
        own = own.split("Command exited with non-zero status")[0]
    return p.returncode, p.stdout, own.strip(), wall, peak


def defects(code, err, outputs):
    """What would be a defect: a signal, a crash, an error of several lines, a partial output."""
    found = []
    if code < 0 or code > 128 and code != 130:
        found.append(f"exit {code} (signal)")
    if code != 0:
        lines = [l for l in err.splitlines() if l and not l.startswith("clumpkit: note")
                 and not l.startswith("clumpkit: warning")]
        if len(lines) != 1:
            found.append(f"{len(lines)}-line error")
        for o in outputs:
            if os.path.exists(o):
                found.append(f"partial output {os.path.basename(o)}")
    return found


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("folder")
    ap.add_argument("--bin", default="build/io/clumpkit")
    ap.add_argument("--out", default="/tmp/repair-corpus")
    a = ap.parse_args()
    binary = os.path.realpath(a.bin)
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    rows, bad = [], []
    names = sorted(f for f in os.listdir(a.folder) if f.lower().endswith(MESH))
    for name in names:
        src = os.path.join(a.folder, name)
        stem = os.path.splitext(name)[0]
        code, out, err, _, _ = run([binary, "describe", src, "--json"])
        raw_ok = code == 0
        for d in defects(code, err, []):
            bad.append(f"{name}: describe: {d}: {err[:200]}")
        fixed = os.path.join(a.out, stem + ".ply")
        code, out, err, wall, peak = run([binary, "repair", src, "-o", fixed, "--json"])
        for d in defects(code, err, [fixed]):
            bad.append(f"{name}: repair: {d}: {err[:300]}")
        row = {"name": name, "raw_ok": raw_ok, "repair_code": code, "seconds": wall, "peak": peak}
        if code == 0:
            r = json.loads(out)
            si = r["self_intersections"]
            steps = []
            if r["merged_vertices"]:
                steps.append("weld")
            if r["duplicate_triangles"] or r["double_wall_triangles"] or r["repeated_vertex_triangles"]:
                steps.append("duplicates")
            if r["split_vertices"]:
                steps.append("non-manifold")
            if r["degenerate_triangles"]:
                steps.append("degenerate")
            if r["small_components"]:
                steps.append("small components")
            if r["holes"]:
                steps.append(f"holes ({r['holes']})")
            if si["local_rounds"]:
                steps.append(f"local ({len(si['local_rounds'])} rounds)")
            if si["united_shells"]:
                steps.append(f"union ({si['united_shells']})")
            if r["wrap"]["applied"]:
                steps.append(f"wrap ({r['wrap']['seconds']:.2f} s)")
            row.update(
                triangles_out=r["triangles"], steps=", ".join(steps) or "none",
                crossings=si["crossings_within_shells"] + si["crossings_between_shells"],
                volume_capped=si["volume_capped"], volume_after=r["volume_after"],
                distance=r.get("distance", {}).get("max_fraction"), warnings=len(r["warnings"]))
            code, out, err, _, _ = run([binary, "describe", fixed, "--json"])
            row["describe"] = code == 0
            for d in defects(code, err, []):
                bad.append(f"{name}: describe repaired: {d}")
            if code != 0:
                bad.append(f"{name}: describe refuses the repaired mesh: {err[:300]}")
            clump = os.path.join(a.out, stem + ".csv")
            code, out, err, fw, _ = run([binary, "fill", fixed, "-o", clump, "--spheres", "20"])
            row["fill"] = code == 0
            row["fill_seconds"] = fw
            for d in defects(code, err, [clump]):
                bad.append(f"{name}: fill: {d}")
            if code != 0:
                bad.append(f"{name}: fill refuses the repaired mesh: {err[:300]}")
        else:
            row["error"] = err.splitlines()[-1] if err else ""
        # The raw file through fill --repair as well: the one-command path.
        clump = os.path.join(a.out, stem + "-direct.csv")
        code, out, err, _, _ = run([binary, "fill", src, "--repair", "-o", clump, "--spheres", "20"])
        row["fill_repair"] = code == 0
        for d in defects(code, err, [clump]):
            bad.append(f"{name}: fill --repair: {d}: {err[:300]}")
        if (code == 0) != (row["repair_code"] == 0):
            bad.append(f"{name}: fill --repair exit {code} but repair exit {row['repair_code']}")
        rows.append(row)
        print(f"{name}: repair exit {row['repair_code']} in {wall:.2f} s", file=sys.stderr)

    print("| mesh | as read | repair: steps | triangles out | crossing pairs | volume capped -> after "
          "| max distance / diag | s | MiB | describe, fill |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if r["repair_code"] == 0:
            # The capped surface may face inward (orientation comes after): its size counts.
            capped = abs(r["volume_capped"])
            change = (r["volume_after"] / capped - 1) * 100 if capped else 0
            dist = f"{100 * r['distance']:.3f} %" if r["distance"] is not None else "-"
            print(f"| {r['name']} | {'solid' if r['raw_ok'] else 'refused'} | {r['steps']} | "
                  f"{r['triangles_out']} | {r['crossings']} | {abs(r['volume_capped']):.4g} -> "
                  f"{r['volume_after']:.4g} ({change:+.2f} %) | {dist} | {r['seconds']:.2f} | "
                  f"{r['peak']:.0f} | {'yes' if r['describe'] else 'NO'}, "
                  f"{'yes' if r['fill'] else 'NO'} |")
        else:
            print(f"| {r['name']} | {'solid' if r['raw_ok'] else 'refused'} | refused: "
                  f"{r.get('error', '')[:160]} | | | | | {r['seconds']:.2f} | {r['peak']:.0f} | |")
    repaired = sum(1 for r in rows if r["repair_code"] == 0)
    print(f"\n{len(rows)} meshes: {repaired} repaired, {len(rows) - repaired} refused; "
          f"{sum(1 for r in rows if r.get('fill'))} filled after repair, "
          f"{sum(1 for r in rows if r['fill_repair'])} by fill --repair")
    print(f"defects: {len(bad)}")
    for b in bad:
        print(f"- {b}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
