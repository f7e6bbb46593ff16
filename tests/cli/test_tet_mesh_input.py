"""analyze on tet meshes from other tools (gmsh .msh v4, Medit .mesh): the same oracles as on CAD.

gmsh (Debian's, installed by scripts/deps.sh) makes the meshes."""
import subprocess

import pytest

from conftest import SAMPLES, run

def gmsh_mesh(step, out, h, fmt="msh4"):
    subprocess.run(["gmsh", str(step), "-3", "-nt", "1", "-clmax", str(h), "-format", fmt, "-o", str(out), "-v", "1"],
                   check=True, timeout=300)
    return out


def test_gmsh_cube_has_12_convex_curves_and_no_singular_curve(analyze, tmp_path):
    r = analyze(gmsh_mesh(SAMPLES / "cube.step", tmp_path / "cube.msh", 0.1))
    assert r["input"]["kind"] == "msh"
    assert r["features"]["by_valence"]["1"] == 12
    assert r["singularities"]["summary"]["curves"] == 0


def test_gmsh_cylinder_has_four_valence3_curves(analyze, tmp_path):
    r = analyze(gmsh_mesh(SAMPLES / "cylinder.step", tmp_path / "cylinder.msh", 0.08))
    s = r["singularities"]["summary"]
    assert (s["valence3"], s["valence5"], s["curves_3_5"]) == (4, 0, 0)


def test_medit_notch_has_one_three_five_curve(analyze, tmp_path):
    r = analyze(gmsh_mesh(SAMPLES / "notch.step", tmp_path / "notch.mesh", 0.05, fmt="mesh"))
    assert r["input"]["kind"] == "mesh"
    assert r["singularities"]["summary"]["curves_3_5"] == 1


def test_a_surface_mesh_is_refused(tmp_path):
    msh = tmp_path / "surface.msh"
    subprocess.run(["gmsh", str(SAMPLES / "cube.step"), "-2", "-format", "msh4", "-o", str(msh), "-v", "1"], check=True)
    code, out, err = run("analyze", msh, "--out", tmp_path / "o")
    assert code == 2
    assert "tet" in err.lower()
