import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from framefix_testing import BIN, SAMPLES, TESTDATA, analyze, progress_stages, run  # noqa: E402,F401
