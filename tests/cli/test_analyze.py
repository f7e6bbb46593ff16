"""framefix analyze on samples/: domain facts as oracles (the paper's graphs at three sizes are in
test_paper_topology.py)."""
import pytest

from conftest import run, SAMPLES


def summary(report):
    return report["singularities"]["summary"]


def kinds(report):
    return sorted(c["kind"] for c in report["singularities"]["curves"])


def test_cube_has_no_singular_curve(analyze):
    r = analyze("cube.step")
    assert summary(r)["curves"] == 0
    assert summary(r)["meshable"]
    # The constant field is MBO's fixed point: the change test stops it before the cap.
    assert r["field"]["converged"] is True and r["field"]["iterations"] < 60
    # A default-size mesh is far below the large-mesh settings: Jacobi CG and the cap of 60.
    assert r["field"]["iteration_cap"] == 60 and 1 < r["field"]["floor_iteration"] < 60
    assert "coarse" not in r["field"]["solver"]


def test_l_prism_has_no_singular_curve(analyze):
    assert summary(analyze("l_prism.step"))["curves"] == 0


def test_cylinder_has_four_valence3_curves_along_the_axis(analyze):
    r = analyze("cylinder.step")
    assert kinds(r) == ["valence3"] * 4
    assert summary(r)["curves_3_5"] == 0
    for c in r["singularities"]["curves"]:
        p0, p1 = c["points"][0], c["points"][-1]
        d = [b - a for a, b in zip(p0, p1)]
        # the cylinder's axis is z: the curve runs along it
        assert abs(d[2]) > 0.9 * sum(x * x for x in d) ** 0.5


@pytest.mark.parametrize("name", ["notch.step", "cylinder.step"])
def test_result_does_not_depend_on_the_mesh_size(analyze, name):
    a = summary(analyze(name))
    b = summary(analyze(name, "--size-factor", "0.7"))
    assert (a["curves_3_5"], a["valence3"], a["valence5"]) == (b["curves_3_5"], b["valence3"], b["valence5"])


@pytest.mark.parametrize("name", ["notch.step", "half_sphere_box.step", "cylinder.step"])
def test_curves_end_at_nodes_and_node_counts_agree(analyze, name):
    g = analyze(name)["singularities"]
    nodes = {n["id"]: n for n in g["nodes"]}
    meet3 = {i: 0 for i in nodes}
    meet5 = {i: 0 for i in nodes}
    for c in g["curves"]:
        if c.get("closed"):
            continue
        for end in c["ends"]:
            assert end in nodes, f"curve {c['id']} ends nowhere"
        # a 3-5 curve counts with the valence it has at each end
        for k, end in enumerate(c["ends"]):
            v = c.get("end_valences", [None, None])[k] or {"valence3": 3, "valence5": 5}.get(c["kind"])
            if v == 3:
                meet3[end] += 1
            elif v == 5:
                meet5[end] += 1
    for i, n in nodes.items():
        assert (n["n3"], n["n5"]) == (meet3[i], meet5[i]), n


def test_human_summary_is_printed(tmp_path):
    code, out, err = run("analyze", SAMPLES / "cube.step", "--out", tmp_path, "--quiet")
    assert code == 0, err
    first = out.splitlines()[0]
    assert first.startswith("cube.step: ") and "tets" in first and "singular curve" in first
