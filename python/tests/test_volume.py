"""mass_properties and volume of unions of spheres: analytic oracles, the command line's
`volume --json` to the last bit, and bad arrays."""
import math

import numpy as np
import pytest

import clumpkit


def test_one_sphere_and_two_apart_are_analytic():
    r, rho = 0.5, 2650.0
    p = clumpkit.mass_properties([[1.0, 2.0, 3.0]], [r], density=rho)
    v = 4.0 / 3.0 * math.pi * r**3
    assert p.volume == pytest.approx(v, rel=1e-14)
    assert p.mass == pytest.approx(rho * v, rel=1e-14)
    assert np.allclose(p.centroid, [1.0, 2.0, 3.0], rtol=1e-14)
    assert np.allclose(p.inertia, 0.4 * rho * v * r * r * np.eye(3), rtol=1e-12, atol=1e-12)
    assert p.area == pytest.approx(4 * math.pi * r * r, rel=1e-14)
    # Two unit spheres 4 apart on x: I_xx = 2·(2/5)mr², I_yy = I_zz = that + 2m·2².
    q = clumpkit.mass_properties([[0, 0, 0], [4, 0, 0]], [1.0, 1.0])
    m = 4.0 / 3.0 * math.pi
    assert np.allclose(q.principal_moments, [0.8 * m, 0.8 * m + 8 * m, 0.8 * m + 8 * m],
                       rtol=1e-12)
    assert abs(q.principal_axes[0, 0]) == pytest.approx(1.0, rel=1e-12)
    assert np.linalg.det(q.principal_axes) == pytest.approx(1.0, rel=1e-12)


def clump(n=60, seed=3):
    g = np.random.default_rng(seed)
    return g.uniform(-1, 1, (n, 3)), g.uniform(0.2, 0.5, n)


def write_csv(path, c, r):
    with open(path, "w") as f:
        f.write("x,y,z,r\n")
        for p, q in zip(c, r):
            f.write(",".join(repr(float(x)) for x in (*p, q)) + "\n")


def test_equals_the_command_line_to_the_last_bit(cli, tmp_path):
    c, r = clump()
    write_csv(tmp_path / "c.csv", c, r)
    want = cli("volume", tmp_path / "c.csv", "--method", "all", "--slices", 20, "--json",
               as_json=True)
    assert want.pop("units")["exact.volume"] == "L3"  # the file's own unit, unnamed
    p = clumpkit.mass_properties(c, r)
    assert p.volume == want["exact"]["volume"] and p.area == want["exact"]["area"]
    assert list(p.centroid) == want["exact"]["centroid"]
    assert p.inertia.tolist() == want["exact"]["inertia"]
    got = clumpkit.volume(c, r, "all", slices=20)
    assert list(got) == list(want)
    for method in want:
        for key, value in want[method].items():
            if key != "seconds":
                assert got[method][key] == value, (method, key)
    assert clumpkit.volume(c, r)["volume"] == want["exact"]["volume"]


def test_invariant_under_translation_and_row_order():
    c, r = clump()
    p = clumpkit.mass_properties(c, r)
    q = clumpkit.mass_properties(c[::-1] + 10.0, r[::-1])
    assert q.volume == pytest.approx(p.volume, rel=1e-12)
    assert np.allclose(q.centroid, p.centroid + 10.0, rtol=1e-12)
    assert np.allclose(q.inertia, p.inertia, rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("centres, radii, message", [
    ([[0, 0, float("nan")]], [1.0], "sphere 0"),
    ([[0, 0, 0], [1, 0, 0]], [1.0, -0.5], "sphere 1"),
    (np.zeros((0, 3)), np.zeros(0), "centres: the array is empty"),
    (np.zeros((2, 2)), [1.0, 1.0], r"expected an \(n, 3\) array, got shape \(2, 2\)"),
    ([[0, 0, 0]], [1.0, 2.0], r"radii: expected an \(n,\) array with n = 1"),
])
def test_bad_arrays_raise_value_error_with_the_library_message(centres, radii, message):
    with pytest.raises(ValueError, match=message):
        clumpkit.mass_properties(centres, radii)
    with pytest.raises(ValueError, match=message):
        clumpkit.volume(centres, radii)


def test_bad_options():
    c, r = clump(5)
    with pytest.raises(ValueError, match="unknown method 'bogus'"):
        clumpkit.volume(c, r, "bogus")
    with pytest.raises(ValueError, match="density must be positive"):
        clumpkit.mass_properties(c, r, density=-1.0)
