# FrameFix workbench, application part (runs in freecadcmd too). Kept tiny: the code is in
# the framefix_wb package. Makes `import framefix.freecad` work in macros by putting the
# backend's Python package (installed beside the workbench, or FRAMEFIX_PYTHONPATH, or a
# build tree) on sys.path.
def _framefix_add_python_path():
    import sys
    try:
        from framefix_wb.backend import find_python_dir
        path = find_python_dir()
    except Exception as e:  # never break FreeCAD's start-up
        import FreeCAD
        FreeCAD.Console.PrintWarning("FrameFix: %s\n" % e)
        return
    if path and path not in sys.path:
        sys.path.append(path)


_framefix_add_python_path()
