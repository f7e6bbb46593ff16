"""framefix blocks: the block decomposition of the corrected field, through the command line."""
import pytest


def block_ids(vtk_path):
    """Block id of every tet, from blocks.vtk's CELL_DATA "block"."""
    lines = vtk_path.read_text().splitlines()
    at = next(i for i, l in enumerate(lines) if l.startswith("SCALARS block "))
    n = int(next(l for l in lines if l.startswith("CELL_DATA")).split()[1])
    return [int(float(x)) for x in lines[at + 2: at + 2 + n]]


@pytest.mark.parametrize("name,count,pairs", [("cube.step", 1, 0), ("l_prism.step", 3, 2)])
def test_sanity_parts_give_the_expected_valid_blocks(analyze, tmp_path, name, count, pairs):
    r = analyze(name, command="blocks")
    b = r["blocks"]
    assert b["count"] == count
    assert b["valid"] == count
    assert (b["conforming_pairs"], b["pairs"]) == (pairs, pairs)
    assert len(b["blocks"]) == count
    assert all(k["faces"] == 6 and k["edges"] == 12 and k["corners"] == 8 for k in b["blocks"])
    # every tet belongs to exactly one block, and every block has tets
    ids = block_ids(tmp_path / "out" / "blocks.vtk")
    assert len(ids) == r["mesh"]["tets"]
    assert sorted(set(ids)) == list(range(count))
    assert sum(k["tets"] for k in b["blocks"]) == r["mesh"]["tets"]


def test_blocks_report_keeps_the_correction(analyze):
    r = analyze("notch.step", command="blocks")
    assert r["correction"]["before"]["curves_3_5"] == 1
    assert r["correction"]["after"]["curves_3_5"] == 0
    assert r["blocks"]["count"] >= 1
    assert "blocks" in r["timings_s"]
