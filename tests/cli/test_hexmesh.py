"""framefix hexmesh: the hex mesh of the blocks, in the files FEM tools read (VTK, gmsh, CalculiX)."""
import json
import shutil
import subprocess

import pytest

from conftest import SAMPLES, progress_stages, run


def vtk_cells(path):
    """(cell types, cells) of a legacy ASCII VTK unstructured grid."""
    lines = path.read_text().splitlines()
    at = next(i for i, l in enumerate(lines) if l.startswith("CELLS "))
    n = int(lines[at].split()[1])
    cells = [[int(x) for x in l.split()[1:]] for l in lines[at + 1: at + 1 + n]]
    t = next(i for i, l in enumerate(lines) if l.startswith("CELL_TYPES "))
    return [int(x) for x in lines[t + 1: t + 1 + n]], cells


def inp_sections(path):
    """Keyword line -> its data lines, of a CalculiX/Abaqus .inp file."""
    sections, current = {}, None
    for line in path.read_text().splitlines():
        if line.startswith("**"):
            continue
        if line.startswith("*"):
            current = line
            sections[current] = []
        elif current:
            sections[current].append(line)
    return sections


def hexmesh(tmp_path, name, *flags):
    code, out, err = run("hexmesh", SAMPLES / name, "--out", tmp_path, *flags)
    assert code == 0, err
    return json.loads((tmp_path / "report.json").read_text()), err


def test_notch_hex_mesh_files_agree_with_the_report(tmp_path):
    r, err = hexmesh(tmp_path, "notch.step")
    assert progress_stages(err)[-2:] == ["blocks", "hexmesh"]
    h = r["hexmesh"]
    assert h["done"] and h["inverted"] == 0 and h["min_scaled_jacobian"] > 0
    assert abs(h["volume"] - h["part_volume"]) <= 0.01 * h["part_volume"]
    assert r["blocks"]["before_refinement"]["count"] == 7  # as the sheets cut them
    # the flat-edge block, cut in three with its neighbour along the edge, is what the blocks are
    assert len(h["blocks"]) == r["blocks"]["count"] == r["blocks"]["refined"]["count"] == 7 + 2 * h["refinement"]["refined"] == 9
    assert sum(b["hexes"] for b in h["blocks"]) == h["hexes"]
    types, cells = vtk_cells(tmp_path / "hex.vtk")
    assert types == [12] * h["hexes"] and all(len(c) == 8 for c in cells)
    inp = inp_sections(tmp_path / "hex.inp")
    assert len(inp["*NODE, NSET=NALL"]) == h["vertices"]
    assert len(inp["*ELEMENT, TYPE=C3D8, ELSET=EALL"]) == h["hexes"]
    face_sets = [k for k in inp if k.startswith("*NSET, NSET=FACE")]
    assert len(face_sets) >= 6  # a box's faces at least; each B-rep face under the hexes has a set
    msh = (tmp_path / "hex.msh").read_text()
    assert msh.startswith("$MeshFormat\n4.1 0 8\n")
    if shutil.which("gmsh"):
        p = subprocess.run(["gmsh", "-check", str(tmp_path / "hex.msh")], capture_output=True, text=True, timeout=120)
        assert p.returncode == 0, p.stderr
        assert "%d elements" % h["hexes"] in p.stdout


