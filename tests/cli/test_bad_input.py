"""Every bad input reaches the user as exit code 2 and a one-line message, never a crash."""
import pytest

from conftest import TESTDATA, SAMPLES, run

CASES = [
    # (arguments, words the message must contain)
    (["mesh", "/nonexistent/part.step"], ["part.step", "does not exist"]),
    (["mesh", TESTDATA / "empty.step"], ["empty.step", "empty"]),
    (["mesh", TESTDATA / "truncated.step"], ["truncated.step"]),
    (["mesh", TESTDATA / "garbage.step"], ["garbage.step"]),
    (["mesh", TESTDATA / "face.brep"], ["face.brep", "solid"]),
    (["mesh", TESTDATA / "open_shell.brep"], ["open_shell.brep"]),
    (["mesh", TESTDATA / "two_solids.step"], ["2 solids"]),
    (["mesh", SAMPLES / "cube.step", "--size", "-1"], ["--size"]),
    (["mesh", SAMPLES / "cube.step", "--size", "1e-5"], ["size", "--size"]),
    (["mesh", "part.xyz"], ["extension"]),
    (["frobnicate", "x"], []),
    (["analyze"], ["PART"]),
]


@pytest.mark.parametrize("args,words", CASES, ids=[" ".join(map(str, c[0]))[:60] for c in CASES])
def test_bad_input_exits_2_with_a_clear_message(args, words, tmp_path):
    code, out, err = run(*args, "--out", tmp_path)
    assert code == 2, (out, err)
    lines = [l for l in err.splitlines() if not l.startswith("progress ")]
    assert len(lines) == 1, err
    assert lines[0].startswith("framefix: error")
    for w in words:
        assert w.lower() in lines[0].lower(), lines[0]
