"""Damaged inputs never kill the CLI or a Python host: seeded mutations of STEP, BREP, IGES, .msh
and .mesh files (truncations, changed bytes, deleted, swapped and repeated lines, changed numbers),
made at test time. Every run ends with exit 0, or exit 2 and one error line; no signal, no hang.
A file that crashes OCCT's reader in a worker process raises framefix.Error in this interpreter.
"""
import random
import re
import subprocess
from concurrent.futures import ThreadPoolExecutor

import pytest

from conftest import BIN, SAMPLES, TESTDATA

SEED = 20261201
TIMEOUT_S = 60       # a run past this is a hang
COARSE = "3"         # --size-factor: a few thousand tets, so 300+ runs take about a minute
CASES = {"notch.step": 90, "groove.step": 50, "notch.brep": 50, "notch.igs": 50, "cube.msh": 40, "cube.mesh": 30}
NUMBER = re.compile(rb"-?\d+\.?\d*(?:[eE][-+]?\d+)?")


def truncate(rng, data):
    return data[:rng.randrange(1, len(data))]


def change_bytes(rng, data):
    b = bytearray(data)
    for _ in range(rng.randint(1, 8)):
        b[rng.randrange(len(b))] = rng.randrange(256)
    return bytes(b)


def edit_lines(rng, data, edit):
    lines = data.split(b"\n")
    i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
    if edit == "delete":
        del lines[i]
    elif edit == "swap":
        lines[i], lines[j] = lines[j], lines[i]
    else:
        lines.insert(i, lines[j])
    return b"\n".join(lines)


def change_number(rng, data):
    spans = [m.span() for m in NUMBER.finditer(data)]
    out = data
    for a, b in sorted(rng.sample(spans, min(len(spans), rng.randint(1, 4))), reverse=True):
        value = rng.choice([b"0", b"-1", b"1e308", b"nan", b"7", b"99999999", b"0.5", b"-0.0001"])
        out = out[:a] + value + out[b:]
    return out


MUTATIONS = {
    "truncate": truncate,
    "bytes": change_bytes,
    "delete-line": lambda rng, d: edit_lines(rng, d, "delete"),
    "swap-lines": lambda rng, d: edit_lines(rng, d, "swap"),
    "repeat-line": lambda rng, d: edit_lines(rng, d, "repeat"),
    "number": change_number,
}


def sources(folder):
    """The files to mutate; the tet meshes are made by gmsh from the cube, here."""
    out = {"notch.step": SAMPLES / "notch.step", "groove.step": SAMPLES / "groove.step",
           "notch.brep": TESTDATA / "notch.brep", "notch.igs": TESTDATA / "notch.igs"}
    for name, fmt in [("cube.msh", "msh4"), ("cube.mesh", "mesh")]:
        out[name] = folder / name
        subprocess.run(["gmsh", str(SAMPLES / "cube.step"), "-3", "-nt", "1", "-clmax", "0.3", "-format", fmt,
                        "-o", str(out[name]), "-v", "1"], check=True, capture_output=True, timeout=120)
    return out


def make_cases(folder):
    rng = random.Random(SEED)
    cases = []
    for name, path in sources(folder).items():
        data = path.read_bytes()
        for k in range(CASES[name]):
            kind = rng.choice(sorted(MUTATIONS))
            mutated = folder / ("%03d_%s_%s" % (k, kind, name))
            mutated.write_bytes(MUTATIONS[kind](rng, data))
            cases.append(mutated)
    return cases


def run_case(path):
    out = path.parent / (path.name + ".out")
    try:
        p = subprocess.run([BIN, "mesh", str(path), "--size-factor", COARSE, "--quiet", "--threads", "1", "--out", str(out)],
                           capture_output=True, timeout=TIMEOUT_S)
        return path, p.returncode, p.stderr.decode("utf-8", errors="replace")
    except subprocess.TimeoutExpired:
        return path, "hang", ""


@pytest.fixture(scope="module")
def outcomes(tmp_path_factory):
    cases = make_cases(tmp_path_factory.mktemp("fuzz"))
    with ThreadPoolExecutor(max_workers=2) as pool:
        return list(pool.map(run_case, cases))


def test_at_least_300_cases_over_five_formats(outcomes):
    assert len(outcomes) >= 300
    assert {p.suffix for p, _, _ in outcomes} == {".step", ".brep", ".igs", ".msh", ".mesh"}


def test_every_run_ends_with_exit_0_or_a_clear_error(outcomes):
    bad = ["%s: %s %s" % (p.name, code, err.strip()[-200:]) for p, code, err in outcomes if code not in (0, 2)]
    assert not bad, "\n".join(bad)
    for p, code, err in outcomes:
        if code == 2:
            lines = err.strip().splitlines()
            assert len(lines) == 1 and re.match(r"framefix: error \[\w+\]: \S", lines[0]), (p.name, err)
            assert "\ufffd" not in err, (p.name, err)  # the line is valid UTF-8


def test_the_mutations_reach_the_readers(outcomes):
    # Not every mutation is harmless: the corpus must hold refused files, or it tests nothing.
    assert sum(code == 2 for _, code, _ in outcomes) >= 30
    assert sum(code == 0 for _, code, _ in outcomes) >= 30


def test_a_crash_in_a_reader_raises_framefix_error_in_python(outcomes):
    framefix = pytest.importorskip("framefix")  # absent only in the sanitizer build (no Python module)
    crashed = [p for p, code, err in outcomes if code == 2 and "crashed" in err]
    if not crashed:
        pytest.skip("no mutation of this seed crashes a third-party reader")
    for path in crashed[:3]:
        with pytest.raises(framefix.Error, match="crashed"):
            framefix.analyze(str(path), size_factor=3.0)
    assert framefix.analyze(str(SAMPLES / "cube.step"), size_factor=3.0).singularities.summary["curves"] == 0
