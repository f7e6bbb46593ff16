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
STREAMLINE_COLOR = (0.10, 0.75, 0.10)  # an extrusion's streamlines (green, as in the paper)
STREAMLINE_LINE_WIDTH = 1.5
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


# Blocks: one colour per block (hues around the wheel, skipping red), invalid ones red.
INVALID_BLOCK_COLOR = (0.90, 0.10, 0.10)
BLOCKS_TRANSPARENCY = 30
BLOCK_EDGE_COLOR = (0.10, 0.10, 0.12)
BLOCK_EDGE_WIDTH = 2.0
_BLOCK_HUES = (0.58, 0.12, 0.33, 0.80, 0.48, 0.17, 0.68, 0.27, 0.90, 0.40, 0.07, 0.53)


def block_color(block, valid):
    """The colour of block `block` (-1: no block), red if not `valid`."""
    import colorsys
    if not valid:
        return INVALID_BLOCK_COLOR
    hue = _BLOCK_HUES[block % len(_BLOCK_HUES)]
    light = (0.62, 0.50, 0.72)[(block // len(_BLOCK_HUES)) % 3]
    return colorsys.hls_to_rgb(hue, light, 0.65)


def block_colors(blocks):
    """One colour per block of a report's blocks list: valid blocks take the first hue that
    none of their already coloured neighbours has (greedy, in block order), invalid ones red."""
    index = {}
    for i, b in enumerate(blocks):
        taken = {index.get(n) for n in b["neighbours"]}
        index[i] = next(k for k in range(len(blocks) + 1) if k not in taken)
    return [block_color(index[i], b["valid"]) for i, b in enumerate(blocks)]


def blocks_legend_html(blocks):
    """The colour swatches of a report's blocks list, invalid ones named."""
    rows = []
    colors = block_colors(blocks)
    valid_flags = [b["valid"] for b in blocks]
    for b in range(len(blocks)):
        rgb = colors[b]
        hexcol = "#%02x%02x%02x" % tuple(int(255 * c) for c in rgb)
        rows.append('<span style="color:%s">&#9632;</span> %d%s'
                    % (hexcol, b, "" if valid_flags[b] else " (invalid)"))
    return "&nbsp;".join(rows)


# Hex mesh: each hex coloured by its smallest scaled Jacobian (1 a perfect cube, <= 0 inverted).
HEX_QUALITY_COLORS = ((0.0, (0.90, 0.10, 0.10), "inverted"), (0.2, (1.00, 0.55, 0.00), "< 0.2"),
                      (0.5, (0.95, 0.85, 0.20), "0.2 - 0.5"), (2.0, (0.35, 0.75, 0.35), ">= 0.5"))


def hex_quality_color(scaled_jacobian):
    """The colour of a hex whose smallest scaled Jacobian is `scaled_jacobian`."""
    for bound, rgb, _ in HEX_QUALITY_COLORS:
        if scaled_jacobian <= 0 if bound == 0.0 else scaled_jacobian < bound:
            return rgb
    return HEX_QUALITY_COLORS[-1][1]
