"""Helpers shared by the proxies: adding properties once, read-only and hidden ones."""
import json

from ..report import check_report

READ_ONLY, HIDDEN = 1, 2


def add(obj, kind, name, group, doc, mode=0, default=None):
    """Add property `name` unless a restored object already has it."""
    if name not in obj.PropertiesList:
        obj.addProperty(kind, name, group, doc)
        if default is not None:
            setattr(obj, name, default)
    if mode:
        obj.setEditorMode(name, mode)


def report_of(curves):
    """The checked report stored on a SingularCurves object (raises BackendError if bad)."""
    return check_report(json.loads(curves.Report or "null"))


class ProxyBase:
    """Proxies keep no state of their own: everything lives in properties."""

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    # FreeCAD 0.21+ names
    def dumps(self):
        return None

    def loads(self, state):
        return None
