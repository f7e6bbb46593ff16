"""FrameFix workbench package, layered like Draft: runs.py (and its leaf helpers), objects/,
make.py, then taskpanels/ and commands/ (workbench/README.md).

Everything outside commands/, taskpanels/ and viewproviders/ imports without the GUI, so
freecadcmd and macros can build the analysis objects. The backend always runs as a child
process (the `framefix` CLI or `/usr/bin/python3 -m framefix`), never inside FreeCAD.
"""

__version__ = "0.1.0"
