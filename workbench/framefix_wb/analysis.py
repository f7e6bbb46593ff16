"""The make layer under its old name: macros and saved scripts call
framefix_wb.analysis.make_analysis / make_blocks / make_hex_mesh. Everything lives in make.py and runs.py."""
from . import runs
from .make import (BLOCKS_GROUP_LABEL, CORRECTION_GROUP_LABEL, GROUP_LABEL,  # noqa: F401
                   analyses_of, blocks_of, make_analysis, make_blocks, make_hex_mesh, update_analysis)
from .runs import block_mesh, input_digest, remember_block_mesh  # noqa: F401

__all__ = ["BLOCKS_GROUP_LABEL", "CORRECTION_GROUP_LABEL", "GROUP_LABEL", "analyses_of",
           "blocks_of", "make_analysis", "make_blocks", "make_hex_mesh", "update_analysis", "block_mesh",
           "input_digest", "remember_block_mesh", "run_analysis"]


def run_analysis(solid, size, backend=None, timeout=None, method=None, blocks=False):
    """runs.run with the arguments in their old order."""
    return runs.run(solid, size, method, blocks, backend, timeout)
