"""Where the workbench's own files are: computed from this file, never from InitGui.py."""
import os

WORKBENCH_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def _first_existing(candidates):
    for path in candidates:
        if os.path.isdir(path):
            return path
    return candidates[0]


# Installed: <Mod/FrameFix>/resources/icons; source tree: <repo>/resources/icons.
ICONS_DIR = _first_existing([
    os.path.join(WORKBENCH_DIR, "resources", "icons"),
    os.path.join(os.path.dirname(WORKBENCH_DIR), "resources", "icons"),
])


def icon(name):
    """Absolute path of resources/icons/<name>.svg."""
    return os.path.join(ICONS_DIR, name + ".svg")
