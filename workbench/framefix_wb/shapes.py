"""From what the user selected to the one solid the backend analyses (never modified)."""
import Part

from .errors import SelectionError

ACCEPTED = "a Part feature, a PartDesign Body, or a Link to one"


def label_of(obj):
    return getattr(obj, "Label", None) or getattr(obj, "Name", "?")


def solid_of(obj):
    """The single solid of `obj` in global coordinates (a copy); SelectionError otherwise."""
    if obj is None:
        raise SelectionError("no part: select one solid (%s)" % ACCEPTED)
    if isinstance(obj, Part.Shape):
        shape, label = obj, "the shape"
    else:
        try:
            shape = Part.getShape(obj)  # follows Links and Bodies, applies placements
        except Exception as e:  # Part raises plain exceptions for odd objects
            raise SelectionError("'%s' has no shape (%s)" % (label_of(obj), e)) from None
        label = "'%s'" % label_of(obj)
    if shape.isNull():
        raise SelectionError("%s has no shape: select %s" % (label, ACCEPTED))
    solids = shape.Solids
    if len(solids) != 1:
        kinds = "%d faces" % len(shape.Faces) if not solids else "%d solids" % len(solids)
        raise SelectionError("%s has %s; FrameFix analyses exactly one solid: select a single "
                             "solid (%s)" % (label, kinds, ACCEPTED))
    return solids[0].copy()


def analysed_part(obj):
    """The part a FrameFix result object (curves, nodes, blocks, their group) was computed
    from, so commands work on an existing analysis too; other objects are returned as is."""
    analysis = getattr(obj, "Analysis", None) if hasattr(obj, "Proxy") else None
    if analysis is not None and getattr(analysis, "Source", None) is not None:
        return analysis.Source
    if hasattr(obj, "Proxy") and getattr(obj, "Source", None) is not None and hasattr(
            obj, "InputDigest"):
        return obj.Source
    if obj is not None and obj.isDerivedFrom("App::DocumentObjectGroup"):
        parts = {analysed_part(o) for o in obj.Group} - set(obj.Group)
        if len(parts) == 1:
            return parts.pop()
    return obj


def source_from_selection(selected):
    """The one selected document object, given Gui.Selection.getSelection()'s list; a
    FrameFix result stands for the part it was computed from."""
    objects = []
    for obj in map(analysed_part, selected):
        if obj not in objects:
            objects.append(obj)
    if len(objects) != 1:
        raise SelectionError("%d objects selected: select exactly one solid (%s)"
                             % (len(objects), ACCEPTED))
    solid_of(objects[0])  # raises with the reason if it is not one solid
    return objects[0]


def shape_digest(shape):
    """A digest of the shape's geometry: equal for equal shapes, across sessions."""
    import hashlib
    return hashlib.sha1(shape.exportBrepToString().encode("utf-8")).hexdigest()


def volume_and_diagonal(shape):
    return abs(shape.Volume), shape.BoundBox.DiagonalLength

