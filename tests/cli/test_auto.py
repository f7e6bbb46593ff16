"""framefix correct --method auto, the default: the methods in turn, the best kept, never worse
than the input (docs/algorithms.md#method-auto)."""
import json
import os
from pathlib import Path

import pytest

from conftest import run


NEEDS_CORRECTION = ["notch.step", "notch_wide.step", "notch_shallow.step", "box_arc.step", "box_arc_curved.step",
                    "half_sphere_box.step", "half_sphere_box_small.step", "half_sphere_box_large.step",
                    "groove.step", "groove_wide.step", "groove_narrow.step", "two_cylinders.step"]


def defects(s):
    return s["curves_3_5"] + s["invalid_nodes"]


@pytest.mark.parametrize("name", NEEDS_CORRECTION + ["cylinder.step"])
def test_auto_is_never_worse(analyze, name):
    r = analyze(name, command="correct")
    c = r["correction"]
    assert c["method"] == "auto" and r["singularities"]["summary"] == c["after"]
    assert defects(c["after"]) <= defects(c["before"])
    for t in c["tries"]:
        assert t["ran"] or t["reason"], t
        assert not t["kept"] or defects(t["after"]) <= defects(c["before"]), t
    if c["chosen"]:
        kept = [t for t in c["tries"] if t["method"] == c["chosen"]]
        assert kept and kept[-1]["kept"] and kept[-1]["after"] == c["after"]


@pytest.mark.parametrize("name", ["notch.step", "box_arc.step", "half_sphere_box.step"])
def test_auto_makes_the_papers_parts_hex_meshable(analyze, name):
    c = analyze(name, command="correct")["correction"]
    assert c["before"]["curves_3_5"] >= 1
    assert c["after"]["meshable"] and c["chosen"] in ("snap", "extrude-nodes", "extrude-curves", "fillet")
    assert c["tries"][-1]["method"] == c["chosen"]  # the first hex-meshable try ends the search


def test_auto_leaves_a_part_without_three_five_curves_alone(analyze):
    c = analyze("cylinder.step", command="correct")["correction"]
    assert c["chosen"] == "" and c["tries"] == [] and c["before"] == c["after"]
    assert c["notes"] == ["already hex-meshable: nothing to correct"]


def test_auto_respects_its_budget(analyze):
    """A budget below one field solve runs no try: the input's graph is kept, and says why."""
    r = analyze("notch.step", "--budget-s", "0.01", command="correct")
    c = r["correction"]
    assert c["budget_s"] == 0.01 and c["chosen"] == "" and c["after"] == c["before"]
    assert [t["method"] for t in c["tries"]] == ["snap", "extrude-nodes", "extrude-curves", "fillet"]
    assert all(not t["ran"] and t["reason"].startswith("budget:") for t in c["tries"])
    assert "raise --budget-s" in c["notes"][-1]
    assert r["timings_s"]["correct"] < 1  # no re-solve ran


# Measured 2026-12-02 at the default size: 8 of the 14 HexMe models that need a correction
# become hex-meshable with auto (docs/results.md); none may become worse.
HEXME_MESHABLE_AFTER = 8


def test_auto_meshable_fraction_on_hexme(tmp_path):
    folder = os.environ.get("FRAMEFIX_HEXME")  # the HexMe models' folder, when this machine has them
    if not folder:
        pytest.skip("set FRAMEFIX_HEXME to the HexMe models' folder to run this test")
    needing, meshable = [], []
    for part in sorted(Path(folder).glob("*.st*p")):
        out = tmp_path / part.stem
        code, _, err = run("correct", part, "--out", out, "--quiet", timeout=900)
        assert code == 0, (part.name, err)
        c = json.loads((out / "report.json").read_text())["correction"]
        if c["before"]["meshable"]:
            continue
        needing.append(part.stem)
        assert defects(c["after"]) <= defects(c["before"]), part.name
        meshable += [part.stem] if c["after"]["meshable"] else []
    assert len(needing) >= 10 and len(meshable) >= HEXME_MESHABLE_AFTER, (needing, meshable)
