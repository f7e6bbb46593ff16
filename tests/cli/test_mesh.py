"""framefix mesh: report.json sections and a VTK file ParaView opens, on every sample."""
import json

import pytest

from conftest import SAMPLES, run

SAMPLE_FILES = sorted(p.name for p in SAMPLES.glob("*.step"))


def test_samples_exist():
    assert {"notch.step", "cube.step", "cylinder.step", "l_prism.step"} <= set(SAMPLE_FILES)


@pytest.mark.parametrize("name", SAMPLE_FILES)
def test_mesh_writes_report_and_vtk(name, tmp_path):
    code, out, err = run("mesh", SAMPLES / name, "--out", tmp_path, "--size-factor", "1.6")
    assert code == 0, err
    assert "report.json" in out
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["version"] == 1
    assert report["input"]["kind"] == "step"
    assert report["input"]["path"].endswith(name)
    assert report["mesh"]["tets"] > 1000
    assert report["mesh"]["vertices"] > 100
    assert set(report["features"]["by_valence"]) == {"1", "2", "3", "4"}
    assert {"load", "mesh", "total"} <= set(report["timings_s"])
    assert "singularities" not in report  # mesh does not analyse
    vtk = (tmp_path / "mesh.vtk").read_text().splitlines()
    assert vtk[0].startswith("# vtk DataFile")
    assert any(l.startswith("SCALARS face_tag") for l in vtk)
    assert any(l.startswith("SCALARS edge_tag") for l in vtk)


def test_progress_lines_on_stderr(tmp_path):
    code, out, err = run("mesh", SAMPLES / "cube.step", "--out", tmp_path)
    assert code == 0
    stages = [l.split()[1] for l in err.splitlines() if l.startswith("progress ")]
    assert "mesh" in stages


def test_cube_has_12_convex_feature_curves(analyze):
    report = analyze("cube.step", command="mesh")
    assert report["features"]["curves"] == 12
    assert report["features"]["by_valence"]["1"] == 12


def test_l_prism_has_one_concave_feature_curve(analyze):
    report = analyze("l_prism.step", command="mesh")
    assert report["features"]["by_valence"]["3"] == 1
    assert report["features"]["by_valence"]["1"] == 17


@pytest.mark.parametrize("name,kind", [("notch.igs", "iges"), ("notch.brep", "brep")])
def test_iges_and_brep_inputs_give_the_same_part_as_step(analyze, name, kind):
    from conftest import TESTDATA
    other = analyze(TESTDATA / name)
    step = analyze("notch.step")
    assert other["input"]["kind"] == kind
    assert other["features"]["by_valence"] == step["features"]["by_valence"]
    assert other["singularities"]["summary"]["curves_3_5"] == 1
