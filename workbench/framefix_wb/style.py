"""Colours and line styles of the results; the panel's legend reads the same table."""

# kind code stored per edge (EdgeKinds) -> (RGB, legend text); 0: a kind this workbench
# does not know (the backend may add kinds, e.g. "other")
CURVE_KIND_CODES = {"valence3": 3, "valence5": 5, "3-5": 35}
OTHER_KIND = 0
CURVE_COLORS = {
    3: ((0.10, 0.45, 1.00), "valence 3"),
    5: ((0.00, 0.70, 0.25), "valence 5"),
    35: ((1.00, 0.00, 0.00), "3-5 curve (not hex-meshable)"),
    OTHER_KIND: ((0.45, 0.45, 0.45), "other"),
}
NODE_COLORS = {True: ((0.15, 0.15, 0.15), "node"), False: ((1.00, 0.00, 1.00), "invalid node")}
# feature curve hex valence 1..4 (dihedral angle 90, 180, 270, 360 degrees)
FEATURE_COLORS = {
    1: ((0.85, 0.55, 0.00), "valence 1 (convex, 90 deg)"),
    2: ((0.55, 0.55, 0.55), "valence 2 (flat)"),
    3: ((0.55, 0.20, 0.80), "valence 3 (concave, 270 deg)"),
    4: ((0.00, 0.60, 0.60), "valence 4"),
}
OTHER = (0.3, 0.3, 0.3)
SNAPPED_PATH_COLOR = (1.00, 0.55, 0.00)  # where a correction moved a 3-5 curve to
CURVE_LINE_WIDTH = 4.0
FEATURE_LINE_WIDTH = 2.0
NODE_POINT_SIZE = 9.0
SOURCE_TRANSPARENCY = 70


def color_list(codes, table):
    """One RGB per code, OTHER for unknown codes."""
    return [table.get(c, (OTHER, ""))[0] for c in codes]


def legend_html(table, codes_present=None):
    rows = []
    for code, (rgb, text) in table.items():
        if codes_present is None or code in codes_present:
            hexcol = "#%02x%02x%02x" % tuple(int(255 * c) for c in rgb)
            rows.append('<span style="color:%s">&#9632;</span> %s' % (hexcol, text))
    return "&nbsp;&nbsp;".join(rows)
