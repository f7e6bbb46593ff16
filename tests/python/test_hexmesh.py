"""The hex mesh from Python: framefix.hex_mesh and python -m framefix hexmesh."""
import json
import subprocess
import sys

import numpy as np

import framefix
from conftest import SAMPLES


def test_hex_mesh_of_the_cube_is_n_cubed_unit_hexes():
    r = framefix.hex_mesh(str(SAMPLES / "cube.step"), layers=2)
    h = r.hexmesh
    assert h.done, h.reason
    assert isinstance(h.hexes, np.ndarray) and h.hexes.shape == (8, 8)
    assert h.points.shape == (27, 3)
    assert np.allclose(h.scaled_jacobian, 1)
    assert h.quality["inverted"] == 0
    assert abs(h.quality["volume"] - framefix.report(r)["hexmesh"]["part_volume"]) < 1e-9
    assert h.midpoints.shape == (0, 12)


def test_hex_mesh_of_a_shape_at_order_two():
    shape = framefix.load_shape(str(SAMPLES / "l_prism.step"))
    h = framefix.hex_mesh(shape, layers=1, order=2).hexmesh
    assert h.done, h.reason
    assert h.midpoints.shape == (len(h.hexes), 12)
    assert set(h.hex_block) == {0, 1, 2}  # the L-prism's three blocks


def test_no_hex_mesh_is_a_reason(tmp_path):
    r = framefix.hex_mesh(str(SAMPLES / "two_cylinders.step"))
    if r.blocks.valid == r.blocks.count:
        return  # its blocks became valid: nothing to check here
    assert not r.hexmesh.done and "hexahedron" in r.hexmesh.reason
    assert r.hexmesh.hexes.shape == (0, 8)


def test_python_m_framefix_hexmesh(tmp_path):
    p = subprocess.run([sys.executable, "-m", "framefix", "hexmesh", str(SAMPLES / "cube.step"), "--layers", "3",
                        "--out", str(tmp_path)], capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    assert "27 hexes" in p.stdout
    assert json.loads((tmp_path / "report.json").read_text())["hexmesh"]["hexes"] == 27
    assert (tmp_path / "hex.inp").exists()


def test_the_notchs_flat_edge_is_refined_and_can_be_turned_off():
    refined = framefix.hex_mesh(str(SAMPLES / "notch.step"), method="snap").hexmesh
    plain = framefix.hex_mesh(str(SAMPLES / "notch.step"), method="snap", refine=False).hexmesh
    assert refined.done and plain.done
    r = refined.refinement
    assert r["applied"] and r["kept"] and r["refined"] >= 1
    assert r["blocks"] == r["blocks_before"] + 2 * r["refined"] == len(set(refined.hex_block))
    assert not plain.refinement["applied"] and len(set(plain.hex_block)) == r["blocks_before"]
    assert refined.quality["min_scaled_jacobian"] > plain.quality["min_scaled_jacobian"]
    assert plain.quality["min_scaled_jacobian"] == r["plain_min_scaled_jacobian"]
