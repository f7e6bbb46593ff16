"""Finding the FrameFix backend (the `framefix` CLI) this workbench runs as a child process.

The one lookup order of the project: the workbench and the macro API (framefix.freecad,
through runs.py) both call find_backend(). Order, first match wins:
 1. FRAMEFIX_BACKEND: path of a `framefix` executable (or any program with its CLI);
    FRAMEFIX_PYTHONPATH alone: a folder holding the `framefix` package, run with
    `/usr/bin/python3 -m framefix`. An explicit variable beats everything so a user (or a
    test) can point an installed workbench at another backend.
 2. Installed beside the workbench: <workbench>/bin/framefix, <workbench>/python/framefix.
 3. A build tree next to the sources: <repo>/build*/bin/framefix, newest first.
"""
import glob
import os

from .errors import BackendError
from .paths import WORKBENCH_DIR

SYSTEM_PYTHON = "/usr/bin/python3"  # the interpreter FreeCAD embeds and the module is built for


class Backend:
    """A command prefix (`argv + ["analyze", ...]`) and the extra environment it needs."""

    def __init__(self, argv, env=None, origin=""):
        self.argv = list(argv)
        self.env = dict(env or {})
        self.origin = origin

    def environment(self, base=None):
        env = dict(os.environ if base is None else base)
        env.update(self.env)
        return env

    def __repr__(self):
        return "Backend(%r, origin=%r)" % (" ".join(self.argv), self.origin)


def _is_executable(path):
    return os.path.isfile(path) and os.access(path, os.X_OK)


def _build_trees():
    repo = os.path.dirname(WORKBENCH_DIR)
    trees = [d for d in glob.glob(os.path.join(repo, "build*")) if os.path.isdir(d)]
    return sorted(trees, key=os.path.getmtime, reverse=True)


def _python_backend(python_dir, origin):
    return Backend([SYSTEM_PYTHON, "-m", "framefix"], {"PYTHONPATH": python_dir}, origin)


def find_backend(environ=None):
    """The backend to run; raises BackendError saying how to get one if there is none."""
    environ = os.environ if environ is None else environ
    exe = environ.get("FRAMEFIX_BACKEND", "")
    if exe:
        if not _is_executable(exe):
            raise BackendError("FRAMEFIX_BACKEND=%s is not an executable file" % exe)
        return Backend([exe], origin="FRAMEFIX_BACKEND")
    pydir = environ.get("FRAMEFIX_PYTHONPATH", "")
    if pydir:
        if not os.path.isdir(os.path.join(pydir, "framefix")):
            raise BackendError("FRAMEFIX_PYTHONPATH=%s holds no framefix package" % pydir)
        return _python_backend(pydir, "FRAMEFIX_PYTHONPATH")
    for root, origin in [(WORKBENCH_DIR, "installed")] + [(t, "build tree") for t in _build_trees()]:
        exe = os.path.join(root, "bin", "framefix")
        if _is_executable(exe):
            return Backend([exe], origin="%s %s" % (origin, root))
        if glob.glob(os.path.join(root, "python", "framefix", "_core*.so")):
            return _python_backend(os.path.join(root, "python"), "%s %s" % (origin, root))
    raise BackendError(
        "FrameFix backend not found: install the workbench with its backend "
        "(cmake --install build --prefix ~/.local/share/FreeCAD/Mod/FrameFix) "
        "or set FRAMEFIX_BACKEND to the framefix executable")


def find_python_dir(environ=None):
    """The folder holding the `framefix` package (for macros), or None."""
    environ = os.environ if environ is None else environ
    candidates = [environ.get("FRAMEFIX_PYTHONPATH", ""), os.path.join(WORKBENCH_DIR, "python")]
    candidates += [os.path.join(t, "python") for t in _build_trees()]
    for path in candidates:
        if path and os.path.isfile(os.path.join(path, "framefix", "__init__.py")):
            return path
    return None
