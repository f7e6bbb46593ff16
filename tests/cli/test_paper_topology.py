"""Every sample gives the paper's singularity graph at 0.6, 1 and 1.5 x the default size, and one
topology at the three sizes (samples/README.md lists the expectations). Where the paper is silent
the oracle is a domain fact (the cube has no singular curve, the cylinder four valence-3 curves);
tests/python/test_poincare_hopf.py checks the curve ends against Poincare-Hopf."""
import json
import subprocess

import pytest

from conftest import BIN, SAMPLES

FACTORS = ["0.6", "1", "1.5"]
_cache = {}


def graph(tmp_path_factory, name, factor):
    """(summary, interior nodes) of `framefix analyze` on a sample, computed once per session."""
    key = (name, factor)
    if key not in _cache:
        out = tmp_path_factory.mktemp("paper") / "out"
        p = subprocess.run([BIN, "analyze", SAMPLES / name, "--out", out, "--quiet", "--size-factor", factor],
                           capture_output=True, text=True, timeout=900)
        assert p.returncode == 0, p.stderr
        s = json.loads((out / "report.json").read_text())["singularities"]
        _cache[key] = (s["summary"], [n for n in s["nodes"] if not n["boundary"]])
    return _cache[key]


def counts(s):
    return s["valence3"], s["valence5"], s["curves_3_5"], s["invalid_nodes"]


def exactly(v3, v5, c35, invalid):
    def check(s, nodes):
        assert counts(s) == (v3, v5, c35, invalid)
    return check


def one_three_five(s, nodes):
    assert (s["curves_3_5"], s["invalid_nodes"]) == (1, 0)


def four_three_five(s, nodes):
    assert (s["curves_3_5"], s["invalid_nodes"]) == (4, 0)


def two_three_five(s, nodes):
    assert (s["curves_3_5"], s["invalid_nodes"]) == (2, 0)


def valid(s, nodes):
    assert s["meshable"] and s["curves_3_5"] == 0 and s["invalid_nodes"] == 0
    assert all(n["valid"] for n in nodes)


def notch_filleted(s, nodes):
    """Fig. 1b: one interior node joins one valence-3 curve (down to the fillet) and three valence-5 curves."""
    valid(s, nodes)
    assert counts(s) == (1, 3, 0, 0)
    assert [(n["n3"], n["n5"]) for n in nodes] == [(1, 3)]


def half_sphere_box_filleted(s, nodes):
    """Fig. 3b: valid, with four extra valence-5 curves."""
    valid(s, nodes)
    assert s["valence5"] >= 4


def groove_filleted(s, nodes):
    """Fig. 5b: valid, with valid internal nodes (the paper's groove has four; its dimensions are
    not published and ours has one per 3-5 curve of the unfilleted groove)."""
    valid(s, nodes)
    assert len(nodes) >= 2


def groove_wide_filleted(s, nodes):
    """Fig. 5b with every curve of the groove filleted (floor arcs and rims): four valid internal
    nodes, as the paper has."""
    valid(s, nodes)
    assert len(nodes) == 4


def cube_in_sphere(s, nodes):
    """Not in the paper: a cube inside the sphere (or the rounded box), its 12 edges and 8 radial
    curves to the surface valence 3, each of its corners an interior node of 4 of them."""
    valid(s, nodes)
    assert counts(s) == (20, 0, 0, 0)
    assert [(n["n3"], n["n5"]) for n in nodes] == [(4, 0)] * 8


def many_three_five(s, nodes):
    """Two cylinders: "many 3-5 curves"."""
    assert s["curves_3_5"] >= 2


EXPECT = {
    "cube.step": exactly(0, 0, 0, 0),
    "l_prism.step": exactly(0, 0, 0, 0),
    "cylinder.step": exactly(4, 0, 0, 0),
    "notch.step": one_three_five,
    "notch_wide.step": one_three_five,
    "notch_shallow.step": one_three_five,
    "box_arc.step": one_three_five,
    "box_arc_curved.step": one_three_five,  # the paper's two extra lines are not found (samples/README.md)
    "box_arc_wide.step": one_three_five,
    "box_arc_small.step": one_three_five,
    "box_arc_curved_flat.step": one_three_five,
    "box_arc_curved_steep.step": one_three_five,
    "half_sphere_box.step": four_three_five,
    "half_sphere_box_small.step": four_three_five,
    "half_sphere_box_large.step": four_three_five,
    "groove.step": two_three_five,
    "groove_wide.step": two_three_five,
    "groove_narrow.step": two_three_five,
    "two_cylinders.step": many_three_five,
    "notch_filleted.step": notch_filleted,
    "half_sphere_box_filleted.step": half_sphere_box_filleted,
    "groove_filleted.step": groove_filleted,
    "groove_wide_filleted.step": groove_wide_filleted,
    "sphere.step": cube_in_sphere,
    "rounded_box.step": cube_in_sphere,
    "tube.step": exactly(0, 0, 0, 0),  # not in the paper: a bushing, no singular curve
    # Not in the paper: machined parts with 135 and 225 degree edges; the curves the field lays
    # along them are glued to them (docs/algorithms.md#curves-along-ambiguous-edges).
    "chamfer_box.step": exactly(0, 0, 0, 0),
    "chamfer_top.step": exactly(0, 0, 0, 0),
    "gusset.step": exactly(0, 0, 0, 0),
}

# Known deviations, kept visible: strict, so that a fix shows up as a failure to remove the mark.
KNOWN = {
    ("groove_narrow.step", "0.6"): "a 0.1-wide groove: one 3-5 curve where the paper has two",
    ("groove_narrow.step", "1"): "a 0.1-wide groove: one 3-5 curve where the paper has two",
    ("groove_narrow.step", "1.5"): "a 0.1-wide groove: one 3-5 curve where the paper has two",
}
UNSTABLE = {}


def test_every_sample_has_an_expectation():
    assert sorted(EXPECT) == sorted(p.name for p in SAMPLES.glob("*.step"))


def cases():
    for name in sorted(EXPECT):
        for f in FACTORS:
            marks = [pytest.mark.xfail(reason=KNOWN[(name, f)], strict=True)] if (name, f) in KNOWN else []
            yield pytest.param(name, f, marks=marks, id="%s-%s" % (name.split(".")[0], f))


@pytest.mark.parametrize("name,factor", list(cases()))
def test_papers_topology(tmp_path_factory, name, factor):
    s, nodes = graph(tmp_path_factory, name, factor)
    EXPECT[name](s, nodes)


@pytest.mark.parametrize("name", [pytest.param(n, marks=[pytest.mark.xfail(reason=UNSTABLE[n], strict=True)]
                                               if n in UNSTABLE else []) for n in sorted(EXPECT)])
def test_one_topology_at_three_sizes(tmp_path_factory, name):
    tops = [counts(graph(tmp_path_factory, name, f)[0]) + (graph(tmp_path_factory, name, f)[0]["meshable"],)
            for f in FACTORS]
    assert len(set(tops)) == 1, dict(zip(FACTORS, tops))
