"""Streamlines: what an extrusion correction traced (report.correction.streamlines), as
polylines inside the part; the ones that constrain the field are kept apart from the failed
ones by their edge code (1 used, 0 not used)."""
from .correction_lines import CorrectionLines


class Streamlines(CorrectionLines):
    KEY = "streamlines"

    @staticmethod
    def code_of(item):
        return int(item["used"])
