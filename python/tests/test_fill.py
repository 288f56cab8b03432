"""fill against `clumpkit fill` (the same spheres to the last bit), its progress reports, and
stopping it: an exception from the progress callable, and Ctrl-C (SIGINT) from outside."""
import _thread

import numpy as np
import pytest

import clumpkit
from conftest import read_clump_csv


@pytest.fixture(scope="module")
def rock(tmp_path_factory):
    path = tmp_path_factory.mktemp("rock") / "rock.stl"
    clumpkit.block(0.04, 0.03, 0.02, seed=7).write(str(path))
    return str(path)


@pytest.mark.parametrize("options, flags", [
    (dict(spheres=30), ["--spheres", 30]),
    (dict(coverage=0.8, voxels=30, max_overshoot=0.0), ["--coverage", 0.8, "--voxels", 30,
                                                        "--max-overshoot", 0]),
])
def test_fill_equals_the_command_line(cli, tmp_path, rock, options, flags):
    clump = clumpkit.fill(clumpkit.read_mesh(rock), **options)
    report = cli("fill", rock, "-o", tmp_path / "c.csv", "--json", *flags, as_json=True)
    rows = np.array(read_clump_csv(tmp_path / "c.csv"))
    assert clump.centres.dtype == np.float64 and clump.centres.flags["C_CONTIGUOUS"]
    assert np.array_equal(clump.centres, rows[:, :3]) and np.array_equal(clump.radii, rows[:, 3])
    f = clump.fidelity.as_dict()
    for key in ("covered_fraction", "overshoot_fraction", "clump_volume", "mesh_volume"):
        assert f[key] == report[key], key
    # The attributes and the record come from one list of fields: the same names and values.
    for key, value in f.items():
        assert getattr(clump.fidelity, key) == value, key
    assert clump.stopped_by == report["stopped_by"] and clump.voxel == report["voxel"]
    assert len(clump.coverage_curve) == len(clump) and np.all(np.diff(clump.coverage_curve) > 0)


def test_progress_reports_fill_fractions_in_order(rock):
    seen = []
    clumpkit.fill(clumpkit.read_mesh(rock), spheres=200, voxels=60,
                  progress=lambda stage, fraction: seen.append((stage, fraction)))
    assert seen and {s for s, _ in seen} == {"fill"}
    fractions = [f for _, f in seen]
    assert all(0.0 <= f <= 1.0 for f in fractions) and fractions == sorted(fractions)


def test_an_error_in_progress_stops_the_fill_and_is_raised(rock):
    calls = []

    def progress(stage, fraction):
        calls.append(fraction)
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        clumpkit.fill(clumpkit.read_mesh(rock), spheres=5000, voxels=80, progress=progress)
    assert len(calls) == 1


def test_ctrl_c_stops_the_fill_with_keyboard_interrupt(rock):
    # The signal arrives while the fill runs (simulated with _thread.interrupt_main() from the
    # progress callable at the first report: the same flag a Ctrl-C sets); the main thread turns
    # it into a stop request and KeyboardInterrupt. The latency is measured in
    # tests/bench/python_bench.py, not asserted here.
    heard = []

    def progress(stage, fraction):
        heard.append(fraction)
        _thread.interrupt_main()

    with pytest.raises(KeyboardInterrupt):
        clumpkit.fill(clumpkit.read_mesh(rock), spheres=3000, voxels=60, progress=progress)
    assert len(heard) == 1 and heard[0] < 1.0


def test_bad_fill_options_raise_value_error(rock):
    mesh = clumpkit.read_mesh(rock)
    with pytest.raises(ValueError, match="spheres must be at least 1, got 0"):
        clumpkit.fill(mesh, spheres=0)
    with pytest.raises(ValueError, match="coverage"):
        clumpkit.fill(mesh, coverage=1.5)
    with pytest.raises(ValueError, match="min_radius|min-radius"):
        clumpkit.fill(mesh, min_radius=float("nan"))