def test_the_notchs_fillet_correction_is_hex_meshed_through_its_seven_blocks(tmp_path):
    # The paper's Fig. 6a carried on to hexahedra: the notch's concave arc filleted by the
    # correction, its 7 blocks around the fillet's node, each a structured grid of hexes, or
    # split further by the flat-edge refinement where that makes the hexes better.
    r, err = hexmesh(tmp_path, "notch.step", "--method", "fillet")
    assert r["correction"]["method"] == "fillet" and r["correction"]["kept"]
    b, h = r["blocks"], r["hexmesh"]
    cut = b["before_refinement"]
    assert (cut["count"], cut["valid"], cut["conforming_pairs"], cut["pairs"]) == (7, 7, 9, 9)
    assert h["done"] and h["inverted"] == 0 and h["min_scaled_jacobian"] > 0
    ref = h["refinement"]
    assert ref["blocks_before"] == 7 and len(h["blocks"]) == ref["blocks"]
    if b["flat_refinement"]["kept"]:  # the blocks are the hex mesh's
        assert (b["count"], b["valid"], b["conforming_pairs"], b["pairs"]) == (ref["blocks"],) * 2 + (ref["pairs"],) * 2
    assert sum(x["hexes"] for x in h["blocks"]) == h["hexes"]
    if ref["kept"]:
        assert ref["blocks"] > 7 and h["min_scaled_jacobian"] > ref["plain_min_scaled_jacobian"]
    assert abs(h["volume"] - h["part_volume"]) <= 0.01 * h["part_volume"]


def test_order_two_writes_twenty_node_hexes(tmp_path):
    r, _ = hexmesh(tmp_path, "cube.step", "--layers", "3", "--order", "2")
    h = r["hexmesh"]
    assert h["hexes"] == 27 and h["order"] == 2
    assert h["vertices"] == 4 ** 3 + 3 * 3 * 4 * 4  # corners + one midpoint per hex edge
    types, cells = vtk_cells(tmp_path / "hex.vtk")
    assert types == [25] * 27 and all(len(c) == 20 for c in cells)
    elements = inp_sections(tmp_path / "hex.inp")["*ELEMENT, TYPE=C3D20, ELSET=EALL"]
    assert len(elements) == 2 * 27  # 15 nodes on the first line, 5 on the next


def test_hex_size_sets_the_counts(tmp_path):
    r, _ = hexmesh(tmp_path, "cube.step", "--hex-size", "0.25")
    assert r["hexmesh"]["hexes"] == 4 ** 3
    assert r["hexmesh"]["min_scaled_jacobian"] == pytest.approx(1, abs=1e-6)


def test_blocks_that_are_not_hexahedra_give_a_reason_and_no_files(tmp_path):
    r, _ = hexmesh(tmp_path, "two_cylinders.step")
    if r["blocks"]["valid"] == r["blocks"]["count"]:
        pytest.skip("two_cylinders' blocks became valid: pick another part")
    assert r["hexmesh"]["done"] is False
    assert "not a hexahedron" in r["hexmesh"]["reason"]
    assert not (tmp_path / "hex.vtk").exists()


def test_bad_hex_options_are_refused(tmp_path):
    for flags in (["--order", "3"], ["--layers", "0"], ["--hex-size", "-1"]):
        code, _, err = run("hexmesh", SAMPLES / "cube.step", "--out", tmp_path, *flags)
        assert code == 2 and "error" in err, flags


