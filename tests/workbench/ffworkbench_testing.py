"""Helpers shared by the workbench tests, headless and GUI (importable without the GUI)."""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
FAKES = os.path.join(HERE, "fake_backends")
SAMPLES = os.environ.get("FRAMEFIX_SAMPLES") or os.path.join(os.path.dirname(os.path.dirname(HERE)), "samples")


def alive(pid):
    """True if `pid` runs (a zombie counts as gone)."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            return f.read().split(")")[-1].split()[0] != "Z"
    except FileNotFoundError:
        return False


def sample_document(sample, name, part_name):
    """A new document `name` holding samples/<sample>.step as the Part feature `part_name`;
    returns (doc, part)."""
    import FreeCAD
    import Part
    doc = FreeCAD.newDocument(name)
    part = doc.addObject("Part::Feature", part_name)
    part.Shape = Part.read(os.path.join(SAMPLES, sample + ".step"))
    doc.recompute()
    return doc, part


def notch_document(name="Notch"):
    """A new document holding samples/notch.step as a Part feature; returns (doc, part)."""
    return sample_document("notch", name, "Notch")
