"""SnappedPaths: where boundary snapping moved each 3-5 curve (a correction's
report.correction.snapped_paths), as polylines on the part's boundary."""
from .correction_lines import CorrectionLines


class SnappedPaths(CorrectionLines):
    KEY = "snapped_paths"
