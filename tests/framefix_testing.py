"""Shared by the CLI and Python tests (their conftest.py files re-export it)."""
import json
import os
import subprocess
from pathlib import Path

import pytest

BIN = os.environ.get("FRAMEFIX_BIN", "framefix")
SAMPLES = Path(os.environ.get("FRAMEFIX_SAMPLES", Path(__file__).parents[1] / "samples"))
TESTDATA = Path(os.environ.get("FRAMEFIX_TESTDATA", Path(__file__).parent / "data"))


def run(*args, timeout=600):
    """Runs the CLI; returns (exit code, stdout, stderr)."""
    p = subprocess.run([BIN, *map(str, args)], capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


@pytest.fixture
def analyze(tmp_path):
    """analyze(part, *flags, command=...) -> report dict, for a sample name or a path."""
    def go(part, *flags, command="analyze"):
        path = SAMPLES / part if not os.path.isabs(str(part)) else part
        code, out, err = run(command, path, "--out", tmp_path / "out", "--quiet", *flags)
        assert code == 0, err
        return json.loads((tmp_path / "out" / "report.json").read_text())
    return go


STAGE_ORDER = ["load", "mesh", "field", "singularities", "correct", "blocks", "hexmesh"]


def progress_stages(stderr):
    """The stages of the progress lines in stderr, in order of first appearance; asserts that
    (stage, fraction) never goes back: no stage after a later one, no fraction below the last."""
    seen, last = [], (-1, 0.0)
    for line in stderr.splitlines():
        if not line.startswith("progress "):
            continue
        _, stage, fraction = line.split()
        now = (STAGE_ORDER.index(stage), float(fraction))
        assert now >= last, "progress went back: %s after %s" % (now, last)
        assert 0.0 <= now[1] <= 1.0, line
        last = now
        if stage not in seen:
            seen.append(stage)
    return seen