@pytest.mark.skipif(not shutil.which("ccx"), reason="CalculiX (calculix-ccx) is not installed")
def test_notch_hex_mesh_runs_a_calculix_static_analysis(tmp_path):
    # Fixed on the bottom face, a pressure-like load on the top: CalculiX solves it and the
    # top moves down, the bottom not at all.
    r, _ = hexmesh(tmp_path, "notch.step")
    inp = inp_sections(tmp_path / "hex.inp")
    nodes = {int(l.split(",")[0]): [float(x) for x in l.split(",")[1:]] for l in inp["*NODE, NSET=NALL"]}
    zmin = min(p[2] for p in nodes.values())
    zmax = max(p[2] for p in nodes.values())

    def face_where(test):
        for key, lines in inp.items():
            if key.startswith("*NSET, NSET=FACE"):
                ids = [int(x) for l in lines for x in l.split(",") if x.strip()]
                if all(test(nodes[i][2]) for i in ids):
                    return key.split("=")[-1], ids
        raise AssertionError("no face set found")

    bottom, _ = face_where(lambda z: abs(z - zmin) < 1e-6)
    top, top_ids = face_where(lambda z: abs(z - zmax) < 1e-6)
    deck = tmp_path / "static.inp"
    deck.write_text("\n".join([
        "*INCLUDE, INPUT=hex.inp",
        "*MATERIAL, NAME=STEEL", "*ELASTIC", "210000, 0.3",
        "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL",
        "*STEP", "*STATIC",
        "*BOUNDARY", "%s, 1, 3" % bottom,
        "*CLOAD"] + ["%d, 3, %g" % (i, -1.0 / len(top_ids)) for i in top_ids] + [
        "*NODE FILE", "U", "*END STEP", ""]))
    p = subprocess.run(["ccx", "-i", "static"], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stdout[-2000:]
    frd = (tmp_path / "static.frd").read_text().splitlines()
    at = next(i for i, l in enumerate(frd) if l.strip().startswith("-4") and "DISP" in l)
    disp = {}
    for l in frd[at + 1:]:
        if l.startswith(" -3"):
            break
        if l.startswith(" -1"):
            node = int(l[3:13])
            disp[node] = [float(l[13 + 12 * k: 25 + 12 * k]) for k in range(3)]
    assert len(disp) == r["hexmesh"]["vertices"]
    assert max(abs(disp[i][2]) for i in face_where(lambda z: abs(z - zmin) < 1e-6)[1]) == 0
    assert all(disp[i][2] < 0 for i in top_ids)


@pytest.mark.skipif(not shutil.which("gmsh"), reason="gmsh is not installed")
def test_a_tet_mesh_input_gets_a_hex_mesh_on_its_own_boundary(tmp_path):
    # No B-rep: the boundary vertices go onto the tet mesh's boundary triangles (the cube's
    # planes, so the hexes are exact).
    msh = tmp_path / "cube.msh"
    subprocess.run(["gmsh", str(SAMPLES / "cube.step"), "-3", "-nt", "1", "-clmax", "0.08", "-format", "msh4",
                    "-o", str(msh), "-v", "1"], check=True, timeout=300)
    code, _, err = run("hexmesh", msh, "--out", tmp_path / "out", "--quiet")
    assert code == 0, err
    h = json.loads((tmp_path / "out" / "report.json").read_text())["hexmesh"]
    assert h["done"] and h["inverted"] == 0
    assert h["min_scaled_jacobian"] == pytest.approx(1, abs=1e-6)
    assert h["volume"] == pytest.approx(h["part_volume"], rel=1e-9)


def test_flat_edge_refinement_is_reported_and_can_be_turned_off(tmp_path):
    r, err = hexmesh(tmp_path / "refined", "notch.step")
    plain, _ = hexmesh(tmp_path / "plain", "notch.step", "--no-refine")
    ref = r["hexmesh"]["refinement"]
    assert ref["applied"] and ref["kept"] and ref["refined"] == 1
    assert all(s.startswith("block ") and ": " in s for s in ref["skipped"])  # other near-flat blocks, with why
    assert ref["flat_edges_before"] >= 1 and ref["flat_edges"] == 0
    assert len(ref["flat_corner_positions"]) == ref["flat_corners"]
    assert r["blocks"]["refined"]["pairs"] == r["blocks"]["pairs"] == r["blocks"]["before_refinement"]["pairs"] + 3  # the three new interfaces
    assert not plain["hexmesh"]["refinement"]["applied"] and "refined" not in plain["blocks"]
    assert plain["blocks"]["count"] == 7 and "turned off" in plain["blocks"]["flat_refinement"]["reason"]
    assert plain["hexmesh"]["min_scaled_jacobian"] == pytest.approx(ref["plain_min_scaled_jacobian"])
    assert r["hexmesh"]["min_scaled_jacobian"] == pytest.approx(ref["refined_min_scaled_jacobian"])
    assert r["hexmesh"]["min_scaled_jacobian"] > plain["hexmesh"]["min_scaled_jacobian"] + 0.2
