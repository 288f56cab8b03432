"""Rows of a clumpkit CSV keyed by bare column names (docs/units.md).

Header cells carry their unit ("axial_stress[Pa]"); folders written before units carried some
in the name ("axial_stress_pa"). Both read as "axial_stress", so the bench scripts work on old
and new folders alike.
"""
import csv

OLD_NAMES = {
    "axial_stress_pa": "axial_stress", "radial_stress_pa": "radial_stress", "p_pa": "p",
    "q_pa": "q", "work_pa": "work", "depth_m": "depth", "tip_force_n": "tip_force",
    "sleeve_force_n": "sleeve_force", "qc_pa": "qc", "fs_pa": "fs", "sieve_m": "sieve",
    "diameter_m": "diameter", "peak_force_n": "peak_force", "peak_travel_m": "peak_travel",
    "strength_pa": "strength", "max_force_n": "max_force", "travel_m": "travel",
    "force_n": "force", "stress_pa": "stress",
}


def column_name(cell):
    """'volume[m3]' -> 'volume'; an old suffixed name -> today's."""
    if cell.endswith("]") and "[" in cell:
        return cell[:cell.index("[")]
    return OLD_NAMES.get(cell, cell)


def rows(path):
    """The data rows of the CSV at `path` ('#' lines skipped) as dicts of bare names."""
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    reader = csv.reader(lines)
    header = [column_name(c) for c in next(reader)]
    return [dict(zip(header, r)) for r in reader]
