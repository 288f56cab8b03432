"""library, specimen and read_specimen against the command line: the same files, a stopped
library resumed from its .partial folder, and the specimen's arrays."""
import _thread
import os
import pathlib

import numpy as np
import pytest

import clumpkit
from conftest import SOURCE


@pytest.fixture(scope="module")
def recipes_dir():
    """The tiny specimen of the command-line tests (a 60 mm cylinder, about 600 bodies)."""
    return pathlib.Path(SOURCE) / "tests" / "cli" / "tiny"


def files_of(folder):
    out = {}
    for root, _, names in os.walk(folder):
        for n in names:
            if n == "manifest.json":  # holds the run's time
                continue
            p = os.path.join(root, n)
            out[os.path.relpath(p, folder)] = open(p, "rb").read()
    return out


def test_library_equals_the_command_line_and_resumes_after_ctrl_c(cli, recipes, tmp_path):
    recipe = os.path.join(recipes, "quick-rocks.toml")  # 40 blocks, 20 spheres each
    cli("library", "--quiet", "--recipe", recipe, "--out", tmp_path / "cli")
    out = str(tmp_path / "py")
    reports = []

    def progress(stage, fraction):  # Ctrl-C once a particle is done
        reports.append((stage, fraction))
        if fraction > 0:
            _thread.interrupt_main()

    with pytest.raises(KeyboardInterrupt):
        clumpkit.library(recipe, out, progress=progress, threads=1)
    assert not os.path.exists(out) and os.path.isdir(out + ".partial")
    assert reports and {s for s, _ in reports} == {"library"}
    kept = [n for n in os.listdir(out + ".partial/particles") if n.endswith(".json")]
    assert 0 < len(kept) < 40
    result = clumpkit.library(recipe, out)
    assert result["particles"] == 40 and result["resumed"] == len(kept) and result["redone"] == []
    assert files_of(out) == files_of(tmp_path / "cli")


def test_specimen_and_read_specimen(cli, recipes_dir, tmp_path):
    recipe = str(recipes_dir / "tiny.toml")
    stages = set()
    report = clumpkit.specimen(recipe, str(tmp_path / "py"),
                               progress=lambda stage, fraction: stages.add(stage))
    cli("specimen", "--quiet", "--recipe", recipe, "--out", tmp_path / "cli")
    assert (tmp_path / "py" / "specimen.csv").read_bytes() == \
        (tmp_path / "cli" / "specimen.csv").read_bytes()
    assert "library" in stages and len(stages) > 1
    s = clumpkit.read_specimen(str(tmp_path / "py"))
    n = len(s["id"])
    assert n == report["bodies"] and len(s["sphere_radii"]) == report["spheres"]
    assert np.array_equal(s["id"], np.arange(1, n + 1))
    for key, shape in [("position", (n, 3)), ("quaternion", (n, 4)), ("moments", (n, 3)),
                       ("sphere_centres", (len(s["sphere_body"]), 3))]:
        assert s[key].shape == shape and s[key].dtype == np.float64
        assert s[key].flags["C_CONTIGUOUS"]
    assert np.allclose(np.linalg.norm(s["quaternion"], axis=1), 1.0, rtol=1e-12)
    assert np.all(s["mass"] > 0) and np.all(s["sphere_radii"] > 0)
    assert np.all(s["template"][~s["rock"]] == -1) and np.all(s["template"][s["rock"]] >= 0)
    assert set(np.unique(s["sphere_body"])) == set(s["id"])
    # Soil bodies are single spheres at their position.
    soil = s["id"][~s["rock"]]
    first = {b: i for i, b in reversed(list(enumerate(s["sphere_body"])))}
    for b in soil[:20]:
        assert np.array_equal(s["sphere_centres"][first[b]], s["position"][b - 1])


# The headers of today's specimen.csv (units in brackets, docs/units.md) and of a folder
# written before units: both read the same.
BODIES_WITH_UNITS = ("body[1],kind,template[1],x[m],y[m],z[m],qw[1],qx[1],qy[1],qz[1],mass[kg],"
                     "volume[m3],scale[1],I1[kg.m2],I2[kg.m2],I3[kg.m2],zone[1]")
BODIES_BEFORE_UNITS = "body,kind,template,x,y,z,qw,qx,qy,qz,mass,volume,scale,I1,I2,I3,zone"


@pytest.mark.parametrize("bodies,spheres", [
    (BODIES_BEFORE_UNITS, "sphere,body,x,y,z,r"),
    (BODIES_WITH_UNITS, "sphere[1],body[1],x[m],y[m],z[m],r[m]")])
def test_read_specimen_of_a_written_file(tmp_path, bodies, spheres):
    (tmp_path / "specimen.csv").write_text(
        "# clumpkit specimen format 4, SI units\n# bodies\n" + bodies + "\n"
        "1,rock,3,0.1,0.2,0.3,0.5,0.5,0.5,0.5,2.5,0.001,1.5,1e-4,2e-4,3e-4,2\n"
        "2,soil,-1,1,1,1,1,0,0,0,0.1,4e-5,1,1e-6,1e-6,1e-6,0\n"
        "# spheres\n" + spheres + "\n"
        "1,1,0.1,0.2,0.3,0.05\n2,1,0.12,0.2,0.3,0.04\n3,2,1,1,1,0.02\n")
    s = clumpkit.read_specimen(str(tmp_path))
    assert s["rock"].tolist() == [True, False] and s["template"].tolist() == [3, -1]
    assert s["quaternion"][0].tolist() == [0.5, 0.5, 0.5, 0.5]
    assert s["moments"][0].tolist() == [1e-4, 2e-4, 3e-4] and s["zone"].tolist() == [2, 0]
    assert s["sphere_body"].tolist() == [1, 1, 2] and s["sphere_radii"].tolist() == [0.05, 0.04, 0.02]
    with pytest.raises(OSError, match="cannot open"):
        clumpkit.read_specimen(str(tmp_path / "missing"))
    (tmp_path / "bad.csv").write_text((tmp_path / "specimen.csv").read_text().replace("2.5", "nan"))
    with pytest.raises(ValueError, match="bad.csv:4: field mass"):
        clumpkit.read_specimen(str(tmp_path / "bad.csv"))


def test_version_and_commit_are_the_command_lines(cli):
    # The module and the program are built from the same sources: `clumpkit --version` starts
    # "clumpkit VERSION (commit COMMIT)".
    first = cli("--version").splitlines()[0]
    assert first == f"clumpkit {clumpkit.__version__} (commit {clumpkit.__commit__})"
    assert clumpkit.__version__.count(".") == 2
