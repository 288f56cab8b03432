"""Meshes from arrays and files, the shape generators against `clumpkit shape`, and describe
against `clumpkit describe --json`."""
import math

import numpy as np
import pytest

import clumpkit


def box_arrays():
    m = clumpkit.box((2.0, 3.0, 4.0))
    return m.vertices, m.triangles


def test_arrays_round_trip_as_float64_int64_c_order():
    v, t = box_arrays()
    assert v.dtype == np.float64 and v.flags["C_CONTIGUOUS"] and v.shape == (8, 3)
    assert t.dtype == np.int64 and t.flags["C_CONTIGUOUS"] and t.shape == (12, 3)
    m = clumpkit.Mesh(v, t)
    assert np.array_equal(m.vertices, v) and np.array_equal(m.triangles, t)
    assert m.volume == pytest.approx(24.0, rel=1e-15)
    assert m.area == pytest.approx(2 * (6 + 8 + 12), rel=1e-15)
    assert np.allclose(m.centroid, 0.0, atol=1e-15)


def test_lists_int32_and_strided_arrays_are_accepted():
    v, t = box_arrays()
    wide = np.zeros((8, 6))
    wide[:, ::2] = v  # a strided view: copied to C order
    m = clumpkit.Mesh(wide[:, ::2], t.astype(np.int32))
    assert m.volume == pytest.approx(24.0)
    assert clumpkit.Mesh(v.tolist(), t.tolist()).volume == pytest.approx(24.0)


def test_an_inward_mesh_is_turned_outward():
    v, t = box_arrays()
    assert clumpkit.Mesh(v, t[:, ::-1]).volume == pytest.approx(24.0)


@pytest.mark.parametrize(
    "change, message",
    [
        (lambda v, t: (np.where(np.arange(24).reshape(8, 3) == 4, np.nan, v), t), "vertex 1 "),
        (lambda v, t: (v, t[1:]), "mesh is open: 3 boundary edges"),
        (lambda v, t: (v, np.where(t == 7, 8, t)), "vertex index 8, outside 0..7"),
        (lambda v, t: (v[:, :2], t), "expected an (n, 3) array, got shape (8, 2)"),
        (lambda v, t: (np.zeros((0, 3)), t), "vertices: the array is empty"),
        (lambda v, t: (v, np.zeros((0, 3), dtype=int)), "triangles: the array is empty"),
    ],
)
def test_bad_meshes_raise_value_error_with_the_library_message(change, message):
    v, t = change(*box_arrays())
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        clumpkit.Mesh(v, t)


def test_files(tmp_path):
    with pytest.raises(OSError, match="missing.stl"):
        clumpkit.read_mesh(str(tmp_path / "missing.stl"))
    m = clumpkit.polyhedron(0.03, seed=3)
    m.write(str(tmp_path / "p.obj"))
    back = clumpkit.read_mesh(str(tmp_path / "p.obj"))
    assert np.array_equal(back.vertices, m.vertices)  # OBJ keeps every bit
    with pytest.raises(ValueError, match="unknown mesh format '.xyz'"):
        m.write(str(tmp_path / "p.xyz"))


@pytest.mark.parametrize(
    "name, py, args",
    [
        ("block", lambda: clumpkit.block(0.04, 0.03, 0.02, nd=3, seed=11),
         ["--L", 0.04, "--W", 0.03, "--H", 0.02, "--nd", 3, "--seed", 11]),
        ("hull", lambda: clumpkit.hull(0.02, points=25, roundness=(1.0, 4.0), seed=5),
         ["--diameter", 0.02, "--points", 25, "--roundness", "1:4", "--seed", 5]),
        ("polyhedron", lambda: clumpkit.polyhedron(0.0275, planes=20, E=0.8, F=0.7, seed=2),
         ["--diameter", 0.0275, "--planes", 20, "--E", 0.8, "--F", 0.7, "--seed", 2]),
        ("ellipsoid", lambda: clumpkit.ellipsoid((3.0, 2.0, 1.0), level=3),
         ["--axes", "3,2,1", "--level", 3]),
        ("cylinder", lambda: clumpkit.cylinder(0.05, 0.05, sides=32),
         ["--diameter", 0.05, "--height", 0.05, "--sides", 32]),
        ("box", lambda: clumpkit.box((1.0, 2.0, 3.0)), ["--size", "1,2,3"]),
    ],
)
def test_shapes_and_descriptors_equal_the_command_line(cli, tmp_path, name, py, args):
    mesh = py()
    mesh.write(str(tmp_path / "py.obj"))
    cli("shape", name, *args, "-o", tmp_path / "cli.obj")
    assert (tmp_path / "py.obj").read_bytes() == (tmp_path / "cli.obj").read_bytes()
    d = clumpkit.describe(mesh)
    want = cli("describe", tmp_path / "cli.obj", "--json", as_json=True)
    got = d.as_dict()
    for key in ("volume", "area", "sphericity", "L", "W", "H", "E", "F", "convexity",
                "weighted_roundness"):
        assert got[key] == want[key], key
    assert d.volume == want["volume"] and list(d.axes) == want["axes"]


def test_descriptor_oracles():
    d = clumpkit.describe(clumpkit.box((1.0, 2.0, 4.0)))
    assert d.L == pytest.approx(math.sqrt(21.0), rel=1e-12)  # the space diagonal
    assert d.axes.tolist() == pytest.approx([1.0, 2.0, 4.0], rel=1e-12)  # S, I, L
    assert (d.E, d.F, d.AR) == pytest.approx((0.5, 0.5, 0.25), rel=1e-12)
    assert d.volume == pytest.approx(8.0, rel=1e-15)
    assert d.convexity == pytest.approx(1.0, rel=1e-12)
    assert d.sphericity == pytest.approx(math.pi ** (1 / 3) * 48 ** (2 / 3) / 28, rel=1e-12)
